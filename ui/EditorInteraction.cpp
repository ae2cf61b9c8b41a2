// Per-frame interaction of the editor's views: weight painting and the per-vertex scalars (weights, merge
// errors, field influence) shown through the colour map.
#include "ui/EditorUi.h"

#include "core/inspect/VertexErrors.h"
#include "core/paint/PaintRegions.h"
#include "core/paint/RayPick.h"
#include "core/paint/VertexVisibility.h"
#include "core/paint/WeightBrush.h"

#include <imgui.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <utility>

namespace vl::ui {
namespace {

std::vector<float> normalised(const std::vector<double>& values, double scale) {
    std::vector<float> out(values.size(), 0.0f);
    if (scale <= 0.0) return out;
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<float>(values[i] / scale);
    return out;
}

double maxOf(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

} // namespace

const PaintSurface& EditorUi::paintSurface() {
    const auto& set = session.document().visemes;
    if (set != paintSurfaceSet_) {
        paintSurfaceSet_ = set;
        paintSurface_ = set ? PaintSurface(set->neutral.positions, set->neutral.triangles) : PaintSurface();
        paintTool_.selection.clear(); // vertex indices of another mesh
    }
    return paintSurface_;
}

std::vector<double> EditorUi::paintStartWeights() const {
    // Edits start from the weights shown (uniform, area or painted), scaled to [0, 1].
    const auto& weights = session.document().weights;
    return weightsForPainting(weights.mode, session.visemes()->neutral, weights.paintedOrEmpty());
}

void EditorUi::fillVertices(const std::vector<std::uint32_t>& vertices, const char* action) {
    if (vertices.empty()) {
        session.error(std::string(action) + ": nothing to fill");
        return;
    }
    session.attempt(action, [&] {
        session.setPaintedWeights(filled(paintStartWeights(), vertices, paintTool_.fillValue), action);
        char text[160];
        std::snprintf(text, sizeof text, "%s: %zu vertices set to %.2f", action, vertices.size(),
                      static_cast<double>(paintTool_.fillValue));
        session.info(text);
    });
    weightsKey_.clear();
}

void EditorUi::paint(const ViewportEvents& events) {
    const VisemeSet* set = session.visemes();
    paintTool_.readout.reset();
    if (!set) return;
    const PaintSurface& surface = paintSurface();
    const bool painting = brush_.enabled;
    if (painting) drawSelection(events);
    const bool boxing = painting && paintTool_.tool == PaintTool::SelectBox;
    if (boxing) paintBoxSelection(events);
    if (!events.hovered && !strokeActive_) return;
    const OrbitCamera& camera = mainView_.camera;
    const Ray ray = camera.rayThrough(events.ndc.x, events.ndc.y, events.aspect);
    const auto hit =
        intersectRay(surface.positions(), surface.triangles(), Vec3(ray.origin.x, ray.origin.y, ray.origin.z),
                     Vec3(ray.direction.x, ray.direction.y, ray.direction.z));
    std::uint32_t hitVertex = 0; // the corner of the hit triangle nearest to the hit point
    if (hit) {
        const Triangle& t = surface.triangles()[hit->triangle];
        const double* b = hit->barycentric.data();
        hitVertex = t[static_cast<std::size_t>(std::max_element(b, b + 3) - b)];
    }
    const std::vector<double>& shown = strokeActive_ ? strokeWeights_ : shownWeights_;
    if (hit && events.hovered && shown.size() == surface.vertexCount()) {
        // The weight under the cursor, as the colours show it (the stroke's while one is going on).
        paintTool_.readout = valueAt(surface, shown, hit->triangle, hit->barycentric);
        paintTool_.readoutVertex = hitVertex;
        const double largest = maxOf(shown);
        char text[128];
        std::snprintf(text, sizeof text, "weight %.3g  (%.0f%% of the largest; vertex %u)",
                      *paintTool_.readout, largest > 0.0 ? 100.0 * *paintTool_.readout / largest : 0.0,
                      hitVertex);
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const ImVec2 size = ImGui::CalcTextSize(text);
        // Beside the cursor, kept inside the view.
        const float x =
            std::max(events.imageMin.x + 4.0f, std::min(mouse.x + 18.0f, events.imageMax.x - size.x - 8.0f));
        const float y =
            std::max(events.imageMin.y + 4.0f, std::min(mouse.y + 22.0f, events.imageMax.y - size.y - 8.0f));
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddRectFilled(ImVec2(x - 4, y - 2), ImVec2(x + size.x + 4, y + size.y + 2),
                            IM_COL32(20, 20, 24, 200), 3.0f);
        draw->AddText(ImVec2(x, y), IM_COL32(235, 235, 240, 255), text);
    }
    if (hit) {
        // The radius in model units at the hit point: screen pixels scale with its depth.
        const glm::vec3 centre(static_cast<float>(hit->point[0]), static_cast<float>(hit->point[1]),
                               static_cast<float>(hit->point[2]));
        const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
        const double depth = std::max(1e-6, static_cast<double>(glm::dot(centre - camera.eye(), forward)));
        const double imageHeight = std::max(1.0f, events.imageMax.y - events.imageMin.y);
        session.attempt("Brush", [&] {
            const double perPixel = modelUnitsPerPixel(depth, camera.fovY, imageHeight);
            paintTool_.modelRadius = modelRadius(brush_.radius, surface.size(), perPixel);
            paintTool_.unitsPerPixel = perPixel;
            if (events.hovered && brush_.enabled && paintTool_.tool == PaintTool::Brush) {
                const glm::mat4 viewProjection = camera.projection(events.aspect) * camera.view();
                const glm::vec4 clip = viewProjection * glm::vec4(centre, 1.0f);
                const ImVec2 c(events.imageMin.x +
                                   (clip.x / clip.w * 0.5f + 0.5f) * (events.imageMax.x - events.imageMin.x),
                               events.imageMin.y +
                                   (0.5f - clip.y / clip.w * 0.5f) * (events.imageMax.y - events.imageMin.y));
                ImGui::GetWindowDrawList()->AddCircle(c,
                                                      static_cast<float>(paintTool_.modelRadius / perPixel),
                                                      IM_COL32(255, 255, 255, 200), 48, 1.5f);
            }
        });
    }
    if (!painting || boxing) return;
    if (paintTool_.tool == PaintTool::FillRegion) {
        if (events.leftPressed && hit && !ImGui::GetIO().KeyAlt)
            session.attempt("Fill region", [&] {
                const std::vector<double> start = paintStartWeights();
                fillVertices(connectedRegion(surface, start, hitVertex, paintTool_.fillTolerance),
                             "Fill region");
            });
        return;
    }
    paintBrush(events, hit);
}

void EditorUi::paintBrush(const ViewportEvents& events, const std::optional<RayHit>& hit) {
    const PaintSurface& surface = paintSurface_;
    const OrbitCamera& camera = mainView_.camera;
    if (events.leftPressed && !ImGui::GetIO().KeyAlt) {
        strokeActive_ = true;
        strokeStart_ = paintStartWeights();
        strokeWeights_ = strokeStart_;
        lastDab_.reset();
    }
    if (!strokeActive_) return;
    // Dabs are spaced along the stroke (a quarter radius apart), so painting does not depend on
    // the frame rate.
    const double radius = paintTool_.modelRadius;
    const bool farEnough = !lastDab_ || (hit && (hit->point - *lastDab_).norm() >= 0.25 * radius);
    if (events.leftDown && hit && farEnough && radius > 0.0) {
        WeightBrush brush;
        brush.radius = radius;
        brush.strength = brush_.strength;
        brush.falloff = static_cast<Falloff>(brush_.falloff);
        brush.mode = static_cast<BrushMode>(brush_.mode);
        brush.symmetric = brush_.symmetric;
        brush.mirrorX = surface.mirrorX();
        if (brush_.frontFacesOnly) {
            const glm::vec3 eye = camera.eye();
            brush.eye = Vec3(eye.x, eye.y, eye.z);
        }
        session.attempt("Paint", [&] { applyBrushDab(surface, brush, hit->point, strokeWeights_); });
        lastDab_ = hit->point;
        weightsKey_.clear();
    }
    if (events.leftReleased) {
        strokeActive_ = false;
        lastDab_.reset();
        if (strokeWeights_ != strokeStart_)
            session.attempt("Paint stroke",
                            [&] { session.setPaintedWeights(strokeWeights_, "Paint stroke"); });
        weightsKey_.clear();
    }
}

void EditorUi::paintBoxSelection(const ViewportEvents& events) {
    const ImGuiIO& io = ImGui::GetIO();
    if (events.leftPressed && !io.KeyAlt) paintTool_.boxStart = io.MousePos;
    if (!paintTool_.boxStart) return;
    const ImVec2 a = *paintTool_.boxStart, b = io.MousePos;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                        ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), IM_COL32(90, 160, 255, 40));
    draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                  ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), IM_COL32(90, 160, 255, 220));
    if (!events.leftReleased) return;
    paintTool_.boxStart.reset();
    const PaintSurface& surface = paintSurface_;
    const OrbitCamera& camera = mainView_.camera;
    const float width = events.imageMax.x - events.imageMin.x, height = events.imageMax.y - events.imageMin.y;
    auto ndcX = [&](float x) { return 2.0 * (x - events.imageMin.x) / width - 1.0; };
    auto ndcY = [&](float y) { return 1.0 - 2.0 * (y - events.imageMin.y) / height; };
    const glm::mat4 viewProjection = camera.projection(events.aspect) * camera.view();
    std::array<double, 16> matrix{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix[static_cast<std::size_t>(4 * c + r)] = viewProjection[c][r];
    std::optional<Vec3> eye;
    bool flipped = false;
    if (brush_.frontFacesOnly) {
        const glm::vec3 e = camera.eye();
        eye = Vec3(e.x, e.y, e.z);
        // The winding under the box's centre tells which way "facing the camera" points.
        const Ray ray = camera.rayThrough(static_cast<float>(ndcX(0.5f * (a.x + b.x))),
                                          static_cast<float>(ndcY(0.5f * (a.y + b.y))), events.aspect);
        if (const auto hit = intersectRay(surface.positions(), surface.triangles(),
                                          Vec3(ray.origin.x, ray.origin.y, ray.origin.z),
                                          Vec3(ray.direction.x, ray.direction.y, ray.direction.z)))
            flipped = facesAwayAt(surface, hit->point, *eye);
    }
    auto boxed =
        verticesInRectangle(surface, matrix, {ndcX(a.x), ndcY(a.y), ndcX(b.x), ndcY(b.y)}, eye, flipped);
    // Facing the camera is not enough: only what the box shows (not the far lip behind the near one).
    if (eye) boxed = visibleVertices(surface, boxed, matrix, *eye);
    std::vector<std::uint32_t> result;
    auto& selection = paintTool_.selection;
    if (io.KeyShift)
        std::set_union(selection.begin(), selection.end(), boxed.begin(), boxed.end(),
                       std::back_inserter(result));
    else if (io.KeyCtrl)
        std::set_difference(selection.begin(), selection.end(), boxed.begin(), boxed.end(),
                            std::back_inserter(result));
    else
        result = boxed;
    selection = std::move(result);
    const glm::vec3 e = camera.eye();
    paintTool_.boxEye = Vec3(e.x, e.y, e.z);
}

