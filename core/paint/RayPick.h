#pragma once
// The triangle of a mesh a ray hits first (mouse picking in the editor's 3D views).
#include "core/mesh/Mesh.h"

#include <optional>
#include <span>

namespace vl {

struct RayHit {
    std::size_t triangle = 0;
    double distance = 0.0; // along the (unit) direction
    Vec3 point;
    Vec3 barycentric; // weights of the triangle's corners
};

// Distance along the (unit) `direction` from `origin` to triangle abc and the barycentric weights of
// the hit (Moeller-Trumbore, both faces), or nothing when the ray misses it or runs parallel to it.
struct TriangleHit {
    double distance = 0.0;
    Vec3 barycentric;
};
std::optional<TriangleHit> intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& origin,
                                             const Vec3& direction);

// Nearest hit with distance > 0 over all triangles (Moeller-Trumbore, both faces), or nothing.
// O(|F|) per ray: picking happens once per mouse event.
std::optional<RayHit> intersectRay(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                                   const Vec3& origin, const Vec3& direction);

} // namespace vl
