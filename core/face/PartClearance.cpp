#include "core/face/PartClearance.h"

#include "core/face/MeshGeometry.h"

#include <limits>
#include <map>

namespace vl::face {

std::vector<PartClearance> partClearances(const MeshData& head, std::size_t skinVertices,
                                          std::span<const HeadPart> parts, const Vec3& forward,
                                          const Vec2& lo, const Vec2& hi) {
    // The region's skin triangles, and which of their edges are on the skin's border (the lips' rim).
    const auto inRegion = [&](std::uint32_t v) {
        const Vec2& uv = head.uvs[v];
        return v < skinVertices && uv[0] >= lo[0] && uv[0] <= hi[0] && uv[1] >= lo[1] && uv[1] <= hi[1];
    };
    std::vector<Triangle> skin;
    std::map<std::uint64_t, int> edgeUse;
    for (const auto& t : head.triangles) {
        if (t[0] >= skinVertices || t[1] >= skinVertices || t[2] >= skinVertices) continue;
        for (int k = 0; k < 3; ++k) edgeUse[edgeKey(t[k], t[(k + 1) % 3])]++;
        if (inRegion(t[0]) && inRegion(t[1]) && inRegion(t[2])) skin.push_back(t);
    }
    // The skin's winding is consistent (a triangulated domain): one sign makes every normal point out,
    // the one that makes the region face `forward` on the whole (lips folded under or over keep
    // their true side).
    const auto normalOf = [&](const Triangle& t) {
        return OpenMesh::cross(head.positions[t[1]] - head.positions[t[0]],
                               head.positions[t[2]] - head.positions[t[0]]);
    };
    double facing = 0.0;
    for (const auto& t : skin) facing += OpenMesh::dot(normalOf(t), forward);
    const double outward = facing >= 0.0 ? 1.0 : -1.0;
    std::vector<PartClearance> result;
    std::size_t offset = skinVertices;
    for (const auto& part : parts) {
        PartClearance c;
        c.part = part.name;
        c.clearance = std::numeric_limits<double>::max();
        for (std::size_t i = 0; i < part.rest.positions.size(); ++i) {
            const Vec3& p = head.positions[offset + i];
            double best = std::numeric_limits<double>::max(), w[3] = {0, 0, 0};
            const Triangle* nearest = nullptr;
            Vec3 at(0, 0, 0);
            for (const auto& t : skin) {
                double b[3];
                const Vec3 q = closestPointOnTriangle(p, head.positions[t[0]], head.positions[t[1]],
                                                      head.positions[t[2]], b);
                const double d = (q - p).sqrnorm();
                if (d < best) {
                    best = d;
                    nearest = &t;
                    at = q;
                    std::copy(b, b + 3, w);
                }
            }
            if (!nearest) continue;
            // Nearest on the rim (an edge or corner of the border): the vertex is seen through the
            // opening, not behind or through the lips.
            bool onRim = false;
            for (int k = 0; k < 3; ++k) {
                const int other1 = (k + 1) % 3, other2 = (k + 2) % 3;
                const bool onEdge = w[other2] < 1e-9; // between corners k and other1
                if (onEdge && edgeUse[edgeKey((*nearest)[k], (*nearest)[other1])] == 1) onRim = true;
                if (w[k] > 1.0 - 1e-9 && (edgeUse[edgeKey((*nearest)[k], (*nearest)[other1])] == 1 ||
                                          edgeUse[edgeKey((*nearest)[k], (*nearest)[other2])] == 1))
                    onRim = true;
            }
            if (onRim) continue;
            const Vec3 n = normalOf(*nearest) * outward;
            const double distance = std::sqrt(best) * (OpenMesh::dot(p - at, n) > 0.0 ? -1.0 : 1.0);
            c.checked = true;
            if (distance < c.clearance) {
                c.clearance = distance;
                c.vertex = i;
            }
        }
        if (!c.checked) c.clearance = 0.0;
        result.push_back(c);
        offset += part.rest.positions.size();
    }
    return result;
}

} // namespace vl::face