std::size_t EditorUi::selectedHidden() const {
    const auto& selection = paintTool_.selection;
    if (!paintTool_.boxEye || selection.empty()) return 0;
    const Vec3& eye = *paintTool_.boxEye;
    if (selectionHidden_ && selectionHidden_->selection == selection && selectionHidden_->eye == eye)
        return selectionHidden_->hidden;
    // The picking ray from the eye towards each vertex: hidden when it first hits a triangle that
    // does not hold the vertex, short of it (independent of the selection's own visibility test).
    std::size_t hidden = 0;
    const auto& positions = paintSurface_.positions();
    const auto& triangles = paintSurface_.triangles();
    for (const std::uint32_t v : selection) {
        const Vec3 towards = positions[v] - eye;
        const double distance = towards.norm();
        const auto hit = intersectRay(positions, triangles, eye, towards / distance);
        if (!hit || hit->distance >= distance * (1.0 - 1e-6)) continue;
        const Triangle& t = triangles[hit->triangle];
        if (t[0] != v && t[1] != v && t[2] != v) ++hidden;
    }
    selectionHidden_ = HiddenCount{selection, eye, hidden};
    return hidden;
}

void EditorUi::drawSelection(const ViewportEvents& events) {
    if (paintTool_.selection.empty()) return;
    const OrbitCamera& camera = mainView_.camera;
    const glm::mat4 viewProjection = camera.projection(events.aspect) * camera.view();
    const auto& positions = paintSurface_.positions();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(events.imageMin, events.imageMax, true);
    for (const std::uint32_t v : paintTool_.selection) {
        const Vec3& p = positions[v];
        const glm::vec4 clip = viewProjection * glm::vec4(static_cast<float>(p[0]), static_cast<float>(p[1]),
                                                          static_cast<float>(p[2]), 1.0f);
        if (clip.w <= 0.0f) continue;
        const float x =
            events.imageMin.x + (clip.x / clip.w * 0.5f + 0.5f) * (events.imageMax.x - events.imageMin.x);
        const float y =
            events.imageMin.y + (0.5f - clip.y / clip.w * 0.5f) * (events.imageMax.y - events.imageMin.y);
        draw->AddRectFilled(ImVec2(x - 1.5f, y - 1.5f), ImVec2(x + 1.5f, y + 1.5f),
                            IM_COL32(255, 170, 40, 230));
    }
    draw->PopClipRect();
}

