#include "ui/panels/BrushCursor.h"

#include "core/paint/BrushRadius.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace vl::ui {

namespace {
glm::vec3 toGlm(const Vec3& p) {
    return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}
} // namespace

double unitsPerPixelAt(const OrbitCamera& camera, const ViewportEvents& events, const Vec3& point) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
    // Orthographic views show every depth at the scale of the target's (OrbitCamera::projection).
    const double depth =
        camera.orthographic
            ? static_cast<double>(camera.distance)
            : std::max(1e-6, static_cast<double>(glm::dot(toGlm(point) - camera.eye(), forward)));
    const double imageHeight = std::max(1.0f, events.imageMax.y - events.imageMin.y);
    return modelUnitsPerPixel(depth, camera.fovY, imageHeight);
}

void drawBrushCircle(const OrbitCamera& camera, const ViewportEvents& events, const Vec3& point,
                     double radius, double unitsPerPixel, ImU32 colour) {
    const glm::vec4 clip = camera.projection(events.aspect) * camera.view() * glm::vec4(toGlm(point), 1.0f);
    const ImVec2 c(
        events.imageMin.x + (clip.x / clip.w * 0.5f + 0.5f) * (events.imageMax.x - events.imageMin.x),
        events.imageMin.y + (0.5f - clip.y / clip.w * 0.5f) * (events.imageMax.y - events.imageMin.y));
    ImGui::GetWindowDrawList()->AddCircle(c, static_cast<float>(radius / unitsPerPixel), colour, 48, 1.5f);
}

} // namespace vl::ui
