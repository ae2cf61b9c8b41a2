#include "core/reduce/VisemeErrors.h"

#include <algorithm>
#include <cmath>

namespace vl {

std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> frequencies, std::span<const double> weights,
                                      std::span<const int> groupOf) {
    const std::size_t n = shapes.size(), vertices = weights.size();
    const int keys = groupOf.empty() ? 0 : 1 + *std::max_element(groupOf.begin(), groupOf.end());
    // The keys' shapes, each once.
    std::vector<std::vector<Vec3>> keyShapes(static_cast<std::size_t>(std::max(keys, 0)),
                                             std::vector<Vec3>(vertices, Vec3(0, 0, 0)));
    std::vector<double> total(keyShapes.size(), 0.0), count(keyShapes.size(), 0.0);
    for (std::size_t i = 0; i < n; ++i)
        if (groupOf[i] >= 0) {
            total[static_cast<std::size_t>(groupOf[i])] += frequencies[i];
            count[static_cast<std::size_t>(groupOf[i])] += 1;
        }
    for (std::size_t i = 0; i < n; ++i) {
        if (groupOf[i] < 0) continue;
        const auto g = static_cast<std::size_t>(groupOf[i]);
        const double share = total[g] > 0 ? frequencies[i] / total[g] : 1.0 / count[g];
        for (std::size_t v = 0; v < vertices; ++v) keyShapes[g][v] += share * shapes[i][v];
    }
    return visemeErrors(shapes, rest, weights, groupOf, ShapeView(keyShapes));
}

std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> weights, std::span<const int> groupOf,
                                      const ShapeView& keyShapes) {
    const std::size_t n = shapes.size(), vertices = weights.size();
    std::vector<VisemeError> errors(n);
    for (std::size_t i = 0; i < n; ++i) {
        double weightSum = 0, squares = 0;
        for (std::size_t v = 0; v < vertices; ++v) {
            if (!(weights[v] > 0)) continue;
            const Vec3& shown = groupOf[i] < 0 ? rest[v] : keyShapes[static_cast<std::size_t>(groupOf[i])][v];
            const double d = (shapes[i][v] - shown).norm();
            errors[i].max = std::max(errors[i].max, d);
            squares += weights[v] * d * d;
            weightSum += weights[v];
            if (!rest.empty())
                errors[i].largestDisplacement =
                    std::max(errors[i].largestDisplacement, (shapes[i][v] - rest[v]).norm());
        }
        errors[i].rms = weightSum > 0 ? std::sqrt(squares / weightSum) : 0.0;
    }
    return errors;
}

} // namespace vl
