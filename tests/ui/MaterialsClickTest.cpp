// Issue 32's materials with real input (xdotool on a private Xvfb, see GuiDriver.h): a small
// textured avatar (tests/gltf/TexturedAvatar.h, a solid red face texture) is drawn in its texture's
// colour, the "Error colours" switch in the view's corner shows the selected viseme's merge error
// instead (blue where it is zero), and View > Materials brings the texture back.
#include "GuiDriver.h"
#include "tests/gltf/TexturedAvatar.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <memory>

namespace vl::test {
namespace {

// The colour at a fraction of the main view in a screenshot of the window.
std::array<int, 3> viewColour(GuiDriver& gui, const std::string& name, double fx, double fy) {
    const auto view = gui.control("main", "view");
    const std::filesystem::path file = gui.screenshot(name);
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load(file.string().c_str(), &width, &height, &channels, 3), stbi_image_free);
    EXPECT_TRUE(pixels) << file;
    if (!pixels) return {0, 0, 0};
    const int x = static_cast<int>(view["x"].get<double>() + fx * view["width"].get<double>());
    const int y = static_cast<int>(view["y"].get<double>() + fy * view["height"].get<double>());
    const unsigned char* p = pixels.get() + 3 * (y * width + x);
    return {p[0], p[1], p[2]};
}

std::string describe(const std::array<int, 3>& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// The face texture's red (220, 40, 40) under the view's light: red well above green and blue.
bool textureRed(const std::array<int, 3>& c) {
    return c[0] > 170 && c[1] < 110 && c[2] < 110;
}

TEST(MaterialsClicks, TextureDrawnSwitchedToErrorColoursAndBack) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "visemelab_materials_click";
    std::filesystem::create_directories(folder);
    const std::filesystem::path avatar = folder / "textured.glb";
    std::ofstream(avatar, std::ios::binary) << texturedAvatar();

    GuiDriver gui({"--avatar", avatar.string(), "--panel", "Visemes", "--no-wireframe"});
    gui.waitIdle();
    const nlohmann::json& surface = gui.document()["surface"];
    ASSERT_TRUE(surface["has_materials"].get<bool>()) << surface.dump();
    EXPECT_EQ(surface["choice"], "materials");
    EXPECT_EQ(surface["textures"], 1);
    EXPECT_EQ(surface["viseme_ranges"], 2);                      // the face and the eye
    EXPECT_EQ(surface["context_ranges"], 1);                     // the body
    ASSERT_EQ(surface["warnings"].size(), 1u) << surface.dump(); // the body's KTX2 texture
    EXPECT_EQ(gui.document()["surface"]["main_colours"], "material");
    // Above the centre: the face where viseme_aa moves nothing (its merge error is 0 there).
    const double fx = 0.5, fy = 0.4;
    const auto materials = viewColour(gui, "materials", fx, fy);
    EXPECT_TRUE(textureRed(materials)) << describe(materials);

    // Select viseme_aa (still in its texture), then the switch's other half: its merge error.
    gui.click(gui.control("viseme_aa", "selectable"), 0.1, 0.5);
    EXPECT_EQ(gui.document()["selected_viseme"], 1);
    EXPECT_TRUE(textureRed(viewColour(gui, "selected", fx, fy)));
    gui.click(gui.control("Error colours", "button"));
    gui.waitIdle();
    gui.waitFrames(3);
    EXPECT_EQ(gui.document()["surface"]["choice"], "error colours");
    EXPECT_EQ(gui.document()["surface"]["main_colours"], "scalar");
    const auto errors = viewColour(gui, "errors", fx, fy);
    // The colour ramp's zero end (46, 61, 133) under the light: blue, nothing of the texture.
    EXPECT_GT(errors[2], errors[0] + 40) << describe(errors);
    EXPECT_FALSE(textureRed(errors)) << describe(errors);

    // Back through the View menu.
    gui.click(gui.control("View", "menu"));
    gui.click(gui.control("Materials", "menuitem"));
    EXPECT_EQ(gui.document()["surface"]["choice"], "materials");
    EXPECT_EQ(gui.document()["surface"]["main_colours"], "material");
    const auto back = viewColour(gui, "back", fx, fy);
    EXPECT_TRUE(textureRed(back)) << describe(back);
    EXPECT_ALIVE(gui);
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace vl::test
