// A large viseme set in the Reduction panel, driven by real clicks: branch and bound shows the bar of
// its proven bound, and Cancel stops it and keeps the best grouping found with its gap (issue 10).
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace vl::test {
namespace {

// A neutral grid and `count` visemes, each a random bump field over it: far from any clustering a
// search proves within seconds, so the search is still running when the test clicks.
std::filesystem::path writeRandomVisemeFolder(int count) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-large-set-" + std::to_string(getpid()));
    std::mt19937 random(20261126);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<std::string> names;
    for (int v = 1; v <= count; ++v) names.push_back("v" + std::to_string(v));
    writeGridVisemeFolder(dir, names, 8, [&](int, int, int) { return 0.3 * normal(random); });
    return dir;
}

TEST(ReductionClicks, LargeSetShowsTheBoundAndCancelKeepsTheBestFound) {
    REQUIRE_GUI_TOOLS();
    const auto dir = writeRandomVisemeFolder(34);
    GuiDriver gui({"--visemes", dir.string(), "--panel", "Reduction"});
    gui.waitFrames();
    // The neutral is not a viseme.
    ASSERT_EQ(gui.document()["visemes"].get<int>(), 34) << gui.document().dump();

    // The searches run (10 s at most in the editor): wait until the bound of the target is shown.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(8);
    while (!gui.document()["reduction"].contains("bound") && std::chrono::steady_clock::now() < deadline)
        gui.waitFrames(1);
    const auto& reduction = gui.document()["reduction"];
    ASSERT_TRUE(reduction["running"].get<bool>()) << "finished before the test could cancel: " << reduction;
    ASSERT_TRUE(reduction.contains("bound")) << reduction;
    const double lower = reduction["bound"]["lower"], best = reduction["bound"]["best"];
    EXPECT_GE(lower, 0.0);
    EXPECT_LE(lower, best);
    EXPECT_EQ(reduction["bound"]["groups"], gui.document()["target"]);

    gui.click(gui.control("Cancel", "button"));
    EXPECT_ALIVE(gui);
    const auto stopped = std::chrono::steady_clock::now();
    gui.waitIdle(30.0);
    // Stopped at the click, not at the 10 s limit; the grouping found is kept with its proof.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count(), 5.0);
    const auto& after = gui.document()["reduction"];
    EXPECT_FALSE(after["running"].get<bool>());
    ASSERT_TRUE(after.contains("current")) << after;
    const double gap = after["current"]["gap"];
    EXPECT_GE(gap, 0.0);
    EXPECT_LE(gap, 1.0);
    if (!after["current"]["optimal"].get<bool>()) {
        EXPECT_GT(gap, 0.0);
    }
    for (const auto& message : gui.document()["messages"])
        EXPECT_FALSE(message["error"].get<bool>()) << message;
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl::test
