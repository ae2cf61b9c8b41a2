#include "ui/panels/VisemeSculptor.h"

#include "core/paint/RayPick.h"
#include "ui/UiScale.h"
#include "ui/panels/BrushCursor.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/Controls.h"

#include <glm/glm.hpp>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace vl::ui {

namespace {

Vec3 toVec3(const glm::vec3& v) {
    return Vec3(v.x, v.y, v.z);
}

// The middle of the neutral's bounding box in x: the face's left/right symmetry plane.
double symmetryPlane(const VisemeSet& set) {
    return PaintSurface(set.neutral.positions, {}).mirrorX();
}

} // namespace

bool VisemeSculptor::active() const {
    const VisemeSet* set = session_.visemes();
    return settings.enabled && set && session_.selectedViseme() >= 0 &&
           session_.selectedViseme() < static_cast<int>(set->size());
}

SculptDab VisemeSculptor::dab(const Vec3& eye) const {
    SculptDab d;
    d.tool = settings.tool;
    d.brush.radius = strokeRadius_;
    d.brush.strength = settings.strength;
    d.brush.falloff = static_cast<Falloff>(settings.falloff);
    d.brush.symmetric = settings.symmetric;
    d.brush.mirrorX = mirrorX_;
    if (settings.frontFacesOnly) d.brush.eye = eye;
    return d;
}

void VisemeSculptor::sculpt(const ViewportEvents& events) {
    if (!active()) {
        strokeActive_ = false;
        return;
    }
    const VisemeSet& set = *session_.visemes();
    const auto index = static_cast<std::size_t>(session_.selectedViseme());
    const OrbitCamera& camera = view_.camera;
    const Ray ray = camera.rayThrough(events.ndc.x, events.ndc.y, events.aspect);
    const Vec3 origin = toVec3(ray.origin), direction = toVec3(ray.direction);
    // The shape as shown: the stroke's while one lasts, else the document's.
    const PaintSurface shown =
        strokeActive_ ? strokeSurface_ : PaintSurface(set.visemes[index].positions, set.neutral.triangles);
    const auto hit = intersectRay(shown.positions(), shown.triangles(), origin, direction);
    if (hit)
        session_.attempt("Sculpt", [&] {
            unitsPerPixel_ = unitsPerPixelAt(camera, events, hit->point);
            modelRadius_ = modelRadius(settings.radius, shown.size(), unitsPerPixel_);
            if (events.hovered)
                drawBrushCircle(camera, events, hit->point, modelRadius_, unitsPerPixel_,
                                IM_COL32(255, 200, 120, 220));
        });
    if (events.leftPressed && hit && !ImGui::GetIO().KeyAlt && modelRadius_ > 0) {
        strokeActive_ = true;
        strokeViseme_ = session_.selectedViseme();
        strokeStart_ = set.visemes[index].positions;
        strokeShape_ = strokeStart_;
        strokeSurface_ = shown;
        grabPoint_ = hit->point;
        strokeRadius_ = modelRadius_;
        mirrorX_ = symmetryPlane(set);
        lastDab_.reset();
        strokeDabs_ = 0;
    }
    if (!strokeActive_) return;
    if (strokeViseme_ != session_.selectedViseme() || !events.leftDown) {
        strokeActive_ = false;
        session_.history().endEdit(); // the next stroke is its own undo step
        return;
    }
    const Vec3 eye = toVec3(camera.eye());
    bool changed = false;
    session_.attempt("Sculpt", [&] {
        if (settings.tool == SculptTool::Grab) {
            // The grabbed point follows the cursor in the plane facing the camera through it; the
            // footprint stays the one the stroke took hold of.
            const Vec3 normal = toVec3(glm::normalize(camera.target - camera.eye()));
            const double along = OpenMesh::dot(direction, normal);
            if (std::abs(along) < 1e-9) return;
            const double t = OpenMesh::dot(grabPoint_ - origin, normal) / along;
            SculptDab d = dab(eye);
            d.grab = origin + t * direction - grabPoint_;
            strokeShape_ = strokeStart_;
            applySculptDab(strokeSurface_, set.neutral.positions, d, grabPoint_, strokeShape_);
            changed = d.grab.sqrnorm() > 0;
        } else if (hit && (!lastDab_ || (hit->point - *lastDab_).norm() >= 0.25 * strokeRadius_)) {
            // Dabs a quarter radius apart along the stroke, on the shape as it is now.
            applySculptDab(strokeSurface_, set.neutral.positions, dab(eye), hit->point, strokeShape_);
            strokeSurface_ = PaintSurface(strokeShape_, set.neutral.triangles);
            lastDab_ = hit->point;
            changed = true;
        }
        if (!changed) return;
        ++strokeDabs_;
        session_.authoring().sculptViseme(strokeViseme_, strokeShape_, settings.tool);
    });
}

