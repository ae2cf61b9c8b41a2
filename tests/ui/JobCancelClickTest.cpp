// Cancel with real clicks (issue 32): refining for all visemes (seconds of work) is stopped from the
// Refinement panel and from the status bar; the editor is idle within a second and the face keeps
// the mesh it had. Skips with a message when Xvfb or xdotool is not installed.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <chrono>

namespace vl::test {
namespace {

using Clock = std::chrono::steady_clock;

// Starts "For all visemes" and waits (20 s at most) for the Cancel button `cancel`: the run reports
// progress, its bar shows the percentage.
nlohmann::json startRefiningForAllVisemes(GuiDriver& gui, const std::string& cancel) {
    gui.click(gui.control("For all visemes", "button"));
    const auto deadline = Clock::now() + std::chrono::seconds(20);
    while (Clock::now() < deadline) {
        gui.waitFrames(1);
        if (const auto button = gui.find(cancel, "button")) return *button;
    }
    ADD_FAILURE() << "no " << cancel << " button while refining: " << gui.document().dump();
    return gui.control(cancel, "button");
}

TEST(JobCancelClicks, CancelStopsRefiningForAllVisemesWithinASecondAndTheFaceKeepsItsMesh) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    // The finest contour-error thresholds: refining for all 15 visemes then takes seconds.
    gui.click(gui.control("contour error", "radio"));
    gui.click(gui.control("max depth", "slider"), 0.98);
    gui.click(gui.control("maximum error", "slider"), 0.02);
    gui.click(gui.control("average error", "slider"), 0.02);
    gui.waitIdle();
    const auto revision = documentRevision(gui);
    const std::string undo = gui.document()["undo"];
    // The panel's Cancel, then the status bar's (job 1: the refinement).
    for (const char* cancel : {"Cancel##refinement", "Cancel##job1"}) {
        const nlohmann::json button = startRefiningForAllVisemes(gui, cancel);
        ASSERT_EQ(gui.document()["jobs"].size(), 1u) << gui.document().dump();
        const auto clicked = Clock::now();
        gui.click(button);
        gui.waitIdle(5.0);
        EXPECT_LT(std::chrono::duration<double>(Clock::now() - clicked).count(), 1.0) << cancel;
        EXPECT_ALIVE(gui);
        EXPECT_TRUE(gui.document()["jobs"].empty()) << cancel;
        EXPECT_FALSE(gui.document()["busy"].get<bool>()) << cancel;
        EXPECT_EQ(documentRevision(gui), revision) << cancel;
        EXPECT_EQ(gui.document()["undo"], undo) << cancel;
        EXPECT_NE(lastMessage(gui).find("Refinement cancelled"), std::string::npos) << lastMessage(gui);
    }
    // The next run is not disturbed by the cancelled ones.
    gui.click(gui.control("Refine", "button"));
    gui.waitIdle(120.0);
    EXPECT_ALIVE(gui);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

} // namespace
} // namespace vl::test
