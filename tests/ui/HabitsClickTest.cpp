// Issue 32's habits with real input (xdotool on a private Xvfb, see GuiDriver.h): quick key taps
// are not lost, Ctrl+Q quits through the unsaved-changes prompt, the window title names the file
// with a dirty marker, a new document leaves no speech or view title of the old one, ticking
// Automatic moves no slider under the cursor, and the interface follows the content scale.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vl::test {
namespace {

// Three taps within one frame (xdotool sends them at once: numpad 3, W, numpad 7) each do what they
// say; the old polling of ImGui's key state saw none of them. (Not the same key thrice: GLFW takes a
// release and press of one key within 20 ms for autorepeat, as no hand taps that fast.)
TEST(HabitsClicks, QuickKeyTapsAreNotLost) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes"});
    gui.waitIdle();
    const bool wireframe = gui.document()["wireframe"].get<bool>();
    gui.tap("KP_3 w KP_7");
    EXPECT_NE(gui.document()["wireframe"].get<bool>(), wireframe);
    EXPECT_NEAR(gui.document()["camera"]["pitch"].get<double>(), 1.5708, 1e-3) << "the top view";
    gui.tap("KP_1");
    EXPECT_NEAR(gui.document()["camera"]["pitch"].get<double>(), 0.0, 1e-6) << "the front view";
    gui.tap("w");
    EXPECT_EQ(gui.document()["wireframe"].get<bool>(), wireframe);
    // A quick Ctrl+L loads the sample again (the document is unchanged: no prompt).
    const auto loads = gui.document()["messages"].size();
    gui.tap("ctrl+l");
    gui.waitIdle();
    EXPECT_GT(gui.document()["messages"].size(), loads) << gui.document()["messages"].dump();
    EXPECT_ALIVE(gui);
}

// The title: file, dirty marker, folder; Ctrl+Q asks while something is unsaved and quits at once
// when nothing is.
TEST(HabitsClicks, TitleDirtyMarkerAndCtrlQ) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes"});
    gui.waitIdle();
    EXPECT_EQ(gui.windowTitle(), "Untitled - VisemeLab");
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("visemelab-habits-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    gui.key("ctrl+shift+s");
    gui.chooseFile(folder / "habits.vlproj", "Save");
    EXPECT_EQ(gui.windowTitle(), "habits.vlproj - " + folder.string() + " - VisemeLab");
    // An edit: the title says so.
    gui.click(gui.control("aa", "selectable"));
    gui.click(gui.control("Duplicate", "button"));
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["modified"].get<bool>());
    EXPECT_EQ(gui.windowTitle(), "habits.vlproj* - " + folder.string() + " - VisemeLab");
    // Ctrl+Q asks; Cancel keeps the editor.
    gui.tap("ctrl+q");
    ASSERT_TRUE(gui.find("Discard changes", "button")) << "no unsaved-changes prompt";
    gui.click(gui.control("Cancel", "button"));
    EXPECT_ALIVE(gui);
    EXPECT_FALSE(gui.find("Discard changes", "button"));
    // Saved: clean again, and Ctrl+Q quits without asking.
    gui.key("ctrl+s");
    gui.waitIdle();
    EXPECT_FALSE(gui.document()["modified"].get<bool>());
    EXPECT_EQ(gui.windowTitle(), "habits.vlproj - " + folder.string() + " - VisemeLab");
    gui.tap("ctrl+q", false);
    EXPECT_TRUE(gui.waitForExit(10.0)) << "Ctrl+Q with nothing unsaved quits";
    EXPECT_EQ(gui.exitStatus(), "exit code 0");
    std::filesystem::remove_all(folder);
}

TEST(HabitsClicks, CtrlQWithUnsavedChangesDiscards) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes"});
    gui.waitIdle();
    gui.click(gui.control("aa", "selectable"));
    gui.click(gui.control("Duplicate", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.windowTitle(), "Untitled* - VisemeLab");
    // Duplicating the copy counts on.
    gui.click(gui.control("Duplicate", "button"));
    gui.waitIdle();
    EXPECT_TRUE(gui.find("aa copy 2", "selectable")) << "not 'aa copy copy'";
    gui.tap("ctrl+q");
    try {
        gui.click(gui.control("Discard changes", "button"));
    } catch (const std::runtime_error&) {
        // the editor quit before the click's last frame
    }
    EXPECT_TRUE(gui.waitForExit(10.0));
    EXPECT_EQ(gui.exitStatus(), "exit code 0");
}

nlohmann::json say(const GuiDriver& gui) {
    return gui.document()["say"];
}

bool labelled(const GuiDriver& gui, const std::string& part) {
    for (const auto& label : gui.document()["view_labels"])
        if (label.get<std::string>().find(part) != std::string::npos) return true;
    return false;
}

