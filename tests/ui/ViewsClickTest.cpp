// Issue 32's views with real input (xdotool on a private Xvfb, see GuiDriver.h): numpad 1/3/7 and
// Ctrl+numpad give the standard views (the probe's view matrix against a reference built with
// lookAt from the camera's target and distance), the front view shows the sample face frontally (a
// screenshot, mirror-symmetric), Home frames, numpad 5 switches to an orthographic projection of the
// same extent, the View menu's items by click, and the comparison's two views keep one camera.
#include "GuiDriver.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

namespace vl::test {
namespace {

glm::mat4 matrixOf(const nlohmann::json& flat) {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = flat[static_cast<std::size_t>(c * 4 + r)].get<float>();
    return m;
}

// The view a camera at `target + side * distance` looking at the target has, `up` up.
glm::mat4 reference(const nlohmann::json& camera, glm::vec3 side, glm::vec3 up) {
    const glm::vec3 target(camera["target"][0].get<float>(), camera["target"][1].get<float>(),
                           camera["target"][2].get<float>());
    return glm::lookAt(target + side * camera["distance"].get<float>(), target, up);
}

void expectView(const GuiDriver& gui, glm::vec3 side, glm::vec3 up, const std::string& what) {
    const nlohmann::json& camera = gui.document()["camera"];
    const glm::mat4 expected = reference(camera, side, up);
    const glm::mat4 drawn = matrixOf(gui.document()["drawn_camera"]["view"]);
    const float scale = camera["distance"].get<float>();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(drawn[c][r], expected[c][r], 1e-4f * std::max(1.0f, scale))
                << what << " [" << c << "][" << r << "] camera " << camera.dump();
}

void orbitAway(GuiDriver& gui) {
    const auto view = gui.control("main", "view");
    const double x = view["x"].get<double>() + 0.5 * view["width"].get<double>();
    const double y = view["y"].get<double>() + 0.5 * view["height"].get<double>();
    gui.drag(x, y, x + 90, y + 40, 6);
    ASSERT_GT(std::abs(gui.document()["camera"]["yaw"].get<double>()), 0.3) << gui.document()["camera"];
}

struct Picture {
    int width = 0, height = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
    const unsigned char* at(int x, int y) const { return pixels.get() + 3 * (y * width + x); }
};

Picture load(const std::filesystem::path& file) {
    Picture picture;
    int channels = 0;
    picture.pixels.reset(stbi_load(file.string().c_str(), &picture.width, &picture.height, &channels, 3));
    return picture;
}

// Over the middle of the view: the share of pixels that are not the background, and the mean colour
// difference between each pixel and its mirror image across the view's centre line (a face seen
// from the front is left-right symmetric).
struct Symmetry {
    double covered = 0.0, asymmetry = 0.0;
};

Symmetry symmetryOf(const Picture& picture, const nlohmann::json& view) {
    const int x0 = static_cast<int>(view["x"].get<double>()), y0 = static_cast<int>(view["y"].get<double>());
    const int w = static_cast<int>(view["width"].get<double>()),
              h = static_cast<int>(view["height"].get<double>());
    const int cx = x0 + w / 2;
    Symmetry s;
    int n = 0;
    for (int y = y0 + h / 5; y < y0 + 4 * h / 5; y += 2)
        for (int dx = 0; dx < w / 4; dx += 2) {
            const unsigned char* a = picture.at(cx - dx, y);
            const unsigned char* b = picture.at(cx + dx, y);
            const bool background = std::abs(a[0] - 41) + std::abs(a[1] - 43) + std::abs(a[2] - 51) < 12;
            s.covered += background ? 0.0 : 1.0;
            s.asymmetry += std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
            ++n;
        }
    s.covered /= n;
    s.asymmetry /= n;
    return s;
}

TEST(ViewsClicks, NumpadViewsHomeAndOrthographic) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Visemes", "--no-wireframe"});
    gui.waitIdle();
    const double framed = gui.document()["camera"]["distance"].get<double>();
    orbitAway(gui);
    const auto view = gui.control("main", "view");
    const Symmetry away = symmetryOf(load(gui.screenshot("orbited")), view);

    // Numpad 1: the front, the face seen frontally.
    gui.tap("KP_1");
    expectView(gui, {0, 0, 1}, {0, 1, 0}, "front");
    const Symmetry front = symmetryOf(load(gui.screenshot("front")), view);
    EXPECT_GT(front.covered, 0.3) << "the face fills the middle of the view";
    EXPECT_LT(front.asymmetry, 0.5 * away.asymmetry)
        << "front " << front.asymmetry << ", orbited " << away.asymmetry;

