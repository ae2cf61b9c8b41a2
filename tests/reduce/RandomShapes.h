#pragma once
// Random viseme sets for agreement tests.
#include "core/mesh/Mesh.h"

#include <cmath>
#include <random>
#include <vector>

namespace vl::test {

struct RandomInstance {
    std::vector<std::vector<Vec3>> shapes;
    std::vector<double> frequencies;
    std::vector<double> weights;
};

inline RandomInstance randomInstance(std::mt19937& rng, int n, int vertices,
                                     bool someZeroFrequencies = false) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0), freq(0.01, 1.0), weight(0.0, 2.0);
    RandomInstance inst;
    std::vector<Vec3> base(static_cast<std::size_t>(vertices));
    for (auto& p : base) p = Vec3(coord(rng), coord(rng), coord(rng)) * 10.0;
    for (int i = 0; i < n; ++i) {
        auto shape = base;
        for (auto& p : shape) p += Vec3(coord(rng), coord(rng), coord(rng));
        inst.shapes.push_back(std::move(shape));
        inst.frequencies.push_back(freq(rng));
    }
    if (someZeroFrequencies && n > 2) inst.frequencies[1] = 0.0;
    for (int k = 0; k < vertices; ++k) inst.weights.push_back(weight(rng));
    return inst;
}

// Shapes whose differences come from a few smooth "muscles", like a rig's visemes (unlike
// randomInstance, where every shape is about equally far from every other).
inline RandomInstance rigInstance(std::mt19937& rng, int n, int vertices, int muscles) {
    std::uniform_real_distribution<double> u(-1, 1), f(0.01, 1), unit(0, 1);
    RandomInstance inst = randomInstance(rng, 0, vertices);
    std::vector<Vec3> base(static_cast<std::size_t>(vertices));
    for (auto& p : base) p = Vec3(u(rng), u(rng), u(rng)) * 10.0;
    std::vector<std::vector<Vec3>> fields(static_cast<std::size_t>(muscles), base);
    for (auto& field : fields) {
        const Vec3 direction(u(rng), u(rng), u(rng)), centre = Vec3(u(rng), u(rng), u(rng)) * 10.0;
        for (std::size_t k = 0; k < base.size(); ++k)
            field[k] = direction * std::exp(-(base[k] - centre).sqrnorm() / 25.0);
    }
    for (int i = 0; i < n; ++i) {
        auto shape = base;
        for (const auto& field : fields)
            if (unit(rng) < 0.35) {
                const double amount = unit(rng);
                for (std::size_t k = 0; k < shape.size(); ++k) shape[k] += amount * field[k];
            }
        inst.shapes.push_back(std::move(shape));
        inst.frequencies.push_back(f(rng));
    }
    return inst;
}

} // namespace vl::test
