#include "core/paint/WeightBrush.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <map>

namespace vl {
namespace {

void addDab(std::span<const Vec3> positions, const WeightBrush& brush, const Vec3& centre,
            std::map<std::uint32_t, double>& factors) {
    const double r2 = brush.radius * brush.radius;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const double d2 = (positions[i] - centre).sqrnorm();
        if (d2 >= r2) continue;
        const double factor = brush.strength * falloffWeight(brush.falloff, std::sqrt(d2) / brush.radius);
        if (factor <= 0.0) continue;
        double& slot = factors[static_cast<std::uint32_t>(i)];
        slot = std::max(slot, factor);
    }
}

} // namespace

std::vector<std::pair<std::uint32_t, double>> brushFootprint(std::span<const Vec3> positions,
                                                             const WeightBrush& brush, const Vec3& centre) {
    if (!(brush.radius > 0.0))
        throwInputError("brush", "radius must be > 0, got " + formatDouble(brush.radius));
    if (!(brush.strength >= 0.0 && brush.strength <= 1.0))
        throwInputError("brush", "strength must be in [0, 1], got " + formatDouble(brush.strength));
    std::map<std::uint32_t, double> factors;
    addDab(positions, brush, centre, factors);
    if (brush.symmetric) {
        Vec3 mirrored = centre;
        mirrored[0] = 2.0 * brush.mirrorX - centre[0];
        addDab(positions, brush, mirrored, factors);
    }
    return {factors.begin(), factors.end()};
}

void applyBrushDab(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                   const WeightBrush& brush, const Vec3& centre, std::vector<double>& weights) {
    if (weights.size() != positions.size())
        throwInputError("brush", "weights has " + std::to_string(weights.size()) + " entries for " +
                                     std::to_string(positions.size()) + " vertices");
    const auto footprint = brushFootprint(positions, brush, centre);
    if (brush.mode != BrushMode::Smooth) {
        const double sign = brush.mode == BrushMode::Add ? 1.0 : -1.0;
        for (const auto& [v, factor] : footprint)
            weights[v] = std::clamp(weights[v] + sign * factor, 0.0, 1.0);
        return;
    }
    // Neighbour means from the weights before the dab.
    std::vector<double> sum(positions.size(), 0.0);
    std::vector<int> count(positions.size(), 0);
    for (const Triangle& t : triangles)
        for (int a = 0; a < 3; ++a) {
            const std::uint32_t v = t[static_cast<std::size_t>(a)];
            const std::uint32_t w = t[static_cast<std::size_t>((a + 1) % 3)];
            sum[v] += weights[w];
            sum[w] += weights[v];
            ++count[v];
            ++count[w];
        }
    const std::vector<double> before = weights;
    for (const auto& [v, factor] : footprint) {
        if (count[v] == 0) continue;
        const double mean = sum[v] / count[v];
        weights[v] = std::clamp(before[v] + factor * (mean - before[v]), 0.0, 1.0);
    }
}

} // namespace vl
