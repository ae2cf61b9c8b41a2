// Deformation > Use my mesh... with real clicks (xdotool on a private Xvfb): the file dialog, the
// landmark step (a landmark dragged to a new (u,v) becomes "placed by you" while the document stays
// untouched), the build as one undo step, Cancel leaving the document alone. Uses the MediaPipe
// canonical face from VISEMELAB_SHARED_DATA_DIR (skipped loudly when absent).
#include "GuiDriver.h"

#include <gtest/gtest.h>

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
    const auto documentBefore = gui.document()["document_id"];

    // Cancel: the step goes away, the document is what it was.
    chooseFile(gui, kMediaPipe);
    ASSERT_TRUE(gui.document()["own_face_step"].is_object()) << messagesOf(gui);
    gui.click(gui.control("Cancel##ownface", "button"));
    gui.waitFrames();
    EXPECT_TRUE(gui.document()["own_face_step"].is_null());
    EXPECT_EQ(gui.document()["document_id"], documentBefore);

    chooseFile(gui, kMediaPipe);
    auto step = gui.document()["own_face_step"];
    ASSERT_TRUE(step.is_object()) << messagesOf(gui);
    EXPECT_EQ(step["missing"], "");
    EXPECT_EQ(step["landmarks"]["nose_tip"]["source"], "layout");
    const double u0 = step["landmarks"]["nose_tip"]["u"];

    // Drag the nose tip's u to the right: the landmark is now the user's, the document unchanged.
    const auto nose = gui.control("u##nose_tip", "drag");
    const double x = nose["x"].get<double>() + 0.5 * nose["width"].get<double>();
    const double y = nose["y"].get<double>() + 0.5 * nose["height"].get<double>();
    gui.drag(x, y, x + 12, y, 6);
    gui.waitFrames();
    step = gui.document()["own_face_step"];
    EXPECT_EQ(step["landmarks"]["nose_tip"]["source"], "file");
    EXPECT_GT(step["landmarks"]["nose_tip"]["u"].get<double>(), u0);
    EXPECT_EQ(step["landmarks"]["mouth_corner_left"]["source"], "layout");
    EXPECT_EQ(gui.document()["document_id"], documentBefore);

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

} // namespace
} // namespace vl::test
