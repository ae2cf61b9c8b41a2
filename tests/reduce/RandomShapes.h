#pragma once
// Random viseme sets for agreement tests.
#include "core/mesh/Mesh.h"

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

} // namespace vl::test
