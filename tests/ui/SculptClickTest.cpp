// Sculpting with real clicks (issue 32): the Sculpt checkbox on, a grab stroke on the selected viseme
// moves it by the expected amount (the drag, in model units, times the brush's strength at the
// grabbed point), Ctrl+Z takes the stroke back whole, and the camera stays where it was.
// Skips with a message when Xvfb or xdotool is not installed.
#include "GuiDriver.h"
#include "core/common/AtomicFile.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace vl::test {
namespace {

// Turns Sculpt on with a real click and pulls the middle of the face up by `pixels` (a grab stroke).
// Returns the model units per pixel at the grabbed point, 0 when the brush found no surface.
double grabUp(GuiDriver& gui, double pixels) {
    gui.click(gui.control("Sculpt", "checkbox"));
    gui.waitFrames();
    EXPECT_TRUE(gui.document()["sculpt"]["enabled"].get<bool>());
    const auto view = gui.control("main", "view");
    const double x = view["x"].get<double>() + 0.5 * view["width"].get<double>();
    const double y = view["y"].get<double>() + 0.55 * view["height"].get<double>();
    gui.hover(x, y);
    gui.waitFrames();
    const double unitsPerPixel = gui.document()["sculpt"]["units_per_pixel"].get<double>();
    if (unitsPerPixel <= 0.0) return 0.0;
    gui.drag(x, y, x, y - pixels, 12);
    gui.waitIdle();
    return unitsPerPixel;
}

TEST(SculptClicks, AGrabStrokeMovesTheVisemeAndUndoesAsOneStep) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes", "--viseme", "aa"});
    gui.waitIdle();
    const double before = gui.document()["sculpt"]["shape_y_sum"].get<double>();
    const nlohmann::json camera = gui.document()["camera"];
    const double unitsPerPixel = grabUp(gui, 60); // pull the middle of the face up, 60 pixels
    ASSERT_GT(unitsPerPixel, 0.0);
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["undo"], "Sculpt aa (grab)") << gui.document()["messages"].dump();
    const auto& sculpt = gui.document()["sculpt"];
    EXPECT_GT(sculpt["stroke_dabs"].get<int>(), 0);
    // The grabbed vertex alone rises by the pull (60 px) times the strength (0.5) at the centre; its
    // neighbours in reach add their share. (The view looks along -z with y up, and the pull is in the
    // plane facing the camera.)
    const double raised = sculpt["shape_y_sum"].get<double>() - before;
    EXPECT_GT(raised, 0.5 * 60.0 * unitsPerPixel * 0.9) << sculpt.dump();
    EXPECT_EQ(gui.document()["camera"], camera); // the drag sculpted, it did not orbit
    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_NEAR(gui.document()["sculpt"]["shape_y_sum"].get<double>(), before, 1e-6);
    EXPECT_NE(gui.document()["undo"], "Sculpt aa (grab)");
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

// The same stroke on an avatar's viseme (a Ready Player Me-like file: skinned head under a 0.01-scaled
// armature): the avatar's target moves and undoes; the export writing it back is tested in core
// (tests/document/AvatarSculptTest.cpp).
TEST(SculptClicks, AGrabStrokeOnAnAvatarVisemeMovesItsTarget) {
    REQUIRE_GUI_TOOLS();
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-sculpt-avatar-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    writeFileAtomically(dir / "rpm.glb", rpmLikeAvatar());
    GuiDriver gui({"--avatar", (dir / "rpm.glb").string(), "--panel", "Visemes", "--viseme", "viseme_aa"});
    gui.waitIdle();
    const double before = gui.document()["sculpt"]["shape_y_sum"].get<double>();
    const double unitsPerPixel = grabUp(gui, 40);
    ASSERT_GT(unitsPerPixel, 0.0);
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["undo"], "Sculpt viseme_aa (grab)") << gui.document()["messages"].dump();
    EXPECT_GT(gui.document()["sculpt"]["shape_y_sum"].get<double>() - before,
              0.5 * 40.0 * unitsPerPixel * 0.9)
        << gui.document()["sculpt"].dump();
    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_NEAR(gui.document()["sculpt"]["shape_y_sum"].get<double>(), before, 1e-9);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl::test
