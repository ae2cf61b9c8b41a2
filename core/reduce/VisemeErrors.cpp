#include "core/reduce/VisemeErrors.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

VisemeError errorOf(ShapeRow shape, ShapeRow shown, std::span<const Vec3> rest,
                    std::span<const double> weights) {
    VisemeError error;
    double weightSum = 0, squares = 0;
    for (std::size_t v = 0; v < weights.size(); ++v) {
        if (!(weights[v] > 0)) continue;
        const Vec3 a = shape[v];
        const double d = (a - shown[v]).norm();
        error.max = std::max(error.max, d);
        squares += weights[v] * d * d;
        weightSum += weights[v];
        if (!rest.empty())
            error.largestDisplacement = std::max(error.largestDisplacement, (a - rest[v]).norm());
    }
    error.rms = weightSum > 0 ? std::sqrt(squares / weightSum) : 0.0;
    return error;
}

} // namespace

std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> frequencies, std::span<const double> weights,
                                      std::span<const int> groupOf) {
    const std::size_t n = shapes.size(), vertices = weights.size();
    const int keys = groupOf.empty() ? 0 : 1 + *std::max_element(groupOf.begin(), groupOf.end());
    std::vector<VisemeError> errors(n);
    for (std::size_t i = 0; i < n; ++i)
        if (groupOf[i] < 0) errors[i] = errorOf(shapes[i], rest, rest, weights);
    std::vector<Vec3> key(vertices);
    for (int g = 0; g < keys; ++g) {
        double total = 0, count = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (groupOf[i] == g) total += frequencies[i], count += 1;
        if (count == 0) continue;
        std::fill(key.begin(), key.end(), Vec3(0, 0, 0));
        for (std::size_t i = 0; i < n; ++i) {
            if (groupOf[i] != g) continue;
            const double share = total > 0 ? frequencies[i] / total : 1.0 / count;
            const ShapeRow shape = shapes[i];
            for (std::size_t v = 0; v < vertices; ++v) key[v] += share * shape[v];
        }
        for (std::size_t i = 0; i < n; ++i)
            if (groupOf[i] == g) errors[i] = errorOf(shapes[i], key, rest, weights);
    }
    return errors;
}

std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> weights, std::span<const int> groupOf,
                                      const ShapeView& keyShapes) {
    std::vector<VisemeError> errors(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i)
        errors[i] = errorOf(shapes[i],
                            groupOf[i] < 0 ? ShapeRow(rest) : keyShapes[static_cast<std::size_t>(groupOf[i])],
                            rest, weights);
    return errors;
}

} // namespace vl
