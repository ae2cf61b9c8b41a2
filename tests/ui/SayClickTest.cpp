// The Reduction panel's Say section driven with real input (xdotool on a private Xvfb): type a
// sentence, click Say, watch the full and the reduced faces play it, pause, scrub the timeline,
// change voice and rate, play a typed sequence. Each step checks the document or the playback the
// editor reports (GuiProbe summary "say"). Skips with a message when Xvfb or xdotool is missing.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace vl::test {
namespace {

const nlohmann::json& say(const GuiDriver& gui) {
    return gui.document()["say"];
}

// The timeline maps time linearly onto its width after the row names (ui/widgets/SpeechTimeline.cpp:
// 92 px of labels on the left, 12 px margin on the right).
double timelineFraction(const nlohmann::json& timeline, double timeFraction) {
    const double width = timeline["width"].get<double>();
    return (92.0 + timeFraction * (width - 104.0)) / width;
}

// Waits until the speech was synthesised and its tracks built (at most 30 s).
void waitForClip(GuiDriver& gui, const std::string& containing) {
    for (int i = 0; i < 60; ++i) {
        gui.waitIdle();
        if (say(gui).contains("clip") &&
            say(gui)["clip"].get<std::string>().find(containing) != std::string::npos)
            return;
        gui.waitFrames(5);
    }
    FAIL() << "no clip with '" << containing << "': " << gui.document().dump();
}

TEST(SayClicks, TypeSayPauseScrubAndPlay) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    EXPECT_FALSE(say(gui).contains("clip"));
    // The slowest rate and two sentences: about 10 s of speech, so it still plays when Pause is
    // clicked on a loaded machine (a GUI step can take seconds there).
    gui.click(gui.revealAtEnd("words/min", "slider"), 0.01);
    gui.waitFrames(2);
    ASSERT_LE(say(gui)["rate"].get<int>(), 90);
    const std::string text = "Hello world. Four poor fire fighters faced the long and windy night!";
    gui.click(gui.revealAtEnd("##say text", "text"));
    gui.type(text);
    gui.waitFrames(2);
    EXPECT_EQ(say(gui)["draft"], text);
    EXPECT_EQ(say(gui)["text"], ""); // the document takes the text on Say
    gui.click(gui.revealAtEnd("Say", "button"));
    EXPECT_ALIVE(gui);
    waitForClip(gui, "Hello world");
    EXPECT_EQ(say(gui)["text"], text);
    EXPECT_EQ(gui.document()["undo"], "Say text");
    EXPECT_TRUE(gui.document()["modified"].get<bool>());
    const double duration = say(gui)["duration"].get<double>();
    EXPECT_GT(duration, 6.0);
    EXPECT_GT(say(gui)["phonemes"].get<int>(), 30);
    EXPECT_TRUE(say(gui)["shown"].get<bool>());
    EXPECT_EQ(say(gui)["problem"], "");
    EXPECT_EQ(say(gui)["groups"], gui.document()["target"]);
    EXPECT_GT(say(gui)["error_max"].get<double>(), 0.0);
    // Audio: a device plays it, or the editor says it has none (Xvfb machines have none).
    const std::string audio = say(gui)["audio"].get<std::string>();
    EXPECT_TRUE(audio.rfind("audio: ", 0) == 0 || audio.find("shown silently") != std::string::npos) << audio;

    // Pause stops the clock.
    gui.click(gui.revealAtEnd("Pause", "button"));
    gui.waitFrames(3);
    EXPECT_FALSE(say(gui)["playing"].get<bool>());
    const double paused = say(gui)["time"].get<double>();
    gui.waitFrames(5);
    EXPECT_EQ(say(gui)["time"].get<double>(), paused);

