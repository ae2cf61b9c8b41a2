#pragma once
// Small geometric helpers of face building: welding coincident vertices, edge keys, the closest
// point of a triangle, and boundary loops.
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl::face {

// For each position, the index of the first position with exactly the same coordinates (meshes
// split at seams or creases repeat positions).
std::vector<std::uint32_t> weldedVertexIds(std::span<const Vec3> positions);

// An order-independent key of the edge between vertices a and b.
inline std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The point of triangle (a, b, c) closest to p, with its barycentric weights in w.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double w[3]);

// The boundary loops of a triangle set (edges used by exactly one triangle), each as vertex indices
// in order. Vertex indices are those of `triangles` (weld first when the mesh repeats positions).
std::vector<std::vector<std::uint32_t>> boundaryLoops(std::span<const Triangle> triangles);

} // namespace vl::face
