#include "ui/panels/LandmarkHandles.h"

#include "ui/UiScale.h"
#include "ui/probe/GuiProbe.h"
#include "ui/session/EditorSession.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vl::ui {
namespace {

// Where a model point lands in the view's image (pixels), or none behind the camera.
std::optional<ImVec2> onScreen(const OrbitCamera& camera, ImVec2 min, ImVec2 max, const Vec3& p) {
    const float aspect = (max.x - min.x) / std::max(1.0f, max.y - min.y);
    const glm::vec4 clip =
        camera.projection(aspect) * camera.view() *
        glm::vec4(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]), 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    return ImVec2(min.x + (clip.x / clip.w * 0.5f + 0.5f) * (max.x - min.x),
                  min.y + (0.5f - clip.y / clip.w * 0.5f) * (max.y - min.y));
}

float reach() {
    return scaled(9.0f); // pixels from a dot's centre that still take hold of it
}

} // namespace

std::optional<face::Landmark> LandmarkHandles::under(const OrbitCamera& camera, ImVec2 min, ImVec2 max,
                                                     ImVec2 mouse) const {
    const auto& step = session_.document().ownFace;
    if (!step || mouse.x < min.x || mouse.y < min.y || mouse.x > max.x || mouse.y > max.y)
        return std::nullopt;
    std::optional<face::Landmark> best;
    float bestDistance = reach();
    for (const face::Landmark landmark : face::allLandmarks()) {
        const face::FoundLandmark& found = step->landmarks()[landmark];
        if (!found.found()) continue;
        const std::optional<ImVec2> at = onScreen(camera, min, max, found.position);
        if (!at) continue;
        const float d = std::hypot(at->x - mouse.x, at->y - mouse.y);
        if (d <= bestDistance) bestDistance = d, best = landmark;
    }
    return best;
}

bool LandmarkHandles::wantsMouse(const OrbitCamera& camera, ImVec2 min, ImVec2 size) {
    if (!session_.document().ownFace) {
        drag_.cancel();
        hovered_.reset();
        return false;
    }
    if (drag_.landmark()) return true;
    hovered_ = under(camera, min, ImVec2(min.x + size.x, min.y + size.y), ImGui::GetIO().MousePos);
    return hovered_.has_value() && !ImGui::GetIO().KeyAlt; // Alt+drag orbits, as with the brushes
}

void LandmarkHandles::handle(const OrbitCamera& camera, const ViewportEvents& events) {
    drawn_ = nlohmann::json::object();
    const auto& step = session_.document().ownFace;
    if (!step) return;
    if (!events.hovered && !drag_.landmark()) hovered_.reset();
    // Take hold on a press over a dot; follow the cursor over the surface; place on release.
    if (events.leftPressed && hovered_ && !ImGui::GetIO().KeyAlt) drag_.begin(*hovered_);
    if (drag_.landmark()) {
        if (events.leftDown) {
            const Ray ray = camera.rayThrough(events.ndc.x, events.ndc.y, events.aspect);
            drag_.move(Vec3(ray.origin.x, ray.origin.y, ray.origin.z),
                       Vec3(ray.direction.x, ray.direction.y, ray.direction.z));
        } else {
            hovered_ = drag_.landmark();
            drag_.end();
        }
    }

    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(events.imageMin, events.imageMax, true);
    const float radius = scaled(5.0f);
    // What a name must not cover (min x, min y, max x, max y): every dot, then the names drawn.
    std::vector<ImVec4> labels;
    for (const face::Landmark landmark : face::allLandmarks()) {
        const face::FoundLandmark& found = step->landmarks()[landmark];
        if (!found.found()) continue;
        if (const auto at = onScreen(camera, events.imageMin, events.imageMax, found.position))
            labels.emplace_back(at->x - radius, at->y - radius, at->x + radius, at->y + radius);
    }
    for (const face::Landmark landmark : face::allLandmarks()) {
        const face::FoundLandmark& found = step->landmarks()[landmark];
        const bool dragged = drag_.landmark() == landmark;
        if (!found.found() && !dragged) continue;
        const Vec3 position = dragged && drag_.point() ? drag_.point()->position : found.position;
        const std::optional<ImVec2> at = onScreen(camera, events.imageMin, events.imageMax, position);
        if (!at) continue;
        const std::string name(toString(landmark));
        const bool lit = dragged || hovered_ == landmark;
        // Required landmarks yellow, the optional lip points cyan; the one under the cursor white.
        const ImU32 fill = lit                          ? IM_COL32(255, 255, 255, 255)
                           : face::isRequired(landmark) ? IM_COL32(255, 214, 64, 255)
                                                        : IM_COL32(90, 220, 255, 255);
        draw->AddCircleFilled(*at, lit ? 1.5f * radius : radius, fill, 16);
        draw->AddCircle(*at, lit ? 1.5f * radius : radius, IM_COL32(20, 20, 24, 255), 16, 1.5f);
        // The name beside the dot, right or else left of it where no other name is; crowded dots
        // (the lip points) show theirs under the cursor only.
        const ImVec2 size = ImGui::CalcTextSize(name.c_str());
        const float top = at->y - 0.9f * ImGui::GetFontSize();
        for (const float x : {at->x + 1.8f * radius, at->x - 1.8f * radius - size.x}) {
            const ImVec4 box(x - 2.0f, top - 1.0f, x + size.x + 2.0f, top + size.y + 1.0f);
            const bool free = std::none_of(labels.begin(), labels.end(), [&](const ImVec4& other) {
                return box.x < other.z && other.x < box.z && box.y < other.w && other.y < box.w;
            });
            if (!free && !lit) continue;
            if (lit)
                draw->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.z, box.w), IM_COL32(20, 20, 24, 200),
                                    3.0f);
            draw->AddText(ImVec2(x, top), fill, name.c_str());
            labels.push_back(box);
            break;
        }
        probe::recordRect(name.c_str(), "landmark", ImVec2(at->x - radius, at->y - radius),
                          ImVec2(at->x + radius, at->y + radius));
        drawn_[name] = {at->x, at->y};
        if (lit && !dragged)
            ImGui::SetTooltip("%s: %s %.0f%%\n%s\nDrag over the surface to move it (one undo step)",
                              name.c_str(), std::string(face::sourceName(found.source)).c_str(),
                              100.0 * found.confidence, found.method.c_str());
    }
    draw->PopClipRect();
}

nlohmann::json LandmarkHandles::probe() const {
    return {{"dots", drawn_},
            {"hovered", hovered_ ? nlohmann::json(toString(*hovered_)) : nlohmann::json()},
            {"dragged", drag_.landmark() ? nlohmann::json(toString(*drag_.landmark())) : nlohmann::json()}};
}

} // namespace vl::ui
