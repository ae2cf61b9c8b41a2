// The paint tools with real clicks (xdotool on a private Xvfb, see GuiDriver.h): the brush radius
// in screen pixels or % of the head, the weight readout under the cursor, a stroke that stays on
// the faces seen, the region fill, the box selection and its fill, and the camera each view keeps
// across tabs. Every step asserts what the editor's probe summary says about the document.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace vl::test {
namespace {

const nlohmann::json& paint(const GuiDriver& gui) {
    return gui.document()["paint"];
}

struct Point {
    double x, y;
};

Point viewCentre(const GuiDriver& gui) {
    const auto view = gui.control("main", "view");
    return {view["x"].get<double>() + 0.5 * view["width"].get<double>(),
            view["y"].get<double>() + 0.5 * view["height"].get<double>()};
}

// Sets the fill value slider low (about 0.1; all zero is refused: the metric needs some weight) and
// fills every vertex with it; returns the value.
double paintEverythingLow(GuiDriver& gui) {
    const auto slider = gui.control("fill value", "slider");
    const double y = slider["y"].get<double>() + 0.5 * slider["height"].get<double>();
    gui.drag(slider["x"].get<double>() + 0.5 * slider["width"].get<double>(), y,
             slider["x"].get<double>() + 0.1 * slider["width"].get<double>(), y, 6);
    const double value = paint(gui)["fill_value"].get<double>();
    EXPECT_GT(value, 0.0);
    EXPECT_LT(value, 0.3);
    gui.click(gui.control("Fill all", "button"));
    gui.waitFrames();
    EXPECT_EQ(gui.document()["undo"], "Fill all") << gui.document().dump();
    EXPECT_EQ(gui.document()["weight_mode"], "painted");
    EXPECT_NEAR(gui.document()["painted_mean"].get<double>(), value, 1e-6);
    return value;
}

TEST(PaintClicks, RadiusUnitsReadoutAndAStrokeThatStaysOnTheFrontFaces) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    EXPECT_EQ(paint(gui)["radius_unit"], "px");
    EXPECT_TRUE(paint(gui)["front_faces_only"].get<bool>());

    // The readout: pointing at the mesh shows the weight there (uniform weights: the largest, 1).
    const Point c = viewCentre(gui);
    gui.hover(c.x + 1, c.y + 1);
    ASSERT_FALSE(paint(gui)["readout"].is_null()) << gui.document().dump();
    EXPECT_GT(paint(gui)["readout"].get<double>(), 0.0) << "the sample's area weights are positive";
    const double pixelsRadius = paint(gui)["radius_model"].get<double>();
    EXPECT_GT(pixelsRadius, 0.0);

    // % of the head: the unit switches, keeping the brush's size on the face.
    gui.click(gui.control("% of head size", "radio"));
    gui.hover(c.x, c.y);
    EXPECT_EQ(paint(gui)["radius_unit"], "% of head");
    EXPECT_NEAR(paint(gui)["radius_model"].get<double>(), pixelsRadius, 0.05 * pixelsRadius);
    // The slider to its right end: 50 % of the head.
    const auto radius = gui.control("radius", "slider");
    const double ry = radius["y"].get<double>() + 0.5 * radius["height"].get<double>();
    gui.drag(radius["x"].get<double>() + 0.5 * radius["width"].get<double>(), ry,
             radius["x"].get<double>() + radius["width"].get<double>() - 1.0, ry, 6);
    EXPECT_NEAR(paint(gui)["radius_value"].get<double>(), 50.0, 1e-9);

    // A big add stroke over the face from low uniform weights: the faces seen gain weight, the back
    // of the head (facing away from the camera) keeps its weight.
    const double low = paintEverythingLow(gui);
    gui.click(gui.control("brush", "radio"));
    ASSERT_TRUE(gui.document()["brush"].get<bool>());
    const auto before = documentRevision(gui);
    gui.drag(c.x - 40, c.y, c.x + 40, c.y + 10, 10);
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentRevision(gui), before);
    EXPECT_EQ(gui.document()["undo"], "Paint stroke") << gui.document().dump();
    EXPECT_GT(paint(gui)["front_mean"].get<double>(), low + 0.01);
    EXPECT_NEAR(paint(gui)["back_mean"].get<double>(), low, 1e-6) << "paint went through to the back";
    // The readout follows what was painted (the stroke's centre is above the fill).
    gui.hover(c.x, c.y + 5);
    ASSERT_FALSE(paint(gui)["readout"].is_null());
    EXPECT_GT(paint(gui)["readout"].get<double>(), low + 0.01);
}

