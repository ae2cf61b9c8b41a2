#include "core/paint/WeightBrush.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <map>

namespace vl {
namespace {

// The factor of every vertex a dab at `centre` reaches (seen from `eye` when front faces only).
void addDab(const PaintSurface& surface, const WeightBrush& brush, const Vec3& centre,
            const std::optional<Vec3>& eye, std::map<std::uint32_t, double>& factors) {
    const auto& positions = surface.positions();
    const double r2 = brush.radius * brush.radius;
    auto inReach = [&](std::uint32_t v) { return (positions[v] - centre).sqrnorm() < r2; };
    std::vector<std::uint32_t> reached;
    if (!eye) {
        for (std::size_t v = 0; v < positions.size(); ++v)
            if (inReach(static_cast<std::uint32_t>(v))) reached.push_back(static_cast<std::uint32_t>(v));
    } else if (!positions.empty()) {
        // Flood over edges from the vertex under the brush, through vertices in the ball that face
        // the eye on the side that vertex does.
        const std::uint32_t seed = surface.nearestVertex(centre);
        const auto& normals = surface.normals();
        const double side = OpenMesh::dot(normals[seed], *eye - positions[seed]) >= 0.0 ? 1.0 : -1.0;
        auto facing = [&](std::uint32_t v) {
            return side * OpenMesh::dot(normals[v], *eye - positions[v]) > 0.0;
        };
        if (inReach(seed) && facing(seed)) {
            std::vector<char> seen(positions.size(), 0);
            std::vector<std::uint32_t> stack = {seed};
            seen[seed] = 1;
            while (!stack.empty()) {
                const std::uint32_t v = stack.back();
                stack.pop_back();
                reached.push_back(v);
                for (const std::uint32_t w : surface.neighbours(v))
                    if (!seen[w] && inReach(w) && facing(w)) {
                        seen[w] = 1;
                        stack.push_back(w);
                    }
            }
        }
    }
    for (const std::uint32_t v : reached) {
        const double d = (positions[v] - centre).norm();
        const double factor = brush.strength * falloffWeight(brush.falloff, d / brush.radius);
        if (factor <= 0.0) continue;
        double& slot = factors[v];
        slot = std::max(slot, factor);
    }
}

} // namespace

std::vector<std::pair<std::uint32_t, double>> brushFootprint(const PaintSurface& surface,
                                                             const WeightBrush& brush, const Vec3& centre) {
    if (!(brush.radius > 0.0))
        throwInputError("brush", "radius must be > 0, got " + formatDouble(brush.radius));
    if (!(brush.strength >= 0.0 && brush.strength <= 1.0))
        throwInputError("brush", "strength must be in [0, 1], got " + formatDouble(brush.strength));
    std::map<std::uint32_t, double> factors;
    addDab(surface, brush, centre, brush.eye, factors);
    if (brush.symmetric) {
        auto mirror = [&](Vec3 p) {
            p[0] = 2.0 * brush.mirrorX - p[0];
            return p;
        };
        addDab(surface, brush, mirror(centre),
               brush.eye ? std::optional<Vec3>(mirror(*brush.eye)) : std::nullopt, factors);
    }
    return {factors.begin(), factors.end()};
}

void applyBrushDab(const PaintSurface& surface, const WeightBrush& brush, const Vec3& centre,
                   std::vector<double>& weights) {
    if (weights.size() != surface.vertexCount())
        throwInputError("brush", "weights has " + std::to_string(weights.size()) + " entries for " +
                                     std::to_string(surface.vertexCount()) + " vertices");
    const auto footprint = brushFootprint(surface, brush, centre);
    if (brush.mode != BrushMode::Smooth) {
        const double sign = brush.mode == BrushMode::Add ? 1.0 : -1.0;
        for (const auto& [v, factor] : footprint)
            weights[v] = std::clamp(weights[v] + sign * factor, 0.0, 1.0);
        return;
    }
    // Neighbour means from the weights before the dab.
    const std::vector<double> before = weights;
    for (const auto& [v, factor] : footprint) {
        const auto around = surface.neighbours(v);
        if (around.empty()) continue;
        double sum = 0.0;
        for (const std::uint32_t w : around) sum += before[w];
        const double mean = sum / static_cast<double>(around.size());
        weights[v] = std::clamp(before[v] + factor * (mean - before[v]), 0.0, 1.0);
    }
}

void applyBrushDab(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                   const WeightBrush& brush, const Vec3& centre, std::vector<double>& weights) {
    applyBrushDab(PaintSurface(positions, triangles), brush, centre, weights);
}

} // namespace vl