void VisemeSculptor::controls() {
    // On an avatar the meshes without a target of the selected viseme stay put (edit::setVisemeShape),
    // and a new viseme would need a new target: Blend is for viseme sets of meshes.
    const bool avatar = session_.document().avatar.isSet();
    // Two rows, so that the panel's narrowest width still shows every control.
    ctl::Checkbox("Sculpt", &settings.enabled);
    ImGui::SameLine();
    const char* tools[] = {"grab", "smooth", "inflate", "deflate"};
    int tool = static_cast<int>(settings.tool);
    ImGui::SetNextItemWidth(scaled(90));
    if (ctl::Combo("##sculpt-tool", &tool, tools, 4)) settings.tool = static_cast<SculptTool>(tool);
    ImGui::SameLine();
    ctl::Checkbox("X-mirror", &settings.symmetric);
    ImGui::SameLine();
    if (avatar) ImGui::BeginDisabled();
    if (ctl::Button("Blend...")) openBlend_ = true;
    if (avatar) ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(avatar ? "An avatar's visemes are its morph targets: sculpt one of them instead of "
                                   "blending a new one"
                                 : "A new viseme mixed from others: the neutral plus each one's displacement "
                                   "times its weight");
    ImGui::SetNextItemWidth(scaled(140));
    float radius = static_cast<float>(settings.radius.value);
    if (ctl::SliderFloat("##sculpt-radius", &radius, 1.0f, 40.0f, "radius %.0f %%"))
        settings.radius.value = radius;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Brush radius in %% of the head's size");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(scaled(140));
    ctl::SliderFloat("##sculpt-strength", &settings.strength, 0.05f, 1.0f, "strength %.2f");
    if (settings.enabled) {
        ImGui::SameLine();
        ImGui::TextDisabled(session_.selectedViseme() >= 0 ? "Alt+drag orbits" : "select a viseme to sculpt");
    }
    blendPopup();
}

void VisemeSculptor::blendPopup() {
    const VisemeSet* set = session_.visemes();
    if (!set) return;
    if (openBlend_) {
        ImGui::OpenPopup("Blend visemes");
        blendWeights_.assign(set->size(), 0.0f);
        if (session_.selectedViseme() >= 0 && session_.selectedViseme() < static_cast<int>(set->size()))
            blendWeights_[static_cast<std::size_t>(session_.selectedViseme())] = 1.0f;
        blendName_.clear();
        openBlend_ = false;
    }
    if (!ImGui::BeginPopupModal("Blend visemes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    blendWeights_.resize(set->size(), 0.0f);
    ImGui::TextUnformatted("New viseme = neutral + sum of weight x (viseme - neutral)");
    if (ImGui::BeginChild("##blend-weights", ImVec2(scaled(360), scaled(260)), true)) {
        for (std::size_t i = 0; i < set->size(); ++i) {
            ImGui::PushID(static_cast<int>(i));
            ImGui::SetNextItemWidth(scaled(200));
            ctl::SliderFloat(set->visemes[i].name.c_str(), &blendWeights_[i], -1.0f, 2.0f, "%.2f");
            ImGui::PopID();
        }
    }
    ImGui::EndChild();
    ImGui::SetNextItemWidth(scaled(200));
    ctl::InputTextWithHint("##blend-name", "name of the new viseme", &blendName_);
    if (ctl::Button("Create##blend")) {
        std::vector<std::pair<int, double>> mix;
        for (std::size_t i = 0; i < blendWeights_.size(); ++i)
            if (blendWeights_[i] != 0.0f) mix.emplace_back(static_cast<int>(i), blendWeights_[i]);
        if (session_.attempt("Blend visemes",
                             [&] { session_.authoring().addBlendedViseme(blendName_, mix); }))
            ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ctl::Button("Cancel##blend")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

nlohmann::json VisemeSculptor::probe() const {
    // The selected viseme's summed y coordinate: a stroke pulling up raises it by the sum of the
    // reached vertices' factors times the pull.
    double ySum = 0.0;
    const VisemeSet* set = session_.visemes();
    if (set && session_.selectedViseme() >= 0 && session_.selectedViseme() < static_cast<int>(set->size()))
        for (const Vec3& p : set->visemes[static_cast<std::size_t>(session_.selectedViseme())].positions)
            ySum += p[1];
    return {{"enabled", settings.enabled},
            {"shape_y_sum", ySum},
            {"tool", std::string(sculptToolName(settings.tool))},
            {"radius_percent", settings.radius.value},
            {"strength", settings.strength},
            {"mirror", settings.symmetric},
            {"stroke", strokeActive_},
            {"stroke_dabs", strokeDabs_},
            {"model_radius", modelRadius_},
            {"units_per_pixel", unitsPerPixel_}};
}

} // namespace vl::ui
