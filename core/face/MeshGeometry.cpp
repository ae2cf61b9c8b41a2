#include "core/face/MeshGeometry.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>

namespace vl::face {

std::vector<std::uint32_t> weldedVertexIds(std::span<const Vec3> positions) {
    struct Hash {
        std::size_t operator()(const Vec3& p) const {
            std::size_t h = 1469598103934665603ull;
            for (int k = 0; k < 3; ++k) {
                std::uint64_t bits;
                const double x = p[k] == 0.0 ? 0.0 : p[k]; // -0 and +0 weld
                std::memcpy(&bits, &x, sizeof bits);
                h = (h ^ bits) * 1099511628211ull;
            }
            return h;
        }
    };
    struct Equal {
        bool operator()(const Vec3& a, const Vec3& b) const {
            return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
        }
    };
    std::unordered_map<Vec3, std::uint32_t, Hash, Equal> first;
    first.reserve(positions.size());
    std::vector<std::uint32_t> ids(positions.size());
    for (std::uint32_t i = 0; i < positions.size(); ++i)
        ids[i] = first.emplace(positions[i], i).first->second;
    return ids;
}

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double w[3]) {
    // Ericson, Real-Time Collision Detection, 5.1.5: Voronoi regions of the vertices, edges and face.
    const auto set = [&](double x, double y, double z) {
        w[0] = x;
        w[1] = y;
        w[2] = z;
        return a * x + b * y + c * z;
    };
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = OpenMesh::dot(ab, ap), d2 = OpenMesh::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return set(1, 0, 0);
    const Vec3 bp = p - b;
    const double d3 = OpenMesh::dot(ab, bp), d4 = OpenMesh::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return set(0, 1, 0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return set(1 - v, v, 0);
    }
    const Vec3 cp = p - c;
    const double d5 = OpenMesh::dot(ab, cp), d6 = OpenMesh::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return set(0, 0, 1);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double v = d2 / (d2 - d6);
        return set(1 - v, 0, v);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return set(0, 1 - v, v);
    }
    const double sum = va + vb + vc;
    if (sum == 0.0) return set(1, 0, 0); // degenerate triangle
    const double v = vb / sum, u = vc / sum;
    return set(1 - v - u, v, u);
}

std::vector<std::vector<std::uint32_t>> boundaryLoops(std::span<const Triangle> triangles) {
    // Directed boundary half-edges: an edge a->b whose opposite b->a no triangle has.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}]++;
    std::multimap<std::uint32_t, std::uint32_t> next;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            if (count[{std::min(a, b), std::max(a, b)}] == 1) next.emplace(a, b);
        }
    std::vector<std::vector<std::uint32_t>> loops;
    while (!next.empty()) {
        auto it = next.begin();
        const std::uint32_t start = it->first;
        std::vector<std::uint32_t> loop{start};
        std::uint32_t at = it->second;
        next.erase(it);
        while (at != start) {
            loop.push_back(at);
            const auto step = next.find(at);
            if (step == next.end()) break; // open chain at a non-manifold vertex
            at = step->second;
            next.erase(step);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace vl::face
