// The editor used as a designer uses it: real mouse and keyboard events (xdotool on a private Xvfb)
// on the real window, every control of every panel. Each test checks that the editor is still
// running after every event and that the clicks did what they say in the document.
// Skips with a message when Xvfb or xdotool is not installed.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unistd.h>

namespace vl::test {
namespace {

#define REQUIRE_GUI_TOOLS()                                                                                  \
    if (const std::string missing = missingGuiTools(); !missing.empty())                                     \
    GTEST_SKIP() << "GUI click tests need" << missing

#define EXPECT_ALIVE(gui)                                                                                    \
    ASSERT_TRUE((gui).alive()) << "editor " << (gui).exitStatus() << ":\n" << (gui).log()

std::uint64_t documentId(const GuiDriver& gui) {
    return gui.document()["document_id"].get<std::uint64_t>();
}

bool hasError(const GuiDriver& gui) {
    for (const auto& message : gui.document()["messages"])
        if (message["error"].get<bool>()) return true;
    return false;
}

// The report of issue 14: on the Refine tab, clicking "normals" crashed the editor (a reference to
// the face held across the commit of the new settings).
TEST(EditorClicks, RefineTabCriterionRadiosSwitchTheCriterion) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    for (const char* criterion : {"normals", "contour error", "depth", "contour error", "normals", "depth"}) {
        const std::string expected = std::string(criterion) == "contour error" ? "contour" : criterion;
        const bool switches = gui.document()["criterion"] != expected;
        const auto before = documentId(gui);
        gui.click(gui.control(criterion, "radio"));
        EXPECT_ALIVE(gui);
        gui.waitIdle();
        EXPECT_EQ(gui.document()["criterion"].get<std::string>(), expected);
        if (switches) {
            EXPECT_NE(documentId(gui), before) << criterion;
            EXPECT_EQ(gui.document()["undo"], "Refinement thresholds") << gui.document().dump();
        }
    }
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

// Every threshold slider of every criterion, clicked at two places and dragged, then every button.
TEST(EditorClicks, RefineTabSlidersAndButtons) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    const std::tuple<const char*, std::vector<const char*>> criteria[] = {
        {"depth", {"max depth", "uniform depth"}},
        {"normals", {"max depth", "dihedral angle", "normal angle"}},
        {"contour error", {"max depth", "average error", "maximum error", "samples per side"}}};
    for (const auto& [criterion, sliders] : criteria) {
        gui.click(gui.control(criterion, "radio"));
        gui.waitIdle();
        for (const char* name : sliders) {
            // Two far apart places of the frame give two different values: the second click
            // always edits, the first unless the value was already there.
            const auto before = documentId(gui);
            for (const double at : {0.1, 0.9}) {
                const auto clickedFrom = documentId(gui);
                gui.click(gui.control(name, "slider"), at);
                EXPECT_ALIVE(gui);
                gui.waitIdle();
                if (at > 0.5) {
                    EXPECT_NE(documentId(gui), clickedFrom) << criterion << " / " << name;
                }
            }
            EXPECT_NE(documentId(gui), before) << criterion << " / " << name;
            const auto slider = gui.control(name, "slider");
            const double y = slider["y"].get<double>() + 0.5 * slider["height"].get<double>();
            gui.drag(slider["x"].get<double>() + 0.1 * slider["width"].get<double>(), y,
                     slider["x"].get<double>() + 0.4 * slider["width"].get<double>(), y);
            EXPECT_ALIVE(gui);
        }
        for (const char* button : {"Refine", "Simplify", "Re-adapt", "For all visemes"}) {
            gui.click(gui.control(button, "button"));
            EXPECT_ALIVE(gui);
            gui.waitIdle(120.0);
            EXPECT_ALIVE(gui);
        }
    }
    // Automatic mode: a slider change re-adapts in the background.
    gui.click(gui.control("Automatic: re-adapt after every slider or threshold change", "checkbox"));
    gui.click(gui.control("max depth", "slider"), 0.4);
    gui.waitIdle(120.0);
    EXPECT_ALIVE(gui);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();

    // Undo and redo through the keyboard walk back over the edits without a crash.
    const auto edited = documentId(gui);
    for (int i = 0; i < 6; ++i) gui.key("ctrl+z");
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentId(gui), edited);
    for (int i = 0; i < 6; ++i) gui.key("ctrl+y");
    EXPECT_ALIVE(gui);
}

