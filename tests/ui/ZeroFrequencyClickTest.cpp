// Issue 32: a viseme no phoneme maps to (frequency 0 %) is merged for free; the Reduction panel says
// so beside the groups instead of placing it silently. Real clicks: duplicate a viseme of the sample
// (the copy has no phoneme), then open the Reduction panel.
#include "GuiDriver.h"

#include <gtest/gtest.h>

namespace vl::test {
namespace {

TEST(ZeroFrequencyClicks, TheReductionPanelNamesAVisemeOfFrequencyZero) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    EXPECT_FALSE(gui.find("Frequency 0 %: aa copy", "warning").has_value());
    gui.click(gui.control("Visemes", "tab"));
    gui.waitFrames();
    gui.click(gui.control("aa", "selectable"));
    gui.waitFrames();
    gui.click(gui.control("Duplicate", "button"));
    gui.waitIdle();
    ASSERT_EQ(gui.document()["undo"], "Duplicate aa as aa copy") << gui.document()["messages"].dump();
    gui.click(gui.control("Reduce", "tab"));
    gui.waitIdle(60.0);
    gui.waitFrames();
    EXPECT_TRUE(gui.find("Frequency 0 %: aa copy", "warning").has_value()) << gui.report().dump();
    EXPECT_ALIVE(gui);
}

} // namespace
} // namespace vl::test