    // Scrubbing: a click puts the playhead under the mouse; a drag follows it.
    const nlohmann::json timeline = gui.control("##say timeline", "button");
    gui.click(timeline, timelineFraction(timeline, 0.25), 0.5);
    gui.waitFrames(2);
    const double pixel = duration / (timeline["width"].get<double>() - 104.0);
    EXPECT_NEAR(say(gui)["time"].get<double>(), 0.25 * duration, 3 * pixel);
    EXPECT_FALSE(say(gui)["playing"].get<bool>());
    const auto at25 = say(gui);
    ASSERT_TRUE(at25.contains("phoneme") && at25.contains("full_cue") && at25.contains("reduced_cue"));
    const double x = timeline["x"].get<double>(),
                 y = timeline["y"].get<double>() + 0.5 * timeline["height"].get<double>();
    const double width = timeline["width"].get<double>();
    gui.drag(x + timelineFraction(timeline, 0.25) * width, y, x + timelineFraction(timeline, 0.7) * width, y,
             10);
    gui.waitFrames(2);
    EXPECT_NEAR(say(gui)["time"].get<double>(), 0.7 * duration, 3 * pixel);
    // Somewhere along the sentence the face shows other visemes than a quarter in.
    bool changed = false;
    for (const double f : {0.1, 0.4, 0.55, 0.7, 0.85}) {
        gui.click(timeline, timelineFraction(timeline, f), 0.5);
        gui.waitFrames(2);
        changed = changed || say(gui)["full_cue"] != at25["full_cue"];
        EXPECT_GE(say(gui)["error_now"].get<double>(), 0.0);
    }
    EXPECT_TRUE(changed);
    EXPECT_EQ(say(gui)["text"], text); // scrubbing is view state: the document is untouched
    EXPECT_EQ(gui.document()["undo"], "Say text");

    // Play resumes from the playhead and runs to the end (no audio device: on the frame clock).
    gui.click(timeline, timelineFraction(timeline, 0.9), 0.5);
    gui.click(gui.revealAtEnd("Play", "button"));
    gui.waitFrames(3);
    EXPECT_TRUE(say(gui)["playing"].get<bool>() || say(gui)["time"].get<double>() == duration);
    for (int i = 0; i < 100 && say(gui)["playing"].get<bool>(); ++i) gui.waitFrames(3);
    EXPECT_FALSE(say(gui)["playing"].get<bool>());
    EXPECT_DOUBLE_EQ(say(gui)["time"].get<double>(), duration);

    gui.click(gui.revealAtEnd("Hide", "button"));
    gui.waitFrames(2);
    EXPECT_FALSE(say(gui)["shown"].get<bool>());
    EXPECT_ALIVE(gui);
}

TEST(SayClicks, VoiceAndRateAreUndoableAndSpoken) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    gui.click(gui.revealAtEnd("voice", "combo"));
    gui.waitFrames(2);
    gui.click(gui.control("en-gb", "selectable"));
    gui.waitFrames(2);
    EXPECT_EQ(say(gui)["voice"], "en-gb");
    EXPECT_EQ(gui.document()["undo"], "Voice en-gb");
    gui.click(gui.revealAtEnd("words/min", "slider"), 0.9);
    gui.waitFrames(2);
    const int fast = say(gui)["rate"].get<int>();
    EXPECT_GT(fast, 350);
    EXPECT_EQ(gui.document()["undo"].get<std::string>().rfind("Speaking rate", 0), 0u);
    gui.key("ctrl+z");
    gui.waitFrames(3);
    EXPECT_EQ(say(gui)["rate"], 175);
    EXPECT_EQ(say(gui)["voice"], "en-gb");

    gui.click(gui.revealAtEnd("##say text", "text"));
    gui.type("Good morning.");
    gui.click(gui.revealAtEnd("Say", "button"));
    waitForClip(gui, "en-gb, 175 wpm");
    const double british = say(gui)["duration"].get<double>();
    gui.click(gui.revealAtEnd("words/min", "slider"), 0.95);
    gui.click(gui.revealAtEnd("Say", "button"));
    waitForClip(gui, "wpm");
    for (int i = 0; i < 20 && say(gui)["clip"].get<std::string>().find("175 wpm") != std::string::npos; ++i)
        gui.waitFrames(5);
    EXPECT_LT(say(gui)["duration"].get<double>(), british); // faster speech is shorter
    EXPECT_ALIVE(gui);
}

TEST(SayClicks, NothingToSayIsAClearError) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    gui.click(gui.revealAtEnd("Say", "button"));
    gui.waitFrames(3);
    EXPECT_NE(lastMessage(gui).find("type the text to say first"), std::string::npos) << lastMessage(gui);
    EXPECT_FALSE(say(gui).contains("clip"));
    gui.click(gui.revealAtEnd("##say text", "text"));
    gui.type("... , ?"); // punctuation only: espeak-ng speaks no word ("!!" it reads as "exclamation")
    gui.click(gui.revealAtEnd("Say", "button"));
    gui.waitIdle();
    gui.waitFrames(3);
    EXPECT_NE(lastMessage(gui).find("nothing to say"), std::string::npos) << lastMessage(gui);
    EXPECT_FALSE(say(gui).contains("clip"));
    EXPECT_ALIVE(gui);
}

