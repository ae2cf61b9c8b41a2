#pragma once
// Small meshes the paint tests brush, fill and select on.
#include "core/mesh/Mesh.h"

#include <cmath>
#include <numbers>

namespace vl::test {

// An n x n grid of points in the z = 0 plane (x centred on 0, y from 0), triangulated, normals +z.
inline MeshData grid(int n) {
    MeshData mesh;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) mesh.positions.emplace_back(i - (n - 1) / 2.0, j, 0.0);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = static_cast<std::uint32_t>(j * n + i);
            const auto w = static_cast<std::uint32_t>(n);
            mesh.triangles.push_back({v, v + 1, v + w});
            mesh.triangles.push_back({v + 1, v + w + 1, v + w});
        }
    return mesh;
}

// A closed UV sphere of radius 1 around the origin, wound so the normals point outwards.
inline MeshData sphere(int rings, int segments) {
    MeshData mesh;
    mesh.positions.emplace_back(0.0, 1.0, 0.0); // north pole
    for (int r = 1; r < rings; ++r) {
        const double polar = std::numbers::pi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double azimuth = 2.0 * std::numbers::pi * s / segments;
            mesh.positions.emplace_back(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                        std::sin(polar) * std::sin(azimuth));
        }
    }
    mesh.positions.emplace_back(0.0, -1.0, 0.0); // south pole
    const auto ring = [&](int r, int s) {
        return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments));
    };
    const auto south = static_cast<std::uint32_t>(mesh.positions.size() - 1);
    for (int s = 0; s < segments; ++s) {
        mesh.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
        for (int r = 1; r + 1 < rings; ++r) {
            mesh.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s)});
            mesh.triangles.push_back({ring(r, s + 1), ring(r + 1, s + 1), ring(r + 1, s)});
        }
        mesh.triangles.push_back({ring(rings - 1, s), ring(rings - 1, s + 1), south});
    }
    return mesh;
}

// Two n x n sheets 0.2 apart, not joined (z = 0 facing +z, z = -0.2 facing -z): like the two sides
// of a thin part, close in space but not neighbours on the surface.
inline MeshData twoSheets(int n) {
    MeshData mesh = grid(n);
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    const MeshData lower = grid(n);
    for (const Vec3& p : lower.positions) mesh.positions.emplace_back(p[0], p[1], -0.2);
    for (const Triangle& t : lower.triangles)
        mesh.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset}); // reversed: faces -z
    return mesh;
}

} // namespace vl::test
