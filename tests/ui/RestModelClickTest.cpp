// The Reduction panel's model driven with real clicks (xdotool on a private Xvfb, see GuiDriver.h):
// a new document of the sample meshes is rest-free with sil resting; "rest is a key", "rest free" and
// the rest viseme combo are undoable edits the reduction follows; a resting viseme's button in the
// groups table selects it for the comparison.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace vl::test {
namespace {

using Json = nlohmann::json;

const Json& rest(const GuiDriver& gui) {
    return gui.document()["reduction"]["rest"];
}

std::vector<std::string> resting(const GuiDriver& gui) {
    const Json& current = gui.document()["reduction"]["current"];
    return current.is_null() ? std::vector<std::string>{}
                             : current["resting"].get<std::vector<std::string>>();
}

bool rests(const GuiDriver& gui, const std::string& name) {
    const auto names = resting(gui);
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The control of that text and kind in an open combo's list.
std::optional<Json> inCombo(const GuiDriver& gui, const std::string& text) {
    for (const Json& control : gui.report()["controls"])
        if (control["kind"] == "selectable" && control["text"] == text &&
            control["window"].get<std::string>().starts_with("##Combo"))
            return control;
    return std::nullopt;
}

TEST(RestModelClicks, TheModelIsShownSwitchedAndUndone) {
    REQUIRE_GUI_TOOLS();
    const auto sample = std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample";
    GuiDriver gui({"--visemes", sample.string(), "--panel", "Reduction"});
    gui.waitIdle();
    // A new document: auto, rest-free because the set has sil, which rests.
    EXPECT_EQ(rest(gui)["model"], "auto") << rest(gui);
    EXPECT_TRUE(rest(gui)["free"].get<bool>());
    EXPECT_EQ(rest(gui)["resolved"], "sil");
    ASSERT_TRUE(rests(gui, "sil")) << gui.document()["reduction"].dump();

    // Rest is a key: every viseme joins a key again, one undo step.
    gui.click(gui.control("rest is a key", "radio"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(rest(gui)["model"], "key");
    EXPECT_FALSE(rest(gui)["free"].get<bool>());
    EXPECT_TRUE(resting(gui).empty()) << gui.document()["reduction"].dump();
    EXPECT_EQ(gui.document()["undo"], "Rest is a key");
    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_EQ(rest(gui)["model"], "auto");
    EXPECT_TRUE(rests(gui, "sil"));

    // Rest free, then PP as the rest viseme: PP rests from now on.
    gui.click(gui.control("rest free", "radio"));
    gui.waitIdle();
    EXPECT_EQ(rest(gui)["model"], "free");
    gui.click(gui.control("rest viseme", "combo"));
    gui.waitFrames(2);
    const auto pp = inCombo(gui, "PP");
    ASSERT_TRUE(pp) << "no PP in the rest viseme list";
    gui.click(*pp);
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(rest(gui)["rest_viseme"], "PP");
    EXPECT_EQ(rest(gui)["resolved"], "PP");
    ASSERT_TRUE(rests(gui, "PP")) << gui.document()["reduction"].dump();

    // The resting viseme's button in the groups table selects it for the comparison (shown as the
    // neutral, not as a group).
    const auto names = gui.document()["viseme_names"].get<std::vector<std::string>>();
    const auto index = std::find(names.begin(), names.end(), "PP") - names.begin();
    int buttons = 0;
    for (const Json& control : gui.report()["controls"])
        if (control["kind"] == "button" && control["text"] == "PP" && control.value("visible", false)) {
            gui.click(control);
            ++buttons;
            break;
        }
    ASSERT_EQ(buttons, 1) << "no visible PP button in the groups table";
    gui.waitFrames(3);
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["selected_viseme"].get<long>(), static_cast<long>(index));
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

// A neutral grid and three visemes that bend it differently: a set without a rest viseme.
std::filesystem::path writeSetWithoutRest() {
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-no-rest-" + std::to_string(getpid()));
    writeGridVisemeFolder(dir, {"aa", "E", "oh"}, 6,
                          [](int v, int i, int j) { return std::sin(v * (i + 2 * j)); });
    return dir;
}

TEST(RestModelClicks, AddRestVisemeGivesASetWithoutOneItsRest) {
    REQUIRE_GUI_TOOLS();
    const auto dir = writeSetWithoutRest();
    GuiDriver gui({"--visemes", dir.string(), "--panel", "Reduction"});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["visemes"].get<int>(), 3);
    // Auto without a rest viseme: the rest is a key.
    EXPECT_FALSE(rest(gui)["free"].get<bool>()) << rest(gui);
    EXPECT_EQ(rest(gui)["resolved"], "");

    gui.click(gui.control("Add rest viseme", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 4);
    EXPECT_EQ(gui.document()["undo"], "Add rest viseme sil");
    EXPECT_EQ(rest(gui)["resolved"], "sil");
    EXPECT_TRUE(rest(gui)["free"].get<bool>());
    EXPECT_TRUE(rests(gui, "sil")) << gui.document()["reduction"].dump();
    // With a rest viseme the button is gone.
    EXPECT_FALSE(gui.find("Add rest viseme", "button"));
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl::test
