// The editor used as a designer uses it: real mouse and keyboard events (xdotool on a private Xvfb)
// on the real window, every control of every panel. Each test checks that the editor is still
// running after every event and that the clicks did what they say in the document.
// Skips with a message when Xvfb or xdotool is not installed.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <unistd.h>

namespace vl::test {
namespace {

// Closes whatever a click opened (a combo, a file dialog, a confirmation popup): Cancel when the
// popup has one, else Escape; at most three levels.
void closeWhatTheClickOpened(GuiDriver& gui) {
    for (int i = 0;
         i < 3 && (gui.report()["popup_open"].get<bool>() || gui.document()["file_dialog_open"].get<bool>());
         ++i) {
        if (const auto cancel = gui.find("Cancel", "button"))
            gui.click(*cancel);
        else
            gui.key("Escape");
    }
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
        const auto before = documentRevision(gui);
        gui.click(gui.control(criterion, "radio"));
        EXPECT_ALIVE(gui);
        gui.waitIdle();
        EXPECT_EQ(gui.document()["criterion"].get<std::string>(), expected);
        if (switches) {
            EXPECT_NE(documentRevision(gui), before) << criterion;
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
            const auto before = documentRevision(gui);
            for (const double at : {0.1, 0.9}) {
                const auto clickedFrom = documentRevision(gui);
                gui.click(gui.control(name, "slider"), at);
                EXPECT_ALIVE(gui);
                gui.waitIdle();
                if (at > 0.5) {
                    EXPECT_NE(documentRevision(gui), clickedFrom) << criterion << " / " << name;
                }
            }
            EXPECT_NE(documentRevision(gui), before) << criterion << " / " << name;
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
    const auto edited = documentRevision(gui);
    for (int i = 0; i < 6; ++i) gui.key("ctrl+z");
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentRevision(gui), edited);
    for (int i = 0; i < 6; ++i) gui.key("ctrl+y");
    EXPECT_ALIVE(gui);
}

// Monkey test over every panel: every visible control of the side panel is clicked once (popups
// and dialogs it opens are closed with Escape), scrolling the panel to reach the rest. One test per
// panel, each on its own editor: seven ctest entries that two ctest jobs can run side by side
// (as one test it took ~170 s and ended the suite's run alone).
struct MonkeyPanel {
    const char* tab;   // the tab's label
    const char* panel; // the panel's name (--panel, the probe's "panel")
    int minimum; // about half the controls clicked on 2026-11-29 (215 in all): fewer means the walk broke off
};

// The parameter as gtest lists it: gtest_discover_tests names the ctest entries
// EveryPanel/EditorPanelClicks.EveryControlSurvivesAClick/<panel> from it (tests/TestCosts.cmake).
void PrintTo(const MonkeyPanel& panel, std::ostream* out) {
    *out << panel.panel;
}

class EditorPanelClicks : public ::testing::TestWithParam<MonkeyPanel> {};

TEST_P(EditorPanelClicks, EveryControlSurvivesAClick) {
    REQUIRE_GUI_TOOLS();
    const auto& [tab, panel, minimum] = GetParam();
    GuiDriver gui({"--sample", "--panel", panel});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["panel"], panel);
    if (const auto load = gui.find("Load bundled face", "button")) { // face-only panels
        gui.click(*load);
        gui.waitIdle();
    }
    int clicked = 0;
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
                if (control["visible"].get<bool>() && !done.count(key + "|" + std::to_string(rank2[key]++)))
                    fresh = true;
            }
            if (!fresh) break;
            continue;
        }
        done.insert(nextKey);
        gui.click(*next, next->value("kind", "") == "slider" ? 0.3 : 0.5);
        EXPECT_ALIVE(gui) << " after clicking " << nextKey << " on " << tab;
        ++clicked;
        // As waitIdle(120), less its first frame: click() has waited a frame after the release already.
        for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
             gui.document().value("busy", false) && std::chrono::steady_clock::now() < deadline;)
            gui.waitFrames(1);
        gui.waitFrames(1);
        closeWhatTheClickOpened(gui);
        EXPECT_ALIVE(gui);
        // The panel may have changed (a removed viseme, a new tab): keep clicking on this tab.
        if (gui.document()["panel"] != panel) {
            const auto tabControl = gui.find(tab, "tab");
            if (tabControl) gui.click(*tabControl);
        }
    }
    std::printf("%s: %d controls clicked\n", panel, clicked);
    EXPECT_GE(clicked, minimum) << "too few controls reached on " << panel;
    EXPECT_ALIVE(gui);
}

INSTANTIATE_TEST_SUITE_P(
    EveryPanel, EditorPanelClicks,
    ::testing::Values(MonkeyPanel{"Visemes", "Visemes", 20}, MonkeyPanel{"Freq.", "Frequencies", 20},
                      MonkeyPanel{"Weights", "Weights", 13}, MonkeyPanel{"Deform", "Deformation", 20},
                      MonkeyPanel{"Refine", "Refinement", 15}, MonkeyPanel{"Reduce", "Reduction", 14},
                      MonkeyPanel{"Export", "Export", 8}));