// After Say, another document (the sample again, then a viseme set built from the face) shows no
// clip, timeline or title of the old sentence.
TEST(HabitsClicks, NewDocumentDropsTheOldSpeech) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction", "--say", "Hello there."});
    for (int i = 0; i < 60 && !say(gui).contains("clip"); ++i) gui.waitIdle();
    ASSERT_TRUE(say(gui).contains("clip")) << say(gui).dump();
    EXPECT_TRUE(labelled(gui, "Full set"));
    gui.tap("ctrl+l"); // the Say text is an unsaved edit: the prompt asks first
    gui.waitFrames(3);
    gui.click(gui.control("Discard changes", "button"));
    gui.waitIdle();
    EXPECT_FALSE(say(gui).contains("clip")) << say(gui).dump();
    EXPECT_FALSE(say(gui)["shown"].get<bool>());
    EXPECT_FALSE(labelled(gui, "Full set")) << gui.document()["view_labels"].dump();
    EXPECT_FALSE(labelled(gui, "Cannot play")) << gui.document()["view_labels"].dump();
    EXPECT_TRUE(labelled(gui, "Original ")) << gui.document()["view_labels"].dump();
    EXPECT_EQ(say(gui)["draft"], "");

    // Say again, then build the viseme set from the face: the clip goes with the old set.
    gui.click(gui.revealAtEnd("##say text", "text"));
    gui.type("Good morning.");
    gui.click(gui.revealAtEnd("Say", "button"));
    for (int i = 0; i < 60 && !say(gui).contains("clip"); ++i) gui.waitIdle();
    ASSERT_TRUE(say(gui).contains("clip")) << say(gui).dump();
    gui.click(gui.control("Deform", "tab"));
    gui.waitIdle();
    gui.click(gui.reveal("Generate viseme set from face", "button"));
    gui.waitFrames(3);
    gui.click(gui.control("Discard changes", "button")); // the prompt: the set is replaced
    gui.waitIdle();
    EXPECT_EQ(gui.document()["undo"], "Generate visemes from face");
    gui.click(gui.control("Reduce", "tab"));
    gui.waitIdle();
    EXPECT_FALSE(say(gui).contains("clip")) << say(gui).dump();
    EXPECT_FALSE(labelled(gui, "Full set")) << gui.document()["view_labels"].dump();
    EXPECT_ALIVE(gui);
}

// Ticking Automatic starts a refinement whose progress and report used to push the parameter
// sliders down mid-drag: the slider stays where it was and the drag moves jaw_open only.
TEST(HabitsClicks, AutomaticMovesNoSliderUnderTheCursor) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    const auto jaw = gui.reveal("jaw_open", "slider");
    const auto weights = gui.document()["face_view"]["weights"];
    const auto automatic =
        gui.control("Automatic: re-adapt after every slider or threshold change", "checkbox");
    gui.click(automatic);
    gui.waitFrames(2);
    EXPECT_EQ(gui.control("jaw_open", "slider")["y"], jaw["y"]) << "while the refinement runs";
    const double x = jaw["x"].get<double>(), y = jaw["y"].get<double>() + 0.5 * jaw["height"].get<double>();
    const double w = jaw["width"].get<double>();
    gui.drag(x + 0.05 * w, y, x + 0.7 * w, y, 10);
    gui.waitIdle();
    EXPECT_EQ(gui.control("jaw_open", "slider")["y"], jaw["y"]) << "after the refinement's report";
    const auto now = gui.document()["face_view"]["weights"];
    EXPECT_GT(now["jaw_open"].get<double>(), weights["jaw_open"].get<double>() + 0.3) << now.dump();
    EXPECT_EQ(now["lip_pucker"], weights["lip_pucker"]) << "the drag moved another slider";
    EXPECT_EQ(gui.document()["undo"].get<std::string>().find("jaw_open") != std::string::npos, true)
        << gui.document()["undo"];
    EXPECT_ALIVE(gui);
}

// A forced content scale of 2 (Xvfb reports 1): twice the font, twice the controls; the font has
// the phoneme symbols (ŋ, θ ...).
TEST(HabitsClicks, ContentScaleScalesFontAndControls) {
    REQUIRE_GUI_TOOLS();
    double heights[2] = {};
    for (int i = 0; i < 2; ++i) {
        if (i == 1) ::setenv("VISEMELAB_UI_SCALE", "2", 1);
        GuiDriver gui({"--sample", "--panel", "Visemes"});
        ::unsetenv("VISEMELAB_UI_SCALE");
        gui.waitIdle();
        EXPECT_TRUE(gui.document()["font_has_ipa"].get<bool>());
        EXPECT_NEAR(gui.document()["font_size"].get<double>(), 15.0 * (i + 1), 0.5);
        heights[i] = gui.control("Duplicate", "button")["height"].get<double>();
    }
    EXPECT_NEAR(heights[1], 2.0 * heights[0], 2.0);
}

} // namespace
} // namespace vl::test
