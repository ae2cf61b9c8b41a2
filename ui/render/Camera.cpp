#include "ui/render/Camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace vl::ui {
namespace {

constexpr float kMaxPitch = 1.5f;

glm::vec3 forwardOf(float yaw, float pitch) {
    // yaw = 0, pitch = 0 looks down -z (the face looks along +z at the viewer).
    return {-std::sin(yaw) * std::cos(pitch), -std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

} // namespace

glm::vec3 OrbitCamera::eye() const {
    return target - forwardOf(yaw, pitch) * distance;
}

glm::mat4 OrbitCamera::view() const {
    return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float nearPlane = std::max(distance * 0.01f, 1e-4f);
    return glm::perspective(fovY, std::max(aspect, 1e-3f), nearPlane, distance * 100.0f);
}

void OrbitCamera::orbit(float deltaYaw, float deltaPitch) {
    yaw += deltaYaw;
    pitch = std::clamp(pitch + deltaPitch, -kMaxPitch, kMaxPitch);
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