// Monkey test over every panel: every visible control of the side panel is clicked once (popups
// and dialogs it opens are closed with Escape), scrolling the panel to reach the rest.
TEST(EditorClicks, EveryControlOfEveryPanelSurvivesAClick) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample"});
    gui.waitIdle();
    const std::pair<std::string, std::string> tabs[] = {
        {"Visemes", "Visemes"},   {"Freq.", "Frequencies"}, {"Weights", "Weights"}, {"Deform", "Deformation"},
        {"Refine", "Refinement"}, {"Reduce", "Reduction"},  {"Export", "Export"}};
    int clicked = 0;
    for (const auto& [tab, panel] : tabs) {
        gui.click(gui.control(tab, "tab"));
        gui.waitIdle();
        if (const auto load = gui.find("Load bundled face", "button")) { // face-only panels
            gui.click(*load);
            gui.waitIdle();
        }
        std::set<std::string> done;
        for (int pass = 0; pass < 40; ++pass) {
            // The next visible control of the side panel not clicked yet (labels + kind + rank).
            std::optional<nlohmann::json> next;
            std::string nextKey;
            std::map<std::string, int> rank;
            for (const auto& control : gui.report()["controls"]) {
                if (control["window"] != "##side" || control["kind"] == "tab") continue;
                const std::string key =
                    control["kind"].get<std::string>() + "|" + control["label"].get<std::string>();
                const std::string ranked = key + "|" + std::to_string(rank[key]++);
                if (!control["visible"].get<bool>() || done.count(ranked)) continue;
                next = control;
                nextKey = ranked;
                break;
            }
            if (!next) {
                // Scroll the panel body once to reveal what lies below; stop when nothing new shows.
                const auto tabControl = gui.control(tab, "tab");
                gui.scroll(tabControl["x"].get<double>() + 100, 400, 5);
                bool fresh = false;
                std::map<std::string, int> rank2;
                for (const auto& control : gui.report()["controls"]) {
                    if (control["window"] != "##side" || control["kind"] == "tab") continue;
                    const std::string key =
                        control["kind"].get<std::string>() + "|" + control["label"].get<std::string>();
                    if (control["visible"].get<bool>() &&
                        !done.count(key + "|" + std::to_string(rank2[key]++)))
                        fresh = true;
                }
                if (!fresh) break;
                continue;
            }
            done.insert(nextKey);
            gui.click(*next, next->value("kind", "") == "slider" ? 0.3 : 0.5);
            EXPECT_ALIVE(gui) << " after clicking " << nextKey << " on " << tab;
            ++clicked;
            gui.waitIdle(120.0);
            // Close whatever the click opened (a combo, a file dialog, a confirmation popup).
            for (int i = 0; i < 3 && (gui.report()["popup_open"].get<bool>() ||
                                      gui.document()["file_dialog_open"].get<bool>());
                 ++i) {
                if (const auto cancel = gui.find("Cancel", "button"))
                    gui.click(*cancel);
                else
                    gui.key("Escape");
            }
            EXPECT_ALIVE(gui);
            // The panel may have changed (a removed viseme, a new tab): keep clicking on this tab.
            if (gui.document()["panel"] != panel) {
                const auto tabControl = gui.find(tab, "tab");
                if (tabControl) gui.click(*tabControl);
            }
        }
    }
    EXPECT_GT(clicked, 60) << "too few controls reached";
    EXPECT_ALIVE(gui);
}

// Painting weights with a real drag over the 3D view: the Weights panel's brush, one undo step.
TEST(EditorClicks, PaintingWeightsWithARealDrag) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    gui.click(gui.control("painted", "radio"));
    gui.click(gui.control("Paint (left drag on the mesh; Alt + drag orbits)", "checkbox"));
    ASSERT_TRUE(gui.document()["brush"].get<bool>());
    const auto before = documentId(gui);
    const auto view = gui.control("main", "view");
    const double cx = view["x"].get<double>() + 0.5 * view["width"].get<double>();
    const double cy = view["y"].get<double>() + 0.5 * view["height"].get<double>();
    gui.drag(cx - 60, cy, cx + 60, cy + 20, 12);
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentId(gui), before);
    EXPECT_EQ(gui.document()["undo"], "Paint stroke") << gui.document().dump();
    gui.key("ctrl+z");
    EXPECT_NE(gui.document()["undo"], "Paint stroke");
}

