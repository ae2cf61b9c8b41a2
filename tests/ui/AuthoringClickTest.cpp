// Viseme authoring and the phoneme map editor driven with real clicks and keys (xdotool on a private
// Xvfb, see GuiDriver.h): every control they add is operated and the document summary the editor
// reports (EditorUi::authoringProbe) must show the edit. Skips with a message without Xvfb/xdotool.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <unistd.h>

namespace vl::test {
namespace {

using Json = nlohmann::json;

// The control of that text (or label) and kind in a window whose name starts with `window`
// ("##side" the panel, "##Combo" an open combo's list, "Delete viseme" the popup).
std::optional<Json> findIn(const GuiDriver& gui, const std::string& text, const std::string& kind,
                           const std::string& window) {
    for (const Json& control : gui.report()["controls"])
        if (control["kind"] == kind && (control["text"] == text || control["label"] == text) &&
            control["window"].get<std::string>().starts_with(window))
            return control;
    return std::nullopt;
}

// Scrolls the side panel until the control is in view (a user scrolls to reach it too).
Json reveal(GuiDriver& gui, const std::string& text, const std::string& kind) {
    for (int attempt = 0; attempt < 40; ++attempt) {
        const auto control = findIn(gui, text, kind, "##side");
        if (control && control->value("visible", false)) return *control;
        const bool above = control && (*control)["y"].get<double>() < 150.0;
        gui.scroll(150.0, 400.0, above ? -2 : 2);
    }
    throw std::runtime_error("the " + kind + " '" + text + "' never came into view");
}

void typeInto(GuiDriver& gui, const std::string& field, const std::string& text) {
    gui.click(reveal(gui, field, "text"));
    gui.key("ctrl+a");
    gui.type(text);
}

// Opens the combo and clicks the entry `item` in its list.
void choose(GuiDriver& gui, const std::string& combo, const std::string& item) {
    gui.click(reveal(gui, combo, "combo"));
    gui.waitFrames(2);
    const auto entry = findIn(gui, item, "selectable", "##Combo");
    if (!entry) throw std::runtime_error("no entry '" + item + "' in the combo " + combo);
    gui.click(*entry);
    gui.waitIdle();
}

const Json& names(const GuiDriver& gui) {
    return gui.document()["viseme_names"];
}

int indexOf(const GuiDriver& gui, const std::string& name) {
    const Json& list = names(gui);
    const auto it = std::find(list.begin(), list.end(), name);
    return it == list.end() ? -1 : static_cast<int>(it - list.begin());
}

bool hasErrorContaining(const GuiDriver& gui, const std::string& text) {
    for (const Json& message : gui.document()["messages"])
        if (message["error"].get<bool>() &&
            message["text"].get<std::string>().find(text) != std::string::npos)
            return true;
    return false;
}

// Visemes panel: rename (Enter), duplicate, move up and down, delete (directly, and through the
// popup that asks where the phonemes of the deleted viseme go), undo.
TEST(AuthoringClicks, RenameDuplicateMoveAndDeleteVisemes) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes"});
    gui.waitIdle();
    ASSERT_EQ(names(gui)[1], "PP");
    gui.click(gui.control("PP", "selectable"));
    gui.waitFrames(2);
    EXPECT_EQ(gui.document()["selected_viseme"], 1);

    typeInto(gui, "##viseme-name", "closed");
    gui.key("Return");
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(names(gui)[1], "closed");
    EXPECT_EQ(gui.document()["phoneme_map"]["P"], "closed"); // the map follows the name
    EXPECT_TRUE(gui.document()["presets"].contains("closed"));

    gui.click(reveal(gui, "Duplicate", "button"));
    gui.waitIdle();
    ASSERT_EQ(names(gui).size(), 16u);
    EXPECT_EQ(names(gui)[2], "closed copy");
    EXPECT_EQ(gui.document()["selected_viseme"], 2); // the copy is selected