// Painting weights with a real drag over the 3D view: the Weights panel's brush, one undo step.
TEST(EditorClicks, PaintingWeightsWithARealDrag) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    // The first stroke in area mode starts from the area weights shown (not from all ones, which
    // would swallow an "add" stroke) and makes the weights painted.
    gui.click(gui.control("area (rho2)", "radio"));
    ASSERT_EQ(gui.document()["weight_mode"], "area");
    gui.click(gui.control("Paint (left drag on the mesh; Alt + drag orbits)", "checkbox"));
    ASSERT_TRUE(gui.document()["brush"].get<bool>());
    const auto before = documentRevision(gui);
    const auto view = gui.control("main", "view");
    const double cx = view["x"].get<double>() + 0.5 * view["width"].get<double>();
    const double cy = view["y"].get<double>() + 0.5 * view["height"].get<double>();
    gui.drag(cx - 60, cy, cx + 60, cy + 20, 12);
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentRevision(gui), before);
    EXPECT_EQ(gui.document()["undo"], "Paint stroke") << gui.document().dump();
    EXPECT_EQ(gui.document()["weight_mode"], "painted");
    gui.key("ctrl+z");
    EXPECT_NE(gui.document()["undo"], "Paint stroke");
    EXPECT_EQ(gui.document()["weight_mode"], "area");
    // Switching to painted keeps the area weights shown; an "add" stroke raises them.
    gui.click(gui.control("painted", "radio"));
    ASSERT_EQ(gui.document()["weight_mode"], "painted");
    const double mean = gui.document()["painted_mean"].get<double>();
    EXPECT_GT(mean, 0.0);
    EXPECT_LT(mean, 1.0);
    gui.drag(cx - 60, cy - 20, cx + 60, cy, 12);
    EXPECT_EQ(gui.document()["undo"], "Paint stroke") << gui.document().dump();
    EXPECT_GT(gui.document()["painted_mean"].get<double>(), mean);
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
            closeWhatTheClickOpened(gui);
            EXPECT_ALIVE(gui);
        }
    }
}

// The cost plot: a click on the curve picks m (undoable), the axis options redraw it.
TEST(EditorClicks, CostPlotClickChoosesTheTarget) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    // The sample's rest is free and sil rests: its keys run to p = n - 1, the right end of the plot.
    ASSERT_TRUE(gui.document()["reduction"]["rest"]["free"].get<bool>());
    const int n = gui.document()["visemes"].get<int>() - 1;
    ASSERT_NE(gui.document()["target"].get<int>(), n);
    gui.click(gui.control("##cost", "button"), 0.985, 0.5); // the right end: p = n - 1
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