TEST(SayClicks, TypedSequenceAndPlayAllUseTheSamePlayback) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    gui.click(gui.revealAtEnd("Typed sequence", "tree"));
    gui.waitFrames(2);
    gui.click(gui.revealAtEnd("##sequence", "text"));
    gui.type("PP aa E");
    gui.click(gui.revealAtEnd("Play sequence", "button"));
    gui.waitFrames(3);
    EXPECT_NE(say(gui)["clip"].get<std::string>().find("PP aa E"), std::string::npos);
    EXPECT_EQ(say(gui)["phonemes"], 3);
    EXPECT_TRUE(say(gui)["playing"].get<bool>());
    EXPECT_EQ(say(gui)["problem"], "");
    // A sequence loops: its clock wraps instead of stopping.
    const double duration = say(gui)["duration"].get<double>();
    for (int i = 0; i < 30; ++i) gui.waitFrames(3);
    EXPECT_TRUE(say(gui)["playing"].get<bool>());
    EXPECT_LT(say(gui)["time"].get<double>(), duration);

    gui.click(gui.control("Visemes", "tab"));
    gui.waitFrames(2);
    gui.click(gui.control("Play all", "checkbox")); // was off: a sequence is not "all visemes"
    gui.waitFrames(3);
    EXPECT_EQ(say(gui)["clip"], "every viseme");
    EXPECT_EQ(say(gui)["phonemes"], gui.document()["visemes"]);
    EXPECT_TRUE(say(gui)["playing"].get<bool>());
    gui.click(gui.control("Play all", "checkbox"));
    gui.waitFrames(3);
    EXPECT_FALSE(say(gui)["playing"].get<bool>());
    EXPECT_FALSE(say(gui)["shown"].get<bool>());
    EXPECT_ALIVE(gui);
}

// Text and voice are document state: saved in the project's "speech" section and back in the box
// when the project is opened again.
TEST(SayClicks, TextAndVoiceAreSavedWithTheProject) {
    REQUIRE_GUI_TOOLS();
    const auto folder =
        std::filesystem::temp_directory_path() / ("visemelab-say-saved-" + std::to_string(getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const auto target = folder / "spoken.vlproj";
    const std::string text = "The juice of lemons makes fine punch.";
    {
        GuiDriver gui({"--sample", "--panel", "Reduction"});
        gui.waitIdle();
        gui.click(gui.revealAtEnd("voice", "combo"));
        gui.waitFrames(2);
        gui.click(gui.control("en-gb-scotland", "selectable"));
        gui.click(gui.revealAtEnd("##say text", "text"));
        gui.type(text);
        gui.click(gui.revealAtEnd("Say", "button"));
        waitForClip(gui, "juice");
        gui.key("ctrl+s"); // the sample is read-only: Save asks for a file
        ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>());
        gui.click(gui.control("##name", "text"));
        gui.key("ctrl+a");
        gui.type(target.string());
        gui.click(gui.control("Save", "button"));
        gui.waitIdle();
        EXPECT_EQ(gui.document()["project_path"], target.string()) << gui.document()["messages"].dump();
        EXPECT_ALIVE(gui);
    }
    std::ifstream in(target);
    const nlohmann::json saved = nlohmann::json::parse(in);
    EXPECT_EQ(saved["speech"]["text"], text);
    EXPECT_EQ(saved["speech"]["voice"], "en-gb-scotland");
    EXPECT_EQ(saved["speech"]["wordsPerMinute"], 175);

    GuiDriver gui({"--project", target.string(), "--panel", "Reduction"});
    gui.waitIdle();
    EXPECT_EQ(say(gui)["text"], text);
    EXPECT_EQ(say(gui)["draft"], text);
    EXPECT_EQ(say(gui)["voice"], "en-gb-scotland");
    gui.click(gui.revealAtEnd("Say", "button"));
    waitForClip(gui, "en-gb-scotland");
    EXPECT_EQ(say(gui)["problem"], "");
    EXPECT_ALIVE(gui);
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace vl::test