nlohmann::json EditorUi::paintSummary() const {
    static const char* const kTools[] = {"brush", "fill", "select"};
    // Mean painted weight of the vertices facing the camera and of those facing away (the front
    // faces only check: a stroke on the face must leave the back of the head alone).
    double front = 0.0, back = 0.0;
    std::size_t frontCount = 0, backCount = 0;
    const auto& painted = session.document().weights.paintedOrEmpty();
    if (painted.size() == paintSurface_.vertexCount()) {
        const glm::vec3 e = mainView_.camera.eye();
        const Vec3 eye(e.x, e.y, e.z);
        for (std::size_t v = 0; v < painted.size(); ++v) {
            const double facing =
                OpenMesh::dot(paintSurface_.normals()[v], eye - paintSurface_.positions()[v]);
            (facing >= 0.0 ? front : back) += painted[v];
            ++(facing >= 0.0 ? frontCount : backCount);
        }
    }
    return {{"tool", kTools[static_cast<int>(paintTool_.tool)]},
            {"radius_unit", std::string(radiusUnitName(brush_.radius.unit))},
            {"radius_value", brush_.radius.value},
            {"radius_model", paintTool_.modelRadius},
            {"front_faces_only", brush_.frontFacesOnly},
            {"selected", paintTool_.selection.size()},
            {"selected_hidden", selectedHidden()},
            {"vertices", paintSurface_.vertexCount()},
            {"fill_value", paintTool_.fillValue},
            {"readout", paintTool_.readout ? nlohmann::json(*paintTool_.readout) : nlohmann::json()},
            {"front_mean", frontCount ? front / static_cast<double>(frontCount) : 0.0},
            {"back_mean", backCount ? back / static_cast<double>(backCount) : 0.0}};
}

