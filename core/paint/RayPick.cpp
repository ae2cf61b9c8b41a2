#include "core/paint/RayPick.h"

#include <cmath>

namespace vl {

std::optional<TriangleHit> intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& origin,
                                             const Vec3& direction) {
    constexpr double kParallel = 1e-14;
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 p = OpenMesh::cross(direction, e2);
    const double det = OpenMesh::dot(e1, p);
    if (std::abs(det) < kParallel) return std::nullopt;
    const double inv = 1.0 / det;
    const Vec3 s = origin - a;
    const double u = OpenMesh::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const Vec3 q = OpenMesh::cross(s, e1);
    const double v = OpenMesh::dot(direction, q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    return TriangleHit{OpenMesh::dot(e2, q) * inv, Vec3(1.0 - u - v, u, v)};
}

std::optional<RayHit> intersectRay(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                                   const Vec3& origin, const Vec3& direction) {
    std::optional<RayHit> best;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const auto hit = intersectTriangle(positions[triangles[f][0]], positions[triangles[f][1]],
                                           positions[triangles[f][2]], origin, direction);
        if (!hit || hit->distance <= 0.0 || (best && hit->distance >= best->distance)) continue;
        best = RayHit{f, hit->distance, origin + direction * hit->distance, hit->barycentric};
    }
    return best;
}

} // namespace vl
