// The orbit camera's standard views against reference matrices built independently with lookAt
// (eye on the side the view names, +Y up; the top and bottom views with the face towards the
// screen's bottom and top, as in Blender), and the orthographic projection's extent.
#include "ui/render/Camera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace vl::ui {
namespace {

void expectNear(const glm::mat4& actual, const glm::mat4& expected, const char* what) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5f) << what << " [" << c << "][" << r << "]";
}

TEST(Camera, StandardViewsMatchLookAt) {
    OrbitCamera camera;
    camera.target = {0.1f, -0.2f, 0.3f};
    camera.distance = 2.5f;
    camera.orbit(0.7f, 0.4f); // from anywhere
    const glm::vec3 t = camera.target;
    const float d = camera.distance;
    struct Case {
        StandardView view;
        glm::vec3 eyeOffset, up;
    };
    const Case cases[] = {
        {StandardView::Front, {0, 0, d}, {0, 1, 0}}, {StandardView::Back, {0, 0, -d}, {0, 1, 0}},
        {StandardView::Right, {d, 0, 0}, {0, 1, 0}}, {StandardView::Left, {-d, 0, 0}, {0, 1, 0}},
        {StandardView::Top, {0, d, 0}, {0, 0, -1}},  {StandardView::Bottom, {0, -d, 0}, {0, 0, 1}}};
    for (const Case& c : cases) {
        camera.setView(c.view);
        expectNear(camera.view(), glm::lookAt(t + c.eyeOffset, t, c.up), standardViewName(c.view));
        const glm::vec3 eye = camera.eye();
        EXPECT_NEAR(glm::length(eye - (t + c.eyeOffset)), 0.0f, 1e-5f) << standardViewName(c.view);
        EXPECT_EQ(camera.target, t) << "a standard view keeps the target";
        EXPECT_EQ(camera.distance, d) << "and the distance";
    }
}

// The front view shows the face frontally: a point in front of the target (+z) is nearer the eye,
// the viewer's right is +x.
TEST(Camera, FrontViewSeesPlusZWithPlusXRight) {
    OrbitCamera camera;
    camera.setView(StandardView::Front);
    const glm::vec4 nose = camera.view() * glm::vec4(0, 0, 0.1f, 1);
    const glm::vec4 right = camera.view() * glm::vec4(0.1f, 0, 0, 1);
    EXPECT_GT(nose.z, -camera.distance); // view space looks down -z: larger z is nearer
    EXPECT_GT(right.x, 0.0f);
}

// Orbiting reaches the poles and stops there; the view stays defined.
TEST(Camera, OrbitStopsAtThePoles) {
    OrbitCamera camera;
    camera.orbit(0.0f, 10.0f);
    EXPECT_FLOAT_EQ(camera.pitch, glm::half_pi<float>());
    camera.setView(StandardView::Top);
    const glm::mat4 top = camera.view();
    camera.orbit(0.0f, 0.5f);
    expectNear(camera.view(), top, "past the top");
}

// Orthographic: the same extent as the perspective at the target's depth, and parallel rays.
TEST(Camera, OrthographicFramesTheSameExtent) {
    OrbitCamera camera;
    camera.target = {1, 2, 3};
    camera.distance = 4.0f;
    const float aspect = 1.5f, h = camera.visibleHeightAtTarget();
    for (bool ortho : {false, true}) {
        camera.orthographic = ortho;
        const glm::mat4 clip = camera.projection(aspect) * camera.view();
        glm::vec4 top = clip * glm::vec4(camera.target + glm::vec3(0, 0.5f * h, 0), 1);
        glm::vec4 side = clip * glm::vec4(camera.target + glm::vec3(0.5f * h * aspect, 0, 0), 1);
        top /= top.w;
        side /= side.w;
        EXPECT_NEAR(top.y, 1.0f, 1e-4f) << (ortho ? "ortho" : "perspective");
        EXPECT_NEAR(side.x, 1.0f, 1e-4f) << (ortho ? "ortho" : "perspective");
    }
    // In orthographic a point behind the target projects where the target's does.
    const glm::mat4 clip = camera.projection(aspect) * camera.view();
    glm::vec4 far = clip * glm::vec4(camera.target + glm::vec3(0.3f, 0.2f, -2.0f), 1);
    glm::vec4 near = clip * glm::vec4(camera.target + glm::vec3(0.3f, 0.2f, 1.0f), 1);
    EXPECT_NEAR(far.x / far.w, near.x / near.w, 1e-5f);
    EXPECT_NEAR(far.y / far.w, near.y / near.w, 1e-5f);
    const Ray a = camera.rayThrough(0.2f, 0.1f, aspect), b = camera.rayThrough(-0.5f, 0.7f, aspect);
    EXPECT_NEAR(glm::dot(a.direction, b.direction), 1.0f, 1e-5f) << "parallel rays";
    EXPECT_NEAR(glm::dot(a.direction, glm::vec3(0, 0, -1)), 1.0f, 1e-5f);
}

} // namespace
} // namespace vl::ui
