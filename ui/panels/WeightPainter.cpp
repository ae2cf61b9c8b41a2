#include "ui/panels/WeightPainter.h"

#include "ui/panels/BrushCursor.h"

#include "core/paint/PaintRegions.h"
#include "core/paint/VertexVisibility.h"
#include "core/paint/WeightBrush.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>

namespace vl::ui {
namespace {

double largestOf(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

} // namespace

const PaintSurface& WeightPainter::surface() {
    const auto& set = session_.document().visemes;
    if (set != surfaceSet_) {
        surfaceSet_ = set;
        surface_ = set ? PaintSurface(set->neutral.positions, set->neutral.triangles) : PaintSurface();
        tools.selection.clear(); // vertex indices of another mesh
    }
    return surface_;
}

std::vector<double> WeightPainter::startWeights() const {
    // Edits start from the weights shown (uniform, area or painted), scaled to [0, 1].
    const auto& weights = session_.document().weights;
    return weightsForPainting(weights.mode, session_.visemes()->neutral, weights.paintedOrEmpty());
}

void WeightPainter::fill(const std::vector<std::uint32_t>& vertices, const char* action) {
    if (vertices.empty()) {
        session_.error(std::string(action) + ": nothing to fill");
        return;
    }
    session_.attempt(action, [&] {
        session_.weights().setPainted(filled(startWeights(), vertices, tools.fillValue), action);
        char text[160];
        std::snprintf(text, sizeof text, "%s: %zu vertices set to %.2f", action, vertices.size(),
                      static_cast<double>(tools.fillValue));
        session_.info(text);
    });
}

void WeightPainter::paint(const ViewportEvents& events) {
    const VisemeSet* set = session_.visemes();
    tools.readout.reset();
    if (!set) return;
    const PaintSurface& surface = this->surface();
    const bool painting = brush.enabled;
    if (painting) drawSelection(events);
    const bool boxing = painting && tools.tool == PaintTool::SelectBox;
    if (boxing) boxSelection(events);
    if (!events.hovered && !strokeActive_) return;
    const OrbitCamera& camera = view_.camera;
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
        tools.readout = valueAt(surface, shown, hit->triangle, hit->barycentric);
        tools.readoutVertex = hitVertex;
        const double largest = largestOf(shown);
        char text[128];
        std::snprintf(text, sizeof text, "weight %.3g  (%.0f%% of the largest; vertex %u)", *tools.readout,
                      largest > 0.0 ? 100.0 * *tools.readout / largest : 0.0, hitVertex);
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
        session_.attempt("Brush", [&] {
            const double perPixel = unitsPerPixelAt(camera, events, hit->point);
            tools.modelRadius = modelRadius(brush.radius, surface.size(), perPixel);
            tools.unitsPerPixel = perPixel;
            if (events.hovered && brush.enabled && tools.tool == PaintTool::Brush)
                drawBrushCircle(camera, events, hit->point, tools.modelRadius, perPixel,
                                IM_COL32(255, 255, 255, 200));
        });
    }
    if (!painting || boxing) return;
    if (tools.tool == PaintTool::FillRegion) {
        if (events.leftPressed && hit && !ImGui::GetIO().KeyAlt)
            session_.attempt("Fill region", [&] {
                const std::vector<double> start = startWeights();
                fill(connectedRegion(surface, start, hitVertex, tools.fillTolerance), "Fill region");
            });
        return;
    }
    brushStroke(events, hit);
}

void WeightPainter::brushStroke(const ViewportEvents& events, const std::optional<RayHit>& hit) {
    const PaintSurface& surface = surface_;
    const OrbitCamera& camera = view_.camera;
    if (events.leftPressed && !ImGui::GetIO().KeyAlt) {
        strokeActive_ = true;
        strokeStart_ = startWeights();
        strokeWeights_ = strokeStart_;
        lastDab_.reset();
    }
    if (!strokeActive_) return;
    // Dabs are spaced along the stroke (a quarter radius apart), so painting does not depend on
    // the frame rate.
    const double radius = tools.modelRadius;
    const bool farEnough = !lastDab_ || (hit && (hit->point - *lastDab_).norm() >= 0.25 * radius);
    if (events.leftDown && hit && farEnough && radius > 0.0) {
        WeightBrush dab;
        dab.radius = radius;
        dab.strength = brush.strength;
        dab.falloff = static_cast<Falloff>(brush.falloff);
        dab.mode = static_cast<BrushMode>(brush.mode);
        dab.symmetric = brush.symmetric;
        dab.mirrorX = surface.mirrorX();
        if (brush.frontFacesOnly) {
            const glm::vec3 eye = camera.eye();
            dab.eye = Vec3(eye.x, eye.y, eye.z);
        }
        session_.attempt("Paint", [&] { applyBrushDab(surface, dab, hit->point, strokeWeights_); });
        lastDab_ = hit->point;
    }
    if (events.leftReleased) {
        strokeActive_ = false;
        lastDab_.reset();
        if (strokeWeights_ != strokeStart_)
            session_.attempt("Paint stroke",
                             [&] { session_.weights().setPainted(strokeWeights_, "Paint stroke"); });
    }
}

void WeightPainter::boxSelection(const ViewportEvents& events) {
    const ImGuiIO& io = ImGui::GetIO();
    if (events.leftPressed && !io.KeyAlt) tools.boxStart = io.MousePos;
    if (!tools.boxStart) return;
    const ImVec2 a = *tools.boxStart, b = io.MousePos;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                        ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), IM_COL32(90, 160, 255, 40));
    draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                  ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), IM_COL32(90, 160, 255, 220));
    if (!events.leftReleased) return;
    tools.boxStart.reset();
    const PaintSurface& surface = surface_;
    const OrbitCamera& camera = view_.camera;
    const float width = events.imageMax.x - events.imageMin.x, height = events.imageMax.y - events.imageMin.y;
    auto ndcX = [&](float x) { return 2.0 * (x - events.imageMin.x) / width - 1.0; };
    auto ndcY = [&](float y) { return 1.0 - 2.0 * (y - events.imageMin.y) / height; };
    const glm::mat4 viewProjection = camera.projection(events.aspect) * camera.view();
    std::array<double, 16> matrix{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix[static_cast<std::size_t>(4 * c + r)] = viewProjection[c][r];
    std::optional<Vec3> eye;
    bool flipped = false;
    if (brush.frontFacesOnly) {
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
    auto& selection = tools.selection;
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
    tools.boxEye = Vec3(e.x, e.y, e.z);
}

std::size_t WeightPainter::selectedHidden() const {
    const auto& selection = tools.selection;
    if (!tools.boxEye || selection.empty()) return 0;
    const Vec3& eye = *tools.boxEye;
    if (selectionHidden_ && selectionHidden_->selection == selection && selectionHidden_->eye == eye)
        return selectionHidden_->hidden;
    // The picking ray from the eye towards each vertex: hidden when it first hits a triangle that
    // does not hold the vertex, short of it (independent of the selection's own visibility test).
    std::size_t hidden = 0;
    const auto& positions = surface_.positions();
    const auto& triangles = surface_.triangles();
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

void WeightPainter::drawSelection(const ViewportEvents& events) {
    if (tools.selection.empty()) return;
    const OrbitCamera& camera = view_.camera;
    const glm::mat4 viewProjection = camera.projection(events.aspect) * camera.view();
    const auto& positions = surface_.positions();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(events.imageMin, events.imageMax, true);
    for (const std::uint32_t v : tools.selection) {
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

nlohmann::json WeightPainter::probe() const {
    static const char* const kTools[] = {"brush", "fill", "select"};
    // Mean painted weight of the vertices facing the camera and of those facing away (the front
    // faces only check: a stroke on the face must leave the back of the head alone).
    double front = 0.0, back = 0.0;
    std::size_t frontCount = 0, backCount = 0;
    const auto& painted = session_.document().weights.paintedOrEmpty();
    if (painted.size() == surface_.vertexCount()) {
        const glm::vec3 e = view_.camera.eye();
        const Vec3 eye(e.x, e.y, e.z);
        for (std::size_t v = 0; v < painted.size(); ++v) {
            const double facing = OpenMesh::dot(surface_.normals()[v], eye - surface_.positions()[v]);
            (facing >= 0.0 ? front : back) += painted[v];
            ++(facing >= 0.0 ? frontCount : backCount);
        }
    }
    return {{"tool", kTools[static_cast<int>(tools.tool)]},
            {"radius_unit", std::string(radiusUnitName(brush.radius.unit))},
            {"radius_value", brush.radius.value},
            {"radius_model", tools.modelRadius},
            {"front_faces_only", brush.frontFacesOnly},
            {"selected", tools.selection.size()},
            {"selected_hidden", selectedHidden()},
            {"vertices", surface_.vertexCount()},
            {"fill_value", tools.fillValue},
            {"readout", tools.readout ? nlohmann::json(*tools.readout) : nlohmann::json()},
            {"front_mean", frontCount ? front / static_cast<double>(frontCount) : 0.0},
            {"back_mean", backCount ? back / static_cast<double>(backCount) : 0.0}};
}

void WeightPainter::resizeBrush(bool grow) {
    const bool pixels = brush.radius.unit == RadiusUnit::ScreenPixels;
    const double factor = grow ? 1.15 : 1.0 / 1.15;
    brush.radius.value = std::clamp(brush.radius.value * factor, pixels ? 2.0 : 0.5, pixels ? 300.0 : 50.0);
}

} // namespace vl::ui