// Constraints with real clicks: pin PP through its combo and button, keep two visemes together,
// undo, and remove a constraint with its x button; every change is one undo step.
TEST(EditorClicks, ConstraintsArePinnedAndRemovedByClicks) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["constraints"].get<int>(), 0);
    gui.click(gui.control("##pinned viseme", "combo"));
    gui.click(gui.control("PP", "selectable"));
    gui.click(gui.control("Pin as its own key", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["constraints"].get<int>(), 1) << gui.document().dump();
    EXPECT_EQ(gui.document()["undo"], "Constraints");
    gui.click(gui.control("##first of pair", "combo"));
    gui.click(gui.control("E", "selectable"));
    gui.click(gui.control("##second of pair", "combo"));
    gui.click(gui.control("ih", "selectable"));
    gui.click(gui.control("Keep together", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["constraints"].get<int>(), 2) << gui.document()["messages"].dump();
    gui.key("ctrl+z");
    EXPECT_EQ(gui.document()["constraints"].get<int>(), 1);
    gui.click(gui.control("x", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["constraints"].get<int>(), 0);
    EXPECT_ALIVE(gui);
}

// Every file of a folder, byte for byte.
std::map<std::string, std::string> folderBytes(const std::filesystem::path& folder) {
    std::map<std::string, std::string> bytes;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
            bytes[entry.path().lexically_relative(folder).string()] = fileBytes(entry.path());
    return bytes;
}

// The bundled sample is read-only, however it is opened (--sample, the sample project, File > Load
// sample face): after an edit, Ctrl+S asks where to save (an untitled document), the files under
// assets/sample stay byte for byte what they were, and the copy saved elsewhere refers to the
// sample's meshes by paths relative to itself.
TEST(EditorClicks, SaveOnTheSampleAsksForAFileAndLeavesTheAssetsAlone) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path assets = std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample";
    const auto before = folderBytes(assets);
    const auto out = std::filesystem::temp_directory_path() / ("visemelab-saved-" + std::to_string(getpid()));
    std::filesystem::remove_all(out);
    const std::vector<std::vector<std::string>> ways = {
        {"--sample"}, {"--project", (assets / "sample.vlproj").string()}, {}};
    for (std::size_t way = 0; way < ways.size(); ++way) {
        SCOPED_TRACE("opened with: " +
                     (ways[way].empty() ? std::string("File > Load sample face") : ways[way][0]));
        GuiDriver gui(ways[way]);
        gui.waitIdle();
        if (ways[way].empty()) {
            gui.click(gui.control("File", "menu"));
            gui.click(gui.control("Load sample face", "menuitem"));
            gui.waitIdle();
            ASSERT_GT(gui.document()["visemes"].get<int>(), 0) << gui.document().dump();
        }
        EXPECT_EQ(gui.document()["project_path"], "");
        gui.click(gui.control("Reduce", "tab"));
        gui.click(gui.control("groups m", "slider"), way == 1 ? 0.2 : 0.9);
        gui.waitIdle();
        ASSERT_TRUE(gui.document()["modified"].get<bool>());
        gui.key("ctrl+s");
        ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>());
        if (way == 0) {
            gui.click(gui.control("Cancel", "button"));
        } else {
            const auto target = out / ("way" + std::to_string(way)) / "mine.vlproj";
            std::filesystem::create_directories(target.parent_path());
            gui.click(gui.control("##name", "text"));
            gui.key("ctrl+a");
            gui.type(target.string());
            gui.click(gui.control("Save", "button"));
            gui.waitIdle();
            EXPECT_EQ(gui.document()["project_path"], target.string()) << gui.document()["messages"].dump();
            EXPECT_FALSE(gui.document()["modified"].get<bool>());
            const auto saved = nlohmann::json::parse(fileBytes(target));
            std::vector<std::string> files = {saved["neutral"]["file"].get<std::string>()};
            for (const auto& viseme : saved["visemes"]) files.push_back(viseme["file"].get<std::string>());
            for (const std::string& file : files) {
                EXPECT_FALSE(std::filesystem::path(file).is_absolute()) << file;
                EXPECT_TRUE(std::filesystem::is_regular_file(target.parent_path() / file)) << file;
            }
        }
        EXPECT_ALIVE(gui);
        gui.waitIdle();
        EXPECT_TRUE(folderBytes(assets) == before) << "assets/sample changed";
    }
    std::filesystem::remove_all(out);
}

// The status bar's message as drawn (the probe records it as a control of kind "status").
std::string statusText(const GuiDriver& gui) {
    for (const auto& control : gui.report()["controls"])
        if (control["kind"] == "status" && control["visible"].get<bool>()) return control["label"];
    return {};
}

// Bad start options open the editor with the error in its status bar, not an exit: each option
// applies on its own (the panel after a broken project still opens), and Quit exits with code 0.
TEST(EditorClicks, BadStartOptionsAreShownNotFatal) {
    REQUIRE_GUI_TOOLS();
    const auto broken =
        std::filesystem::temp_directory_path() / ("visemelab-broken-" + std::to_string(getpid()) + ".vlproj");
    std::ofstream(broken) << "{\"format\": \"visemelab-project\", \"version\": 1, \"visemes\": [1, 2";
    struct Case {
        std::vector<std::string> arguments;
        std::string expectedError, expectedPanel;
    };
    const std::vector<Case> cases = {
        {{"--project", broken.string(), "--panel", "Weights"}, broken.filename().string(), "Weights"},
        {{"--project", "/nonexistent/nosuch.vlproj"}, "nosuch.vlproj", "Visemes"},
        {{"--visemes", "/nonexistent/folder", "--panel", "Frequencies"},
         "/nonexistent/folder",
         "Frequencies"},
        {{"--sample", "--panel", "Nosuch"}, "unknown panel 'Nosuch'", "Visemes"},
        {{"--sample", "--viseme", "Nosuch", "--panel", "Reduction"}, "no viseme named 'Nosuch'", "Reduction"},
        {{"--sample", "--brush", "spray", "--panel", "Weights"}, "--brush", "Weights"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.arguments[0] + " " + c.arguments[1]);
        GuiDriver gui(c.arguments);
        gui.waitIdle();
        EXPECT_ALIVE(gui);
        EXPECT_TRUE(hasError(gui)) << gui.document()["messages"].dump();
        const std::string shown = statusText(gui);
        EXPECT_NE(shown.find(c.expectedError), std::string::npos) << "status bar: " << shown;
        EXPECT_EQ(gui.document()["panel"], c.expectedPanel);
        gui.click(gui.control("Visemes", "tab"));
        EXPECT_ALIVE(gui);
        gui.click(gui.control("File", "menu"));
        try {
            gui.click(gui.control("Quit", "menuitem"));
        } catch (const std::runtime_error&) {
            // the driver waits for a frame after the click; the editor quit before drawing it
        }
        for (int i = 0; i < 100 && gui.alive(); ++i) usleep(50000);
        EXPECT_EQ(gui.exitStatus(), "exit code 0");
    }
    std::filesystem::remove(broken);
}

} // namespace
} // namespace vl::test
