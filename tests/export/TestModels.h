#pragma once
// Small synthetic reduced models for the export and runtime tests: a wavy grid "face" with (u,v)
// and random key meshes, deterministic from a seed.
#include "core/reduce/ReducedModel.h"

#include <random>
#include <string>

namespace vl::test {

inline MeshData gridMesh(int columns, int rows, bool withUVs) {
    MeshData mesh;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns; ++x) {
            const double u = x / double(columns - 1), v = y / double(rows - 1);
            mesh.positions.emplace_back(u * 2 - 1, v * 2 - 1, 0.1 * std::sin(3 * u) * std::cos(2 * v));
            if (withUVs) mesh.uvs.emplace_back(u, v);
        }
    for (int y = 0; y + 1 < rows; ++y)
        for (int x = 0; x + 1 < columns; ++x) {
            const auto i = static_cast<std::uint32_t>(y * columns + x),
                       c = static_cast<std::uint32_t>(columns);
            mesh.triangles.push_back({i, i + 1, i + c + 1});
            mesh.triangles.push_back({i, i + c + 1, i + c});
        }
    return mesh;
}

// `keys` key meshes displacing every vertex by up to `amplitude`, and phonemes p0..p(2*keys-1)
// mapping two phonemes to each key.
inline ReducedModel randomModel(int columns, int rows, int keys, bool withUVs, unsigned seed,
                                double amplitude = 0.05) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-amplitude, amplitude);
    ReducedModel model;
    model.neutral = gridMesh(columns, rows, withUVs);
    for (int k = 0; k < keys; ++k) {
        KeyMesh key;
        key.name = "key" + std::to_string(k) + (k % 2 ? "+m" + std::to_string(k) : "");
        key.members = {key.name};
        key.frequency = 1.0 / keys;
        for (const Vec3& p : model.neutral.positions)
            key.positions.push_back(p + Vec3(d(rng), d(rng), d(rng)));
        model.keys.push_back(std::move(key));
    }
    for (int p = 0; p < 2 * keys; ++p) {
        model.phonemeToKey.emplace_back("p" + std::to_string(p), p / 2);
        model.phonemeFrequencies.emplace_back("p" + std::to_string(p), 0.5 / keys);
    }
    return model;
}

} // namespace vl::test
