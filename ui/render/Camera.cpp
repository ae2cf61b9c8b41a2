#include "ui/render/Camera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace vl::ui {
namespace {

constexpr float kMaxPitch = glm::half_pi<float>();

glm::vec3 forwardOf(float yaw, float pitch) {
    // yaw = 0, pitch = 0 looks down -z (the face looks along +z at the viewer).
    return {-std::sin(yaw) * std::cos(pitch), -std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

} // namespace

const char* standardViewName(StandardView view) {
    static const char* const kNames[] = {"Front", "Back", "Right", "Left", "Top", "Bottom"};
    return kNames[static_cast<int>(view)];
}

std::optional<StandardView> standardViewFromName(std::string_view name) {
    for (int i = 0; i <= static_cast<int>(StandardView::Bottom); ++i) {
        const std::string_view candidate = standardViewName(static_cast<StandardView>(i));
        if (std::equal(name.begin(), name.end(), candidate.begin(), candidate.end(),
                       [](char a, char b) { return std::tolower(a) == std::tolower(b); }))
            return static_cast<StandardView>(i);
    }
    return std::nullopt;
}

glm::vec3 OrbitCamera::eye() const {
    return target - forwardOf(yaw, pitch) * distance;
}

glm::mat4 OrbitCamera::view() const {
    // Rotations rather than lookAt: the same matrix without roll, and defined at the poles (top and
    // bottom views), where lookAt's up vector would be parallel to the view axis.
    glm::mat4 v = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -distance));
    v = glm::rotate(v, pitch, glm::vec3(1.0f, 0.0f, 0.0f));
    v = glm::rotate(v, -yaw, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::translate(v, -target);
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    aspect = std::max(aspect, 1e-3f);
    if (orthographic) {
        // Depth both sides of the eye: nothing of the model is cut when zoomed in.
        const float h = 0.5f * visibleHeightAtTarget(), depth = distance * 100.0f;
        return glm::ortho(-h * aspect, h * aspect, -h, h, -depth, depth);
    }
    const float nearPlane = std::max(distance * 0.01f, 1e-4f);
    return glm::perspective(fovY, aspect, nearPlane, distance * 100.0f);
}

void OrbitCamera::orbit(float deltaYaw, float deltaPitch) {
    yaw += deltaYaw;
    pitch = std::clamp(pitch + deltaPitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::setView(StandardView view) {
    constexpr float kPi = glm::pi<float>();
    static const float kAngles[][2] = {{0.0f, 0.0f},        {kPi, 0.0f},       {0.5f * kPi, 0.0f},
                                       {-0.5f * kPi, 0.0f}, {0.0f, kMaxPitch}, {0.0f, -kMaxPitch}};
    yaw = kAngles[static_cast<int>(view)][0];
    pitch = kAngles[static_cast<int>(view)][1];
}

float OrbitCamera::visibleHeightAtTarget() const {
    return 2.0f * distance * std::tan(fovY * 0.5f);
}

void OrbitCamera::pan(float dx, float dy) {
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec3 up(v[0][1], v[1][1], v[2][1]);
    const float h = visibleHeightAtTarget();
    target += (-dx * right + dy * up) * h;
}

void OrbitCamera::zoom(float factor) {
    distance = std::clamp(distance * factor, 1e-4f, 1e6f);
}

void OrbitCamera::frame(const glm::vec3& lo, const glm::vec3& hi) {
    target = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-4f);
    distance = radius / std::sin(fovY * 0.5f) * 0.95f;
}

Ray OrbitCamera::rayThrough(float ndcX, float ndcY, float aspect) const {
    const glm::mat4 inverse = glm::inverse(projection(aspect) * view());
    glm::vec4 nearPoint = inverse * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    return {glm::vec3(nearPoint), glm::normalize(glm::vec3(farPoint - nearPoint))};
}

} // namespace vl::ui
