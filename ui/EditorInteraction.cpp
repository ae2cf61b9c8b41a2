// Per-frame interaction of the editor's views: playback of phoneme sequences, weight painting and
// the per-vertex scalars (weights, merge errors, field influence) shown through the colour map.
#include "ui/EditorUi.h"

#include "core/inspect/VertexErrors.h"
#include "core/paint/RayPick.h"
#include "core/paint/WeightBrush.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

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

std::vector<int> EditorUi::playbackKeys() const {
    std::vector<int> keys;
    const VisemeSet* set = session.visemes();
    if (!set) return keys;
    std::istringstream tokens(playback_.sequence);
    std::string token;
    while (tokens >> token) {
        const std::string* viaMap = session.document().frequencies.map.visemeOf(token);
        const int index = set->find(viaMap ? *viaMap : token);
        if (index >= 0) keys.push_back(index);
    }
    if (keys.empty())
        for (std::size_t i = 0; i < set->size(); ++i) keys.push_back(static_cast<int>(i));
    return keys;
}

std::vector<float> EditorUi::playbackWeights(bool reduced) const {
    const std::vector<int> keys = playbackKeys();
    const Grouping* grouping = session.currentGrouping();
    std::vector<float> weights(reduced ? (grouping ? grouping->groups.size() : 0) : session.visemeCount(),
                               0.0f);
    if (keys.empty() || weights.empty()) return weights;
    const double t = playback_.time / playback_.secondsPerKey;
    const auto k = static_cast<std::size_t>(std::floor(t)) % keys.size();
    const double a = t - std::floor(t);
    const float blend = static_cast<float>(a * a * (3.0 - 2.0 * a)); // ease between keys
    auto slot = [&](int viseme) -> float& {
        if (!reduced) return weights[static_cast<std::size_t>(viseme)];
        for (std::size_t g = 0; g < grouping->groups.size(); ++g)
            for (int member : grouping->groups[g])
                if (member == viseme) return weights[g];
        return weights[0];
    };
    slot(keys[k]) += 1.0f - blend;
    slot(keys[(k + 1) % keys.size()]) += blend;
    return weights;
}

void EditorUi::paint(const ViewportEvents& events) {
    const VisemeSet* set = session.visemes();
    if (!set) return;
    if (events.leftPressed && !ImGui::GetIO().KeyAlt) {
        strokeActive_ = true;
        // The stroke starts from the weights shown (uniform, area or painted), scaled to [0, 1].
        const auto& weights = session.document().weights;
        strokeStart_ = weightsForPainting(weights.mode, set->neutral, weights.paintedOrEmpty());
        strokeWeights_ = strokeStart_;
        lastDab_.reset();
    }
    if (!events.hovered && !strokeActive_) return;
    const Ray ray = mainView_.camera.rayThrough(events.ndc.x, events.ndc.y, events.aspect);
    const auto hit = intersectRay(set->neutral.positions, set->neutral.triangles,
                                  Vec3(ray.origin.x, ray.origin.y, ray.origin.z),
                                  Vec3(ray.direction.x, ray.direction.y, ray.direction.z));
    if (hit && events.hovered) {
        // Brush outline: the radius at the hit point, projected to the screen.
        const glm::mat4 viewProjection = mainView_.camera.projection(events.aspect) * mainView_.camera.view();
        const glm::mat4 view = mainView_.camera.view();
        const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
        const glm::vec3 centre(static_cast<float>(hit->point[0]), static_cast<float>(hit->point[1]),
                               static_cast<float>(hit->point[2]));
        auto toScreen = [&](const glm::vec3& p) {
            const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
            return ImVec2(events.imageMin.x +
                              (clip.x / clip.w * 0.5f + 0.5f) * (events.imageMax.x - events.imageMin.x),
                          events.imageMin.y +
                              (0.5f - clip.y / clip.w * 0.5f) * (events.imageMax.y - events.imageMin.y));
        };
        const ImVec2 c = toScreen(centre);
        const ImVec2 edge = toScreen(centre + right * brush_.radius);
        ImGui::GetWindowDrawList()->AddCircle(c, std::abs(edge.x - c.x), IM_COL32(255, 255, 255, 200), 48,
                                              1.5f);
    }
    if (!strokeActive_) return;
    // Dabs are spaced along the stroke (a quarter radius apart), so painting does not depend on
    // the frame rate.
    const bool farEnough = !lastDab_ || (hit && (hit->point - *lastDab_).norm() >= 0.25 * brush_.radius);
    if (events.leftDown && hit && farEnough) {
        Vec3 lo, hi;
        bounds(set->neutral.positions, lo, hi);
        WeightBrush brush;
        brush.radius = brush_.radius;
        brush.strength = brush_.strength;
        brush.falloff = static_cast<Falloff>(brush_.falloff);
        brush.mode = static_cast<BrushMode>(brush_.mode);
        brush.symmetric = brush_.symmetric;
        brush.mirrorX = 0.5 * (lo[0] + hi[0]);
        session.attempt("Paint", [&] {
            applyBrushDab(set->neutral.positions, set->neutral.triangles, brush, hit->point, strokeWeights_);
        });
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

void EditorUi::updateScalars() {
    const VisemeSet* set = session.visemes();
    // Metric weights on the viseme mesh (the Weights panel).
    if (set && activePanel_ == Panel::Weights) {
        const std::string key = "w" + std::to_string(session.inputsGeneration()) + (strokeActive_ ? "s" : "");
        if (key != weightsKey_ || strokeActive_) {
            std::vector<double> w;
            if (strokeActive_)
                w = strokeWeights_;
            else
                session.attempt("Weights", [&] { w = session.weights(); });
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
                const auto& merged = session.mergedShapes();
                const std::vector<double> w = session.weights();
                double scale = 0.0;
                std::vector<double> shown;
                for (std::size_t g = 0; g < grouping->groups.size(); ++g)
                    for (int member : grouping->groups[g]) {
                        auto errors = vertexErrors(set->visemes[static_cast<std::size_t>(member)].positions,
                                                   merged[g], w);
                        scale = std::max(scale, maxOf(errors));
                        if (member == selected) shown = std::move(errors);
                    }
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
