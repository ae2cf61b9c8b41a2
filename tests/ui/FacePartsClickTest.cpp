// The head's parts in the face views with real clicks (xdotool on a private Xvfb, see GuiDriver.h):
// the Refine tab's view draws the eyeballs, teeth, tongue and mouth cavity beside the refined skin,
// jaw_open dragged to its end lowers the lower teeth and the tongue where the view draws them (the
// probe's "face_view": each part's centre at the drawn weights) and leaves the upper teeth, a
// refinement keeps them, the idle view is not rendered again; a face built from the user's mesh
// (Deformation > Use my mesh..., the MediaPipe canonical face from VISEMELAB_SHARED_DATA_DIR, skipped
// loudly when absent) shows the parts carried to it.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vl::test {
namespace {

struct Centre {
    double x = 0, y = 0, z = 0;
};

const nlohmann::json& faceView(const GuiDriver& gui) {
    return gui.document()["face_view"];
}

// Each drawn part's centre, by name.
std::map<std::string, Centre> partCentres(const GuiDriver& gui) {
    std::map<std::string, Centre> out;
    for (const auto& part : faceView(gui)["parts"]) {
        const auto& c = part["centre"];
        out[part["name"].get<std::string>()] = {c[0].get<double>(), c[1].get<double>(), c[2].get<double>()};
    }
    return out;
}

// On the Refine tab with a face: opens the tab and loads the bundled face when it is not there yet.
void openRefineTab(GuiDriver& gui) {
    gui.click(gui.control("Refine", "tab"));
    gui.waitIdle();
    if (const auto load = gui.find("Load bundled face", "button")) {
        gui.click(*load);
        gui.waitIdle();
    }
    ASSERT_EQ(gui.document()["panel"], "Refinement");
    ASSERT_FALSE(gui.document()["face_name"].get<std::string>().empty()) << gui.document().dump();
}

// Drags the jaw_open slider past its right end (its maximum) and checks what the view drew: the
// lower teeth and the tongue went down, the upper teeth stayed with the skull.
void dragJawOpenToItsEnd(GuiDriver& gui) {
    const auto before = partCentres(gui);
    ASSERT_EQ(before.size(), 6u) << faceView(gui).dump();
    const auto renders = faceView(gui)["renders"].get<std::uint64_t>();
    const auto slider = gui.control("jaw_open", "slider");
    const double y = slider["y"].get<double>() + 0.5 * slider["height"].get<double>();
    const double x = slider["x"].get<double>();
    gui.drag(x + 0.3 * slider["width"].get<double>(), y, x + slider["width"].get<double>() + 60.0, y);
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["undo"], "Set jaw_open");
    EXPECT_EQ(faceView(gui)["weights"]["jaw_open"].get<double>(), 1.0) << faceView(gui).dump();
    EXPECT_GT(faceView(gui)["renders"].get<std::uint64_t>(), renders);
    const auto after = partCentres(gui);
    ASSERT_EQ(after.size(), 6u);
    // Relative to the head's size (the eyes' distance): an own face need not be in centimetres.
    const double eyes = std::abs(before.at("eye_left").x - before.at("eye_right").x);
    ASSERT_GT(eyes, 0.0);
    EXPECT_LT(after.at("teeth_lower").y, before.at("teeth_lower").y - 0.05 * eyes);
    EXPECT_LT(after.at("tongue").y, before.at("tongue").y - 0.03 * eyes);
    EXPECT_NEAR(after.at("teeth_upper").y, before.at("teeth_upper").y, 1e-6 * eyes);
    EXPECT_NEAR(after.at("eye_left").y, before.at("eye_left").y, 1e-6 * eyes);
}

TEST(FacePartsClicks, RefineViewDrawsThePartsAndJawOpenMovesThem) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--panel", "Visemes"});
    gui.waitIdle();
    openRefineTab(gui);
    const auto& view = faceView(gui);
    ASSERT_TRUE(view.is_object()) << gui.document().dump();
    EXPECT_EQ(view["panel"], "Refinement");
    EXPECT_GT(view["skin_triangles"].get<int>(), 0);
    EXPECT_GT(view["part_triangles"].get<int>(), 0);
    std::vector<std::string> names;
    for (const auto& part : view["parts"]) names.push_back(part["name"]);
    EXPECT_EQ(names, (std::vector<std::string>{"eye_right", "eye_left", "teeth_upper", "teeth_lower",
                                               "tongue", "mouth_cavity"}));

    dragJawOpenToItsEnd(gui);

    // Idle, the view is not rendered again (its scene's signature, parts included, is unchanged).
    const auto rendersIdle = faceView(gui)["renders"].get<std::uint64_t>();
    gui.waitFrames(20);
    EXPECT_EQ(faceView(gui)["renders"].get<std::uint64_t>(), rendersIdle);

    // A refinement changes the skin, not the parts.
    const int skinBefore = faceView(gui)["skin_triangles"].get<int>();
    const auto partsBefore = partCentres(gui);
    gui.click(gui.control("Refine", "button"));
    gui.waitIdle(120.0);
    EXPECT_ALIVE(gui);
    EXPECT_NE(faceView(gui)["skin_triangles"].get<int>(), skinBefore);
    EXPECT_GT(faceView(gui)["part_triangles"].get<int>(), 0);
    EXPECT_EQ(partCentres(gui).at("teeth_lower").y, partsBefore.at("teeth_lower").y);

    // The Deformation tab's view draws the same parts at the same weights.
    gui.click(gui.control("Deform", "tab"));
    gui.waitIdle();
    EXPECT_EQ(faceView(gui)["panel"], "Deformation");
    EXPECT_GT(faceView(gui)["part_triangles"].get<int>(), 0);
    EXPECT_EQ(partCentres(gui).at("teeth_lower").y, partsBefore.at("teeth_lower").y);
    // Other tabs show the viseme set, not the face.
    gui.click(gui.control("Visemes", "tab"));
    gui.waitIdle();
    EXPECT_TRUE(faceView(gui).is_null());
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

TEST(FacePartsClicks, AFaceFromTheUsersMeshShowsTheCarriedParts) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path mediaPipe = std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) /
                                            "mediapipe-canonical-face" / "canonical_face_model.obj";
    if (!std::filesystem::exists(mediaPipe))
        GTEST_SKIP() << "shared data missing: " << mediaPipe << " (set VISEMELAB_SHARED_DATA_DIR)";
    GuiDriver gui({"--panel", "Deformation"});
    gui.waitIdle();
    const auto bundled = partCentres(gui);
    ASSERT_EQ(bundled.size(), 6u) << gui.document().dump();
    gui.click(gui.control("Use my mesh...", "button"));
    gui.chooseFile(mediaPipe);
    gui.click(gui.control("Build face from these landmarks", "button"));
    gui.waitIdle();
    ASSERT_EQ(gui.document()["face_name"], "canonical_face_model") << gui.document()["messages"].dump();

    openRefineTab(gui);
    EXPECT_GT(faceView(gui)["part_triangles"].get<int>(), 0);
    const auto carried = partCentres(gui);
    ASSERT_EQ(carried.size(), 6u);
    EXPECT_NE(carried.at("teeth_upper").x + carried.at("teeth_upper").y + carried.at("teeth_upper").z,
              bundled.at("teeth_upper").x + bundled.at("teeth_upper").y + bundled.at("teeth_upper").z);
    dragJawOpenToItsEnd(gui);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

} // namespace
} // namespace vl::test