    gui.tap("KP_3");
    expectView(gui, {1, 0, 0}, {0, 1, 0}, "right");
    gui.tap("KP_7");
    expectView(gui, {0, 1, 0}, {0, 0, -1}, "top");
    gui.tap("ctrl+KP_1");
    expectView(gui, {0, 0, -1}, {0, 1, 0}, "back");
    gui.tap("ctrl+KP_3");
    expectView(gui, {-1, 0, 0}, {0, 1, 0}, "left");
    gui.tap("ctrl+KP_7");
    expectView(gui, {0, -1, 0}, {0, 0, 1}, "bottom");

    // Home frames the model again after a zoom.
    gui.scroll(view["x"].get<double>() + 200, view["y"].get<double>() + 200, -4);
    EXPECT_LT(gui.document()["camera"]["distance"].get<double>(), 0.8 * framed);
    gui.tap("Home");
    EXPECT_NEAR(gui.document()["camera"]["distance"].get<double>(), framed, 1e-3 * framed);

    // Numpad 5: orthographic, showing at the target's depth the height the perspective shows.
    gui.tap("KP_1");
    gui.tap("KP_5");
    EXPECT_TRUE(gui.document()["camera"]["orthographic"].get<bool>());
    const glm::mat4 ortho = matrixOf(gui.document()["drawn_camera"]["projection"]);
    EXPECT_FLOAT_EQ(ortho[3][3], 1.0f) << "an orthographic projection";
    EXPECT_FLOAT_EQ(ortho[2][3], 0.0f);
    const float distance = gui.document()["camera"]["distance"].get<float>();
    EXPECT_NEAR(ortho[1][1] * distance * std::tan(0.3f), 1.0f, 1e-3f);
    expectView(gui, {0, 0, 1}, {0, 1, 0}, "front, orthographic");
    EXPECT_GT(symmetryOf(load(gui.screenshot("ortho")), view).covered, 0.3);
    gui.tap("KP_5");
    EXPECT_FALSE(gui.document()["camera"]["orthographic"].get<bool>());
    EXPECT_FLOAT_EQ(matrixOf(gui.document()["drawn_camera"]["projection"])[2][3], -1.0f) << "perspective";
    EXPECT_ALIVE(gui);
}

// The View menu's items, each a click; Reset view is the front view, framed, in perspective. In the
// Reduction panel the two views keep one camera.
TEST(ViewsClicks, ViewMenuItemsAndLinkedComparison) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction", "--no-wireframe"});
    gui.waitIdle();
    const double framed = gui.document()["camera"]["distance"].get<double>();
    const auto choose = [&](const char* item) {
        gui.click(gui.control("View", "menu"));
        gui.waitFrames(2);
        gui.click(gui.control(item, "menuitem"));
        gui.waitFrames(3);
    };
    choose("Right");
    expectView(gui, {1, 0, 0}, {0, 1, 0}, "View > Right");
    EXPECT_TRUE(gui.document()["drawn_camera"]["linked"].get<bool>());
    choose("Top");
    expectView(gui, {0, 1, 0}, {0, 0, -1}, "View > Top");
    choose("Back");
    expectView(gui, {0, 0, -1}, {0, 1, 0}, "View > Back");
    choose("Left");
    expectView(gui, {-1, 0, 0}, {0, 1, 0}, "View > Left");
    choose("Bottom");
    expectView(gui, {0, -1, 0}, {0, 0, 1}, "View > Bottom");
    choose("Orthographic");
    EXPECT_TRUE(gui.document()["camera"]["orthographic"].get<bool>());
    EXPECT_TRUE(gui.document()["drawn_camera"]["linked"].get<bool>()) << "both views orthographic";
    // Orbiting the right view moves the left one with it.
    const auto after = gui.control("after", "view");
    const double x = after["x"].get<double>() + 0.5 * after["width"].get<double>();
    const double y = after["y"].get<double>() + 0.5 * after["height"].get<double>();
    gui.drag(x, y, x + 60, y, 5);
    EXPECT_TRUE(gui.document()["drawn_camera"]["linked"].get<bool>());
    gui.scroll(x, y, -3);
    choose("Reset view");
    expectView(gui, {0, 0, 1}, {0, 1, 0}, "View > Reset view");
    EXPECT_FALSE(gui.document()["camera"]["orthographic"].get<bool>());
    EXPECT_NEAR(gui.document()["camera"]["distance"].get<double>(), framed, 1e-3 * framed);
    choose("Front");
    expectView(gui, {0, 0, 1}, {0, 1, 0}, "View > Front");
    EXPECT_TRUE(gui.document()["drawn_camera"]["linked"].get<bool>());
    EXPECT_ALIVE(gui);
}

} // namespace
} // namespace vl::test
