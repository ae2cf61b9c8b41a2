#pragma once
// Helpers for the mesh I/O tests: random meshes with awkward doubles, bit-exact comparison and
// checks that an InputError names the right place.
#include "core/common/Error.h"
#include "core/mesh/Mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <numeric>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace vl::test {

// Any finite double: half from raw random bits (every exponent, subnormals, -0), half at face-mesh
// scale with full 53-bit mantissas.
inline double randomDouble(std::mt19937_64& rng) {
    if (rng() % 2 == 0) {
        for (;;) {
            const double value = std::bit_cast<double>(rng());
            if (std::isfinite(value)) return value;
        }
    }
    return std::uniform_real_distribution<double>(-20.0, 20.0)(rng);
}

// A random mesh over `vertexCount` vertices (at least 3) in which every vertex is used by some
// triangle (OBJ cannot store the (u,v) of a vertex no face uses) and no triangle repeats a vertex.
inline MeshData randomMesh(std::uint64_t seed, std::size_t vertexCount, std::size_t triangleCount,
                           bool withUVs) {
    std::mt19937_64 rng(seed);
    MeshData mesh;
    for (std::size_t i = 0; i < vertexCount; ++i)
        mesh.positions.emplace_back(randomDouble(rng), randomDouble(rng), randomDouble(rng));
    if (withUVs)
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const double u = randomDouble(rng);
            mesh.uvs.emplace_back(u, randomDouble(rng));
        }
    const auto n = static_cast<std::uint32_t>(vertexCount);
    for (std::uint32_t i = 0; i < n; i += 3) mesh.triangles.push_back({i, (i + 1) % n, (i + 2) % n});
    std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
    while (mesh.triangles.size() < triangleCount) {
        const Triangle t{pick(rng), pick(rng), pick(rng)};
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
    }
    std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
    return mesh;
}

inline bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Positions, (u,v) and triangles identical, doubles compared bit for bit (so -0 differs from 0).
inline void expectIdenticalMesh(const MeshData& expected, const MeshData& actual) {
    ASSERT_EQ(expected.positions.size(), actual.positions.size());
    ASSERT_EQ(expected.uvs.size(), actual.uvs.size());
    ASSERT_EQ(expected.triangles, actual.triangles);
    for (std::size_t i = 0; i < expected.positions.size(); ++i)
        for (int k = 0; k < 3; ++k)
            ASSERT_TRUE(sameBits(expected.positions[i][k], actual.positions[i][k]))
                << "vertex " << i << " coordinate " << k << ": " << expected.positions[i][k] << " vs "
                << actual.positions[i][k];
    for (std::size_t i = 0; i < expected.uvs.size(); ++i)
        for (int k = 0; k < 2; ++k)
            ASSERT_TRUE(sameBits(expected.uvs[i][k], actual.uvs[i][k]))
                << "uv " << i << " component " << k << ": " << expected.uvs[i][k] << " vs "
                << actual.uvs[i][k];
}

// Positions written as float32 (PositionPrecision::Float32) and read back: every coordinate rounds
// to the same float32 as the one written, and has the same sign (the text keeps -0).
inline void expectSameFloat32Positions(const std::vector<Vec3>& written, const std::vector<Vec3>& readBack) {
    ASSERT_EQ(written.size(), readBack.size());
    for (std::size_t i = 0; i < written.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const auto w = static_cast<float>(written[i][k]), r = static_cast<float>(readBack[i][k]);
            ASSERT_EQ(std::bit_cast<std::uint32_t>(w), std::bit_cast<std::uint32_t>(r))
                << "vertex " << i << " coordinate " << k << ": " << written[i][k] << " written, "
                << readBack[i][k] << " read back";
        }
}

// Appends `value` to `out` in big- or little-endian byte order (binary PLY data).
template <class T> void put(std::string& out, T value, bool bigEndian) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
    out.append(raw, sizeof(T));
}

// Runs `action`, which must throw InputError whose message contains every one of `parts`.
inline void expectInputError(const std::function<void()>& action,
                             std::initializer_list<std::string_view> parts) {
    try {
        action();
        ADD_FAILURE() << "expected an InputError mentioning '" << *parts.begin() << "'";
    } catch (const InputError& error) {
        const std::string message = error.what();
        for (const auto part : parts)
            EXPECT_NE(message.find(part), std::string::npos)
                << "message '" << message << "' lacks '" << part << "'";
    }
}

} // namespace vl::test