    gui.click(reveal(gui, "Move up", "button"));
    gui.waitIdle();
    EXPECT_EQ(names(gui)[1], "closed copy");
    EXPECT_EQ(names(gui)[2], "closed");
    EXPECT_EQ(gui.document()["selected_viseme"], 1);
    gui.click(reveal(gui, "Move down", "button"));
    gui.waitIdle();
    EXPECT_EQ(names(gui)[2], "closed copy");

    // No phoneme maps to the copy: it goes at once.
    gui.click(reveal(gui, "Delete...", "button"));
    gui.waitIdle();
    EXPECT_EQ(indexOf(gui, "closed copy"), -1);
    EXPECT_EQ(names(gui).size(), 15u);

    // Phonemes map to "closed": the popup asks where they go; delete is disabled until chosen.
    gui.click(gui.control("closed", "selectable"));
    gui.click(reveal(gui, "Delete...", "button"));
    gui.waitFrames(3);
    ASSERT_TRUE(gui.report()["popup_open"].get<bool>());
    const auto before = gui.document()["document_revision"];
    gui.click(*findIn(gui, "Delete and move the phonemes", "button", "Delete viseme"));
    EXPECT_EQ(gui.document()["document_revision"], before);
    gui.click(*findIn(gui, "##phonemes-go-to", "combo", "Delete viseme"));
    gui.waitFrames(2);
    gui.click(*findIn(gui, "FF", "selectable", "##Combo"));
    gui.click(*findIn(gui, "Delete and move the phonemes", "button", "Delete viseme"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(indexOf(gui, "closed"), -1);
    EXPECT_EQ(gui.document()["phoneme_map"]["M"], "FF");
    EXPECT_FALSE(gui.report()["popup_open"].get<bool>());

    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_EQ(indexOf(gui, "closed"), 1);
    EXPECT_EQ(gui.document()["phoneme_map"]["M"], "closed");
    // A bad name is refused with the reason in the status bar and changes nothing.
    gui.click(gui.control("closed", "selectable"));
    const auto id = gui.document()["document_revision"];
    typeInto(gui, "##viseme-name", "aa");
    gui.click(reveal(gui, "Rename", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["document_revision"], id);
    EXPECT_TRUE(hasErrorContaining(gui, "already exists")) << gui.document()["messages"].dump();
    EXPECT_ALIVE(gui);
}

// Deformation panel: sliders stored as a new viseme (mesh generated: the sample's set is the
// face's), a preset applied, adjusted and stored back, stored into another viseme from the combo,
// a preset that is a viseme of the set refused on removal.
TEST(AuthoringClicks, StoreTheSlidersAsANewAndAnExistingViseme) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Deformation"});
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["presets"].contains("aa")) << gui.document().dump();
    gui.click(reveal(gui, "jaw_open", "slider"), 0.8);
    gui.waitIdle();
    const double jaw = gui.document()["parameters"]["jaw_open"].get<double>();
    EXPECT_GT(jaw, 0.0);

    typeInto(gui, "##new-viseme-name", "wide");
    gui.click(reveal(gui, "Store as new viseme", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(names(gui).back(), "wide");
    EXPECT_DOUBLE_EQ(gui.document()["presets"]["wide"]["jaw_open"].get<double>(), jaw);

    // Apply "oh", change a slider, store into "oh" (the combo follows the applied preset).
    gui.click(reveal(gui, "oh", "button"));
    gui.waitIdle();
    EXPECT_DOUBLE_EQ(gui.document()["parameters"]["lip_pucker"].get<double>(),
                     gui.document()["presets"]["oh"]["lip_pucker"].get<double>());
    gui.click(reveal(gui, "lip_pucker", "slider"), 0.95);
    gui.waitIdle();
    const double pucker = gui.document()["parameters"]["lip_pucker"].get<double>();
    ASSERT_NE(pucker, gui.document()["presets"]["oh"]["lip_pucker"].get<double>());
    gui.click(reveal(gui, "Store into viseme", "button"));
    gui.waitIdle();
    EXPECT_DOUBLE_EQ(gui.document()["presets"]["oh"]["lip_pucker"].get<double>(), pucker);
    EXPECT_EQ(gui.document()["undo"], "Store sliders in oh");

    choose(gui, "##store-into", "PP");
    gui.click(reveal(gui, "Store into viseme", "button"));
    gui.waitIdle();
    EXPECT_DOUBLE_EQ(gui.document()["presets"]["PP"]["lip_pucker"].get<double>(), pucker);

    // "wide" is a viseme of the face's set: its preset is not removed on its own.
    const auto id = gui.document()["document_revision"];
    gui.click(reveal(gui, "x##remove-wide", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["document_revision"], id);
    EXPECT_TRUE(hasErrorContaining(gui, "remove the viseme instead")) << gui.document()["messages"].dump();
    // The preset combo above the sliders lists the face's presets, "wide" among them.
    choose(gui, "preset", "wide");
    EXPECT_DOUBLE_EQ(gui.document()["parameters"]["jaw_open"].get<double>(), jaw);
    EXPECT_ALIVE(gui);
}

// Frequencies panel at 1280x720: a map started from MPEG-4 (its visemes assigned to the sample's,
// one reassigned by hand), edited per phoneme and per viseme, a rest viseme, direct frequencies, a
// per-phoneme start cancelled, the map saved to a file.
TEST(AuthoringClicks, PhonemeMapEditorStartsEditsAndSavesAMap) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Frequencies"}, 1280, 720);
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["phoneme_based"].get<bool>());

    gui.click(reveal(gui, "##map-start", "combo"));
    gui.waitFrames(2);
    std::optional<Json> mpeg4;
    for (const Json& control : gui.report()["controls"])
        if (control["kind"] == "selectable" && control["text"].get<std::string>().starts_with("MPEG-4"))
            mpeg4 = control;
    ASSERT_TRUE(mpeg4) << "no MPEG-4 entry in the start combo";
    gui.click(*mpeg4);
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["map_start_open"].get<bool>());
    // Every MPEG-4 viseme found a viseme of the sample (by name or by the current map).
    EXPECT_EQ(gui.document()["map_start_unassigned"], 0);
    choose(gui, "##assign-A", "E");
    gui.click(reveal(gui, "Apply map", "button"));
    gui.waitIdle();
    EXPECT_FALSE(gui.document()["map_start_open"].get<bool>());
    EXPECT_EQ(gui.document()["phoneme_map"]["AH"], "E");
    EXPECT_EQ(gui.document()["phoneme_map"]["AA"], "E");

    choose(gui, "##map-AH", "aa");
    EXPECT_EQ(gui.document()["phoneme_map"]["AH"], "aa");
    EXPECT_EQ(gui.document()["phoneme_map"]["AA"], "E");

    const double ah = gui.document()["phoneme_frequencies"]["AH"].get<double>();
    const Json drag = reveal(gui, "##freq-AH", "drag");
    const double y = drag["y"].get<double>() + 0.5 * drag["height"].get<double>();
    gui.drag(drag["x"].get<double>() + 0.5 * drag["width"].get<double>(), y,
             drag["x"].get<double>() + 0.5 * drag["width"].get<double>() + 40.0, y);
    gui.waitIdle();
    EXPECT_GT(gui.document()["phoneme_frequencies"]["AH"].get<double>(), ah);

    choose(gui, "##move-PP", "FF");
    EXPECT_EQ(gui.document()["phoneme_map"]["M"], "FF");
    EXPECT_EQ(gui.document()["phoneme_map"]["B"], "FF");

    typeInto(gui, "##rest-name", "rest");
    gui.click(reveal(gui, "Add rest viseme", "button"));
    gui.waitIdle();
    EXPECT_EQ(names(gui).back(), "rest");

    const auto out =
        std::filesystem::temp_directory_path() / ("visemelab-map-" + std::to_string(getpid()) + ".csv");
    std::filesystem::remove(out);
    gui.click(reveal(gui, "Save map...", "button"));
    gui.waitFrames(2);
    ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>());
    gui.click(gui.control("##name", "text"));
    gui.key("ctrl+a");
    gui.type(out.string());
    gui.click(gui.control("Save", "button"));
    gui.waitIdle();
    ASSERT_TRUE(std::filesystem::exists(out)) << gui.document()["messages"].dump();
    std::ifstream saved(out);
    const std::string csv((std::istreambuf_iterator<char>(saved)), std::istreambuf_iterator<char>());
    EXPECT_NE(csv.find("M,FF"), std::string::npos) << csv;
    EXPECT_NE(csv.find("AH,aa"), std::string::npos) << csv;
    std::filesystem::remove(out);

