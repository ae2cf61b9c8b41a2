// Deformation > Use my mesh... with real clicks (xdotool on a private Xvfb): the file dialog, the
// landmark step (a landmark dragged to a new (u,v) becomes "placed by you" while the document stays
// untouched), the build as one undo step, Cancel leaving the document alone. Uses the MediaPipe
// canonical face from VISEMELAB_SHARED_DATA_DIR (skipped loudly when absent).
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace vl::test {
namespace {

const std::filesystem::path kMediaPipe = std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) /
                                         "mediapipe-canonical-face" / "canonical_face_model.obj";

void chooseFile(GuiDriver& gui, const std::filesystem::path& file) {
    gui.click(gui.control("Use my mesh...", "button"));
    gui.chooseFile(file);
}

std::string messagesOf(const GuiDriver& gui) {
    return gui.document()["messages"].dump();
}

TEST(OwnFaceClicks, UseMyMeshConfirmsLandmarksThenBuildsTheFace) {
    REQUIRE_GUI_TOOLS();
    if (!std::filesystem::exists(kMediaPipe))
        GTEST_SKIP() << "shared data missing: " << kMediaPipe << " (set VISEMELAB_SHARED_DATA_DIR)";
    GuiDriver gui({"--panel", "Deformation"});
    gui.waitIdle();
    const std::string bundledName = gui.document()["face_name"];
    ASSERT_FALSE(bundledName.empty()) << gui.document().dump();
    const auto documentBefore = gui.document()["document_revision"];

    // Cancel: the step goes away (an undo step of its own, as opening it was), the face is what it was.
    chooseFile(gui, kMediaPipe);
    ASSERT_TRUE(gui.document()["own_face_step"].is_object()) << messagesOf(gui);
    EXPECT_EQ(gui.document()["undo"], "Open canonical_face_model for its landmarks");
    gui.click(gui.control("Cancel##ownface", "button"));
    gui.waitFrames();
    EXPECT_TRUE(gui.document()["own_face_step"].is_null());
    EXPECT_EQ(gui.document()["undo"], "Cancel Use my mesh");
    EXPECT_EQ(gui.document()["face_name"], bundledName);
    EXPECT_NE(gui.document()["document_revision"], documentBefore);

    chooseFile(gui, kMediaPipe);
    auto step = gui.document()["own_face_step"];
    ASSERT_TRUE(step.is_object()) << messagesOf(gui);
    EXPECT_EQ(step["missing"], "");
    EXPECT_EQ(step["landmarks"]["nose_tip"]["source"], "layout");
    const double u0 = step["landmarks"]["nose_tip"]["u"];

    // Drag the nose tip's u to the right: the landmark is now the user's (one undo step), the face
    // unchanged.
    const auto nose = gui.control("u##nose_tip", "drag");
    const double x = nose["x"].get<double>() + 0.5 * nose["width"].get<double>();
    const double y = nose["y"].get<double>() + 0.5 * nose["height"].get<double>();
    gui.drag(x, y, x + 12, y, 6);
    gui.waitFrames();
    step = gui.document()["own_face_step"];
    EXPECT_EQ(step["landmarks"]["nose_tip"]["source"], "file");
    EXPECT_GT(step["landmarks"]["nose_tip"]["u"].get<double>(), u0);
    EXPECT_EQ(step["landmarks"]["mouth_corner_left"]["source"], "layout");
    EXPECT_EQ(gui.document()["undo"], "Move landmark nose_tip");
    EXPECT_EQ(gui.document()["face_name"], bundledName);

    gui.click(gui.control("Build face from these landmarks", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_TRUE(gui.document()["own_face_step"].is_null());
    EXPECT_EQ(gui.document()["face_name"], "canonical_face_model") << messagesOf(gui);
    EXPECT_EQ(gui.document()["undo"], "Use my mesh canonical_face_model");
    EXPECT_NE(messagesOf(gui).find("Face 'canonical_face_model' built"), std::string::npos)
        << messagesOf(gui);
    EXPECT_TRUE(gui.find("Back to the bundled face", "button").has_value());

    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_EQ(gui.document()["face_name"], bundledName);
    gui.key("ctrl+y");
    gui.waitIdle();
    EXPECT_EQ(gui.document()["face_name"], "canonical_face_model");

    gui.click(gui.control("Back to the bundled face", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["face_name"], bundledName);
    EXPECT_ALIVE(gui);
}

// The landmarks drawn on the mesh in the view: the nose tip's dot dragged over the surface with the
// mouse moves the landmark (snapped to the mesh: a new (u,v) of it, placed by the user) as one undo
// step, the camera does not orbit meanwhile, and Ctrl+Z puts it back. On the bundled sample's neutral
// (always there).
TEST(OwnFaceClicks, ALandmarkDotDraggedInTheViewMovesTheLandmarkAsOneStep) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path sample =
        std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "neutral.obj";
    GuiDriver gui({"--panel", "Deformation"});
    gui.waitIdle();
    chooseFile(gui, sample);
    gui.waitFrames(4); // the view frames the mesh
    const auto step = gui.document()["own_face_step"];
    ASSERT_TRUE(step.is_object()) << messagesOf(gui);
    const auto dot = gui.control("nose_tip", "landmark");
    const double x = dot["x"].get<double>() + 0.5 * dot["width"].get<double>();
    const double y = dot["y"].get<double>() + 0.5 * dot["height"].get<double>();
    const double u0 = step["landmarks"]["nose_tip"]["u"], v0 = step["landmarks"]["nose_tip"]["v"];
    const std::string source0 = step["landmarks"]["nose_tip"]["source"];
    const auto camera = gui.document()["camera"];

    // Hovering lights the dot (its name in a tooltip).
    gui.hover(x, y);
    EXPECT_EQ(gui.document()["landmark_handles"]["hovered"], "nose_tip")
        << gui.document()["landmark_handles"].dump();

    // Down and to the face's right (the viewer's left), onto the cheek.
    const auto before = gui.document()["undo"];
    gui.drag(x, y, x - 45, y + 30, 8);
    gui.waitFrames();
    EXPECT_ALIVE(gui);
    const auto moved = gui.document()["own_face_step"]["landmarks"]["nose_tip"];
    EXPECT_EQ(moved["source"], "file");
    EXPECT_GT(std::hypot(moved["u"].get<double>() - u0, moved["v"].get<double>() - v0), 0.01) << moved.dump();
    EXPECT_EQ(gui.document()["undo"], "Move landmark nose_tip");
    EXPECT_EQ(gui.document()["camera"]["yaw"], camera["yaw"]);
    EXPECT_EQ(gui.document()["camera"]["pitch"], camera["pitch"]);
    // The dot is drawn where the cursor let go, on the surface.
    const auto after = gui.control("nose_tip", "landmark");
    EXPECT_NEAR(after["x"].get<double>() + 0.5 * after["width"].get<double>(), x - 45, 3.0);
    EXPECT_NEAR(after["y"].get<double>() + 0.5 * after["height"].get<double>(), y + 30, 3.0);

    // One undo step: Ctrl+Z restores the landmark as it was.
    gui.key("ctrl+z");
    gui.waitFrames();
    const auto restored = gui.document()["own_face_step"]["landmarks"]["nose_tip"];
    EXPECT_EQ(restored["source"], source0);
    EXPECT_DOUBLE_EQ(restored["u"].get<double>(), u0);
    EXPECT_DOUBLE_EQ(restored["v"].get<double>(), v0);
    EXPECT_EQ(gui.document()["undo"], before);
}

// A viseme set the face generated shows the head's teeth, tongue and cavity in the Visemes view as
// the Deformation view does (it showed a hole for a mouth): posed with the selected viseme's
// parameters ("aa" opens the jaw).
TEST(OwnFaceClicks, AFaceVisemeSetShowsTheTeethInTheVisemeView) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--panel", "Deformation"});
    gui.waitIdle();
    gui.click(gui.reveal("Generate viseme set from face", "button"));
    gui.waitFrames(3);
    if (gui.find("Discard changes", "button")) gui.click(gui.control("Discard changes", "button"));
    gui.waitIdle();
    ASSERT_EQ(gui.document()["undo"], "Generate visemes from face");
    gui.click(gui.control("Visemes", "tab"));
    gui.waitIdle();
    gui.click(gui.reveal("aa", "selectable"));
    gui.waitFrames(3);
    const auto parts = gui.document()["viseme_view_parts"];
    EXPECT_GT(parts["triangles"].get<int>(), 100) << parts.dump();
    // The parts' weights are the face's parameters of "aa": its jaw is open.
    const auto q = parts["q"];
    ASSERT_FALSE(q.empty());
    double largest = 0.0;
    for (const auto& value : q) largest = std::max(largest, value.get<double>());
    EXPECT_GT(largest, 0.2) << q.dump();
    gui.screenshot("viseme-aa-teeth");
    EXPECT_ALIVE(gui);
}

} // namespace
} // namespace vl::test