// The menus: every item of File, Edit and View (dialogs they open are cancelled; Quit is last and
// must ask nothing on an unmodified document).
TEST(EditorClicks, EveryMenuItem) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample"});
    gui.waitIdle();
    for (const char* menu : {"File", "Edit", "View", "Help"}) {
        gui.click(gui.control(menu, "menu"));
        std::vector<std::string> items;
        for (const auto& control : gui.report()["controls"])
            if (control["kind"] == "menuitem") items.push_back(control["label"]);
        gui.key("Escape");
        for (const std::string& item : items) {
            if (item == "Quit") continue;
            gui.click(gui.control(menu, "menu"));
            const auto entry = gui.find(item, "menuitem");
            if (!entry) {
                gui.key("Escape");
                continue; // e.g. "Undo ..." renamed by an earlier item
            }
            gui.click(*entry);
            EXPECT_ALIVE(gui) << " after " << menu << " > " << item;
            gui.waitIdle(120.0);
            for (int i = 0; i < 3 && (gui.report()["popup_open"].get<bool>() ||
                                      gui.document()["file_dialog_open"].get<bool>());
                 ++i) {
                if (const auto cancel = gui.find("Cancel", "button"))
                    gui.click(*cancel);
                else
                    gui.key("Escape");
            }
            EXPECT_ALIVE(gui);
        }
    }
}

// The cost plot: a click on the curve picks m (undoable), the axis options redraw it.
TEST(EditorClicks, CostPlotClickChoosesTheTarget) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    const int n = gui.document()["visemes"].get<int>();
    ASSERT_NE(gui.document()["target"].get<int>(), n);
    gui.click(gui.control("##cost", "button"), 0.985, 0.5); // the right end: p = n
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["target"].get<int>(), n);
    EXPECT_EQ(gui.document()["undo"], "Target m = " + std::to_string(n)) << gui.document().dump();
    for (const char* option : {"log scale", "% of p = 1", "log scale", "% of p = 1"}) {
        gui.click(gui.control(option, "checkbox"));
        EXPECT_ALIVE(gui);
    }
    gui.key("ctrl+z");
    EXPECT_NE(gui.document()["target"].get<int>(), n);
}

std::string fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The bundled sample is read-only: after an edit, Ctrl+S asks where to save (an untitled document)
// and the files under assets/sample are byte for byte what they were.
TEST(EditorClicks, SaveOnTheSampleAsksForAFileAndLeavesTheAssetsAlone) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path sample =
        std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj";
    const std::string before = fileBytes(sample);
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    EXPECT_EQ(gui.document()["project_path"], "");
    gui.click(gui.control("groups m", "slider"), 0.9);
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["modified"].get<bool>());
    gui.key("ctrl+s");
    EXPECT_TRUE(gui.document()["file_dialog_open"].get<bool>());
    gui.click(gui.control("Cancel", "button"));
    EXPECT_ALIVE(gui);
    gui.waitIdle();
    EXPECT_EQ(fileBytes(sample), before);
}

// A broken project given at start opens the editor with the error shown (naming the file), not an exit.
TEST(EditorClicks, BadStartProjectIsShownNotFatal) {
    REQUIRE_GUI_TOOLS();
    const auto file =
        std::filesystem::temp_directory_path() / ("visemelab-broken-" + std::to_string(getpid()) + ".vlproj");
    std::ofstream(file) << "{\"format\": \"visemelab-project\", \"version\": 1, \"visemes\": [1, 2";
    GuiDriver gui({"--project", file.string(), "--panel", "Nosuch"});
    gui.waitFrames(3);
    EXPECT_ALIVE(gui);
    bool named = false;
    for (const auto& message : gui.document()["messages"])
        named |= message["error"].get<bool>() &&
                 message["text"].get<std::string>().find(file.filename().string()) != std::string::npos;
    EXPECT_TRUE(named) << gui.document()["messages"].dump();
    gui.click(gui.control("Visemes", "tab"));
    EXPECT_ALIVE(gui);
    std::filesystem::remove(file);
}

} // namespace
} // namespace vl::test