    gui.click(reveal(gui, "Use direct frequencies", "button"));
    gui.waitIdle();
    EXPECT_FALSE(gui.document()["phoneme_based"].get<bool>());
    EXPECT_EQ(gui.document()["direct_frequencies"].size(), 16u);

    // One viseme per phoneme, with no current map: only the phonemes that name a viseme of the
    // sample ignoring case are assigned (sil, IH -> ih, AA -> aa, CH, TH); Apply waits for the rest.
    gui.click(reveal(gui, "##map-start", "combo"));
    gui.waitFrames(2);
    gui.click(*findIn(gui, "One viseme per phoneme (ARPAbet)", "selectable", "##Combo"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["map_start_unassigned"], 35);
    const auto id = gui.document()["document_revision"];
    gui.click(reveal(gui, "Apply map", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["document_revision"], id);
    gui.click(reveal(gui, "Cancel", "button"));
    gui.waitIdle();
    EXPECT_FALSE(gui.document()["map_start_open"].get<bool>());
    EXPECT_ALIVE(gui);
}

// The authored document is the project: renamed and duplicated visemes, a viseme stored from the
// sliders (preset and mesh) and a phoneme mapped to it are saved with Ctrl+S and come back the same
// when the saved project is opened.
TEST(AuthoringClicks, AuthoredVisemesAndMapSurviveSaveAndReopen) {
    REQUIRE_GUI_TOOLS();
    const auto folder =
        std::filesystem::temp_directory_path() / ("visemelab-authored-" + std::to_string(getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const auto project = folder / "authored.vlproj";
    Json saved;
    {
        GuiDriver gui({"--sample", "--panel", "Visemes"});
        gui.waitIdle();
        gui.click(gui.control("PP", "selectable"));
        typeInto(gui, "##viseme-name", "closed");
        gui.key("Return");
        gui.click(reveal(gui, "Duplicate", "button"));
        gui.waitIdle();
        gui.click(gui.control("Deform", "tab"));
        gui.click(reveal(gui, "jaw_open", "slider"), 0.7);
        typeInto(gui, "##new-viseme-name", "wide");
        gui.click(reveal(gui, "Store as new viseme", "button"));
        gui.waitIdle();
        gui.click(gui.control("Freq.", "tab"));
        choose(gui, "##map-AH", "wide");
        ASSERT_EQ(gui.document()["phoneme_map"]["AH"], "wide") << gui.document()["messages"].dump();
        ASSERT_EQ(names(gui).size(), 17u);

        gui.key("ctrl+s");
        ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>());
        gui.click(gui.control("##name", "text"));
        gui.key("ctrl+a");
        gui.type(project.string());
        gui.click(gui.control("Save", "button"));
        gui.waitIdle();
        ASSERT_EQ(gui.document()["project_path"], project.string()) << gui.document()["messages"].dump();
        EXPECT_FALSE(gui.document()["modified"].get<bool>());
        saved = gui.document();
        EXPECT_ALIVE(gui);
    }
    GuiDriver gui({"--project", project.string()});
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    for (const char* key :
         {"viseme_names", "presets", "parameters", "phoneme_map", "phoneme_frequencies", "target"})
        EXPECT_EQ(gui.document()[key], saved[key]) << key;
    EXPECT_EQ(names(gui)[1], "closed");
    EXPECT_EQ(names(gui)[2], "closed copy");
    EXPECT_EQ(names(gui).back(), "wide");
    EXPECT_FALSE(gui.document()["modified"].get<bool>());
    std::filesystem::remove_all(folder);
}

// Real data nobody here made: the ICT FaceKit mouth shapes have their own names. Started from the
// Oculus map, the pause gets a rest viseme "sil" (which its row then takes by name), the other rows
// are assigned by hand; every shape then has the frequency of the phonemes mapped to it.
TEST(AuthoringClicks, IctMouthShapesGetFrequenciesFromAPhonemeMap) {
    REQUIRE_GUI_TOOLS();
    const auto ict = std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) / "ict-facekit-mouth";
    if (!std::filesystem::is_directory(ict)) GTEST_SKIP() << "shared data folder absent: " << ict;
    GuiDriver gui({"--visemes", ict.string(), "--panel", "Frequencies", "--map-start", "oculus"});
    gui.waitIdle(180.0);
    ASSERT_EQ(names(gui).size(), 7u) << gui.document()["messages"].dump();
    ASSERT_TRUE(gui.document()["map_start_open"].get<bool>());
    EXPECT_EQ(gui.document()["map_start_unassigned"], 15); // no name matches

    typeInto(gui, "##rest-name", "sil");
    gui.click(reveal(gui, "Add rest viseme", "button"));
    gui.waitIdle(180.0);
    EXPECT_EQ(names(gui).back(), "sil");
    EXPECT_EQ(gui.document()["map_start_unassigned"], 14); // the pause row took "sil" by name

    const std::pair<const char*, const char*> shapes[] = {
        {"aa", "jawOpen"},      {"ih", "mouthStretch_L"}, {"nn", "mouthStretch_L"}, {"DD", "jawOpen"},
        {"SS", "mouthSmile_L"}, {"RR", "mouthPucker"},    {"TH", "mouthStretch_L"}, {"PP", "mouthClose"},
        {"E", "mouthSmile_L"},  {"kk", "jawOpen"},        {"FF", "mouthRollLower"}, {"ou", "mouthPucker"},
        {"oh", "mouthFunnel"},  {"CH", "mouthFunnel"}};
    for (const auto& [row, shape] : shapes) choose(gui, std::string("##assign-") + row, shape);
    EXPECT_EQ(gui.document()["map_start_unassigned"], 0);
    gui.click(reveal(gui, "Apply map", "button"));
    gui.waitIdle(180.0);
    EXPECT_ALIVE(gui);
    ASSERT_TRUE(gui.document()["phoneme_based"].get<bool>()) << gui.document()["messages"].dump();
    EXPECT_EQ(gui.document()["undo"], "Phoneme map from Oculus / Meta 15 visemes");

    // Reference: each shape's frequency is its phonemes' share of the table.
    std::map<std::string, double> expected;
    double total = 0.0;
    for (const auto& [phoneme, value] : gui.document()["phoneme_frequencies"].items()) {
        expected[gui.document()["phoneme_map"][phoneme].get<std::string>()] += value.get<double>();
        total += value.get<double>();
    }
    const Json& frequencies = gui.document()["viseme_frequencies"];
    ASSERT_EQ(frequencies.size(), 8u);
    for (const auto& [name, value] : frequencies.items()) {
        EXPECT_NEAR(value.get<double>(), expected[name] / total, 1e-9) << name;
        EXPECT_GT(value.get<double>(), 0.0) << name;
    }
}

} // namespace
} // namespace vl::test