TEST(PaintClicks, RegionFillAndBoxSelectionFill) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    const double low = paintEverythingLow(gui);
    // Fill value to its right end (1), then the region fill: a click on the mesh sets the connected
    // region of equal weight, i.e. the whole connected part under the cursor.
    const auto slider = gui.control("fill value", "slider");
    const double y = slider["y"].get<double>() + 0.5 * slider["height"].get<double>();
    gui.drag(slider["x"].get<double>() + 0.5 * slider["width"].get<double>(), y,
             slider["x"].get<double>() + slider["width"].get<double>() - 1.0, y, 6);
    gui.click(gui.control("fill region", "radio"));
    EXPECT_EQ(paint(gui)["tool"], "fill");
    const Point c = viewCentre(gui);
    gui.clickAt(c.x, c.y);
    gui.waitFrames();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["undo"], "Fill region") << gui.document()["messages"].dump();
    const double regionMean = gui.document()["painted_mean"].get<double>();
    EXPECT_GT(regionMean, low + 0.01);
    gui.key("ctrl+z");
    EXPECT_NEAR(gui.document()["painted_mean"].get<double>(), low, 1e-6);

    // Box selection: a drag over the middle of the face selects the front-facing vertices in it;
    // Fill selection sets them (one undo step) and nothing else.
    gui.click(gui.control("select box", "radio"));
    EXPECT_EQ(paint(gui)["tool"], "select");
    const auto before = documentRevision(gui);
    gui.drag(c.x - 50, c.y - 50, c.x + 50, c.y + 50, 8);
    gui.waitFrames();
    EXPECT_EQ(documentRevision(gui), before) << "selecting is not an edit";
    const int selected = paint(gui)["selected"].get<int>();
    EXPECT_GT(selected, 0);
    EXPECT_LT(selected, paint(gui)["vertices"].get<int>());
    gui.click(gui.control("Fill selection", "button"));
    gui.waitFrames();
    EXPECT_EQ(gui.document()["undo"], "Fill selection");
    const double boxMean = gui.document()["painted_mean"].get<double>();
    const double share = static_cast<double>(selected) / paint(gui)["vertices"].get<double>();
    EXPECT_NEAR(boxMean, low + share * (1.0 - low), 1e-6);
    EXPECT_NEAR(paint(gui)["back_mean"].get<double>(), low, 1e-6);
    // Invert, then Clear.
    gui.click(gui.control("Invert", "button"));
    EXPECT_EQ(paint(gui)["selected"].get<int>(), paint(gui)["vertices"].get<int>() - selected);
    gui.click(gui.control("Clear", "button"));
    EXPECT_EQ(paint(gui)["selected"].get<int>(), 0);
    EXPECT_ALIVE(gui);
}

// Box selection respects occlusion like the brush: seen from the side, a box over the whole face
// takes the near cheek, the nose and the lips but no vertex hidden behind them, although many of
// those face the camera (the far cheek beside the nose, the far corner of the mouth). The probe
// counts the selected vertices a picking ray from the camera does not reach first.
TEST(PaintClicks, BoxSelectionTakesOnlyWhatIsSeen) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    const Point c = viewCentre(gui);
    // A left drag with the brush off orbits: turn the head about 60 degrees to a three-quarter view.
    gui.drag(c.x, c.y, c.x + 170, c.y, 10);
    gui.waitFrames();
    const double yaw = gui.document()["camera"]["yaw"].get<double>();
    ASSERT_GT(std::abs(yaw), 0.6) << gui.document()["camera"].dump();
    gui.click(gui.control("select box", "radio"));
    ASSERT_EQ(paint(gui)["tool"], "select");
    const auto view = gui.control("main", "view");
    const double x0 = view["x"].get<double>() + 4, y0 = view["y"].get<double>() + 4;
    const double x1 = x0 + view["width"].get<double>() - 8, y1 = y0 + view["height"].get<double>() - 8;
    auto boxEverything = [&] {
        gui.drag(x0, y0, x1, y1, 8);
        gui.waitFrames();
        EXPECT_TRUE(gui.alive()) << "editor " << gui.exitStatus() << ":\n" << gui.log();
        return paint(gui)["selected"].get<int>();
    };
    ASSERT_TRUE(paint(gui)["front_faces_only"].get<bool>());
    const int seen = boxEverything();
    EXPECT_GT(seen, paint(gui)["vertices"].get<int>() / 5) << "the visible side of the face";
    EXPECT_EQ(paint(gui)["selected_hidden"].get<int>(), 0) << "hidden vertices were selected";
    // Without "front faces only" the box takes everything inside it, hidden or not.
    gui.click(gui.control("Front faces only (nothing through to the back)", "checkbox"));
    ASSERT_FALSE(paint(gui)["front_faces_only"].get<bool>());
    const int everything = boxEverything();
    EXPECT_GT(everything, seen);
    EXPECT_GT(paint(gui)["selected_hidden"].get<int>(), 0);
    EXPECT_GE(everything - seen, paint(gui)["selected_hidden"].get<int>())
        << "front faces only leaves out every hidden vertex (and those facing away)";
}

// The camera of each view survives tab switches: orbit and zoom the visemes, visit the face tabs
// and come back; the face view keeps its own camera too.
TEST(PaintClicks, TheViewIsKeptWhenSwitchingTabs) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Weights"});
    gui.waitIdle();
    const Point c = viewCentre(gui);
    const nlohmann::json framed = gui.document()["camera"];
    gui.drag(c.x, c.y, c.x + 120, c.y + 30, 8); // brush off: a left drag orbits
    gui.scroll(c.x, c.y, -3);
    gui.waitFrames();
    const nlohmann::json moved = gui.document()["camera"];
    ASSERT_NE(moved, framed) << "the drag and the wheel did not move the camera";
    for (const char* tab : {"Freq.", "Reduce", "Visemes"}) {
        gui.click(gui.control(tab, "tab"));
        gui.waitFrames();
        EXPECT_EQ(gui.document()["camera"], moved) << "after the " << tab << " tab";
    }
    gui.click(gui.control("Refine", "tab"));
    gui.waitIdle();
    const Point f = viewCentre(gui);
    gui.scroll(f.x, f.y, 2);
    gui.waitFrames();
    const nlohmann::json face = gui.document()["camera"];
    EXPECT_NE(face, moved);
    gui.click(gui.control("Weights", "tab"));
    gui.waitFrames();
    EXPECT_EQ(gui.document()["camera"], moved);
    gui.click(gui.control("Refine", "tab"));
    gui.waitFrames();
    EXPECT_EQ(gui.document()["camera"], face);
    EXPECT_ALIVE(gui);
}

} // namespace
} // namespace vl::test