void EditorUi::updateScalars() {
    const VisemeSet* set = session.visemes();
    // Metric weights on the viseme mesh (the Weights panel).
    if (set && activePanel_ == Panel::Weights) {
        const std::string key = "w" + std::to_string(session.inputsGeneration()) + (strokeActive_ ? "s" : "");
        if (key != weightsKey_ || strokeActive_) {
            std::vector<double> w;
            if (strokeActive_) {
                w = strokeWeights_;
            } else {
                session.attempt("Weights", [&] { w = session.weights(); });
                shownWeights_ = w;
            }
            visemeMesh_.setScalars(normalised(w, maxOf(w)));
            weightsKey_ = key;
        }
    }
    // Merge error of the selected viseme on the reduced view.
    const Grouping* grouping = session.currentGrouping();
    if (set && grouping && activePanel_ == Panel::Reduction) {
        const int selected = std::max(session.selectedViseme, 0);
        const std::string key = std::to_string(selected) + ":" + std::to_string(session.inputsGeneration()) +
                                ":" + std::to_string(grouping->groups.size());
        if (key != errorKey_) {
            session.attempt("Error map", [&] {
                const ReducedModel* merged = session.reducedModel();
                if (!merged) return;
                const std::vector<double> w = session.weights();
                double scale = 0.0;
                std::vector<double> shown;
                const auto measure = [&](int member, const std::vector<Vec3>& shape) {
                    auto errors =
                        vertexErrors(set->visemes[static_cast<std::size_t>(member)].positions, shape, w);
                    scale = std::max(scale, maxOf(errors));
                    if (member == selected) shown = std::move(errors);
                };
                for (std::size_t g = 0; g < grouping->groups.size(); ++g)
                    for (int member : grouping->groups[g]) measure(member, merged->keys[g].positions);
                // A resting viseme is shown as the neutral: its error is its distance from it.
                for (int member : grouping->rest) measure(member, set->neutral.positions);
                // Square root: distances read better than squared distances on a colour ramp. The
                // legend reads in distance for a vertex of the largest weight (sqrt(w) d / sqrt(w_max)).
                for (double& e : shown) e = std::sqrt(e);
                mergedMesh_.setScalars(normalised(shown, std::sqrt(scale)));
                const double maxWeight = maxOf(w);
                errorLegendMax_ = maxWeight > 0.0 ? std::sqrt(scale / maxWeight) : 0.0;
            });
            errorKey_ = key;
        }
    }
    // Influence of the selected analytic field on the face.
    const FaceModel& model = session.face();
    if (model.cascade && selectedStage_ >= 0 &&
        selectedStage_ < static_cast<int>(model.cascade->stages.size())) {
        const auto& influences =
            model.cascade->stages[static_cast<std::size_t>(selectedStage_)].field.influences;
        const std::string key = std::to_string(reinterpret_cast<std::uintptr_t>(model.cascade.get())) + ":" +
                                std::to_string(selectedStage_) + ":" + std::to_string(selectedInfluence_);
        if (key != influenceKey_ && selectedInfluence_ < static_cast<int>(influences.size())) {
            const InfluenceField& field = influences[static_cast<std::size_t>(selectedInfluence_)];
            std::vector<float> values;
            values.reserve(model.domain->uvs.size());
            for (const Vec2& uv : model.domain->uvs)
                values.push_back(0.1f + 0.9f * static_cast<float>(field.weight(uv[0], uv[1])));
            faceMesh_.setScalars(values);
            influenceKey_ = key;
        }
    }
}

} // namespace vl::ui
