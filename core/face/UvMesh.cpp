#include "core/face/UvMesh.h"

#include "core/common/Error.h"
#include "core/face/MeshGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace vl::face {

namespace {

double uvCross(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Triangles joined across an edge whose two ends carry the same (u,v) on both sides share an island.
// Edges are keyed by welded positions, so meshes split at normal creases (glTF) still join.
void labelIslands(UvMesh& m) {
    const auto weld = weldedVertexIds(m.positions);
    std::unordered_map<std::uint64_t, std::vector<std::pair<std::uint32_t, int>>> edges; // (triangle, edge)
    edges.reserve(m.triangles.size() * 2);
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = weld[m.triangles[t][k]], b = weld[m.triangles[t][(k + 1) % 3]];
            edges[edgeKey(a, b)].push_back({t, k});
        }
    UnionFind sets(m.triangles.size());
    const auto uvAt = [&](std::uint32_t t, std::uint32_t weldedVertex) {
        for (int k = 0; k < 3; ++k)
            if (weld[m.triangles[t][k]] == weldedVertex) return m.texCoords[m.texTriangles[t][k]];
        return Vec2(std::numeric_limits<double>::quiet_NaN(), 0.0);
    };
    for (const auto& [key, list] : edges) {
        const auto a = static_cast<std::uint32_t>(key >> 32),
                   b = static_cast<std::uint32_t>(key & 0xFFFFFFFFu);
        for (std::size_t i = 0; i < list.size(); ++i)
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const std::uint32_t s = list[i].first, t = list[j].first;
                if ((uvAt(s, a) - uvAt(t, a)).sqrnorm() < 1e-14 &&
                    (uvAt(s, b) - uvAt(t, b)).sqrnorm() < 1e-14)
                    sets.unite(s, t);
            }
    }
    // Islands numbered by their first triangle, in file order.
    std::unordered_map<std::uint32_t, std::uint32_t> number;
    m.island.resize(m.triangles.size());
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
        const auto root = sets.find(t);
        const auto [it, added] = number.emplace(root, static_cast<std::uint32_t>(number.size()));
        m.island[t] = it->second;
    }
    m.islandCount = number.size();
}

UvMesh build(const MeshData& mesh, std::span<const Vec2> texCoords, std::span<const Triangle> texTriangles,
             std::string_view source) {
    UvMesh m;
    m.positions = mesh.positions;
    m.texCoords.assign(texCoords.begin(), texCoords.end());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        const Triangle& tex = texTriangles[t];
        for (int k = 0; k < 3; ++k)
            if (tri[k] >= m.positions.size())
                throwInputError(source, "triangle " + std::to_string(t) + " has a vertex index out of range");
        bool usable = true;
        for (int k = 0; k < 3; ++k) usable = usable && tex[k] < m.texCoords.size();
        usable = usable &&
                 std::abs(uvCross(m.texCoords[tex[0]], m.texCoords[tex[1]], m.texCoords[tex[2]])) > 1e-20;
        if (!usable) {
            ++m.droppedTriangles;
            continue;
        }
        m.triangles.push_back(tri);
        m.texTriangles.push_back(tex);
    }
    if (m.triangles.empty())
        throwInputError(source,
                        "the mesh has no triangles with texture coordinates (u,v): a face is built by "
                        "sampling the mesh over its (u,v)");
    labelIslands(m);
    return m;
}

} // namespace

UvMesh makeUvMesh(const MeshData& mesh, const CornerTexCoords& corners, std::string_view source) {
    if (corners.triangles.size() != mesh.triangles.size())
        throwInputError(source, "the mesh has no texture coordinates (u,v): a face is built by sampling the "
                                "mesh over its (u,v)");
    return build(mesh, corners.texCoords, corners.triangles, source);
}

UvMesh makeUvMesh(const MeshData& mesh, std::string_view source) {
    if (!mesh.hasUVs() || mesh.uvs.size() != mesh.positions.size())
        throwInputError(source, "the mesh has no texture coordinates (u,v): a face is built by sampling the "
                                "mesh over its (u,v)");
    return build(mesh, mesh.uvs, mesh.triangles, source);
}

std::vector<UvIsland> describeIslands(const UvMesh& m) {
    std::vector<UvIsland> islands(m.islandCount);
    std::vector<bool> seen(m.islandCount, false);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        UvIsland& is = islands[m.island[t]];
        const auto& p = m.positions;
        const auto& tri = m.triangles[t];
        is.triangles += 1;
        is.area += 0.5 * OpenMesh::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]).norm();
        const Vec2& a = m.texCoords[m.texTriangles[t][0]];
        const Vec2& b = m.texCoords[m.texTriangles[t][1]];
        const Vec2& c = m.texCoords[m.texTriangles[t][2]];
        is.uvArea += 0.5 * std::abs(uvCross(a, b, c));
        for (const Vec2* q : {&a, &b, &c}) {
            if (!seen[m.island[t]]) {
                is.uvMin = is.uvMax = *q;
                seen[m.island[t]] = true;
            }
            is.uvMin.minimize(*q);
            is.uvMax.maximize(*q);
        }
    }
    return islands;
}

void barycentric(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, double out[3]) {
    const double area = uvCross(a, b, c);
    out[0] = uvCross(p, b, c) / area;
    out[1] = uvCross(a, p, c) / area;
    out[2] = 1.0 - out[0] - out[1];
}

namespace {

// The point of segment ab closest to p (in (u,v)), as the parameter along it.
double segmentParameter(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double len2 = d.sqrnorm();
    return len2 > 0.0 ? std::clamp(OpenMesh::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
}

} // namespace

UvLocator::UvLocator(const UvMesh& mesh, std::span<const std::uint32_t> islands, double tolerance)
    : mesh_(&mesh), priority_(mesh.islandCount, -1), tolerance_(tolerance) {
    for (std::size_t r = 0; r < islands.size(); ++r)
        if (islands[r] < mesh.islandCount && priority_[islands[r]] < 0)
            priority_[islands[r]] = static_cast<int>(r);
    std::vector<std::uint32_t> used;
    Vec2 hi(0, 0);
    double uvArea = 0.0;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        if (priority_[mesh.island[t]] < 0) continue;
        used.push_back(t);
        for (int k = 0; k < 3; ++k) {
            const Vec2& q = mesh.texCoords[mesh.texTriangles[t][k]];
            if (used.size() == 1 && k == 0) lo_ = hi = q;
            lo_.minimize(q);
            hi.maximize(q);
        }
        const auto& tex = mesh.texTriangles[t];
        uvArea +=
            0.5 * std::abs(uvCross(mesh.texCoords[tex[0]], mesh.texCoords[tex[1]], mesh.texCoords[tex[2]]));
    }
    if (used.empty()) return;
    // About two triangles per bucket, at most 1024 x 1024 buckets.
    const Vec2 extent = hi - lo_;
    cell_ = std::max(
        {std::sqrt(2.0 * uvArea / double(used.size())), extent[0] / 1024.0, extent[1] / 1024.0, 1e-12});
    lo_ -= Vec2(tolerance_, tolerance_);
    nx_ = std::max(1, static_cast<int>((extent[0] + 2 * tolerance_) / cell_) + 1);
    ny_ = std::max(1, static_cast<int>((extent[1] + 2 * tolerance_) / cell_) + 1);
    const auto cellRange = [&](std::uint32_t t, int& x0, int& x1, int& y0, int& y1) {
        Vec2 a = mesh.texCoords[mesh.texTriangles[t][0]], b = a;
        for (int k = 1; k < 3; ++k) {
            a.minimize(mesh.texCoords[mesh.texTriangles[t][k]]);
            b.maximize(mesh.texCoords[mesh.texTriangles[t][k]]);
        }
        x0 = std::clamp(static_cast<int>((a[0] - tolerance_ - lo_[0]) / cell_), 0, nx_ - 1);
        x1 = std::clamp(static_cast<int>((b[0] + tolerance_ - lo_[0]) / cell_), 0, nx_ - 1);
        y0 = std::clamp(static_cast<int>((a[1] - tolerance_ - lo_[1]) / cell_), 0, ny_ - 1);
        y1 = std::clamp(static_cast<int>((b[1] + tolerance_ - lo_[1]) / cell_), 0, ny_ - 1);
    };
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    for (const auto t : used) {
        int x0, x1, y0, y1;
        cellRange(t, x0, x1, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) ++count[static_cast<std::size_t>(y) * nx_ + x];
    }
    start_.assign(count.size(), 0);
    for (std::size_t b = 0; b + 1 < count.size(); ++b) start_[b + 1] = start_[b] + count[b];
    items_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (const auto t : used) {
        int x0, x1, y0, y1;
        cellRange(t, x0, x1, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) items_[fill[static_cast<std::size_t>(y) * nx_ + x]++] = t;
    }
}

UvHit UvLocator::locate(const Vec2& uv) const {
    UvHit best;
    if (items_.empty()) return best;
    const int x = static_cast<int>(std::floor((uv[0] - lo_[0]) / cell_));
    const int y = static_cast<int>(std::floor((uv[1] - lo_[1]) / cell_));
    if (x < 0 || y < 0 || x >= nx_ || y >= ny_) return best;
    const std::size_t bucket = static_cast<std::size_t>(y) * nx_ + x;
    const UvMesh& m = *mesh_;
    int bestRank = std::numeric_limits<int>::max();
    double bestInside = -std::numeric_limits<double>::max(); // smallest barycentric weight
    double bestDistance = std::numeric_limits<double>::max();
    for (std::uint32_t i = start_[bucket]; i < start_[bucket + 1]; ++i) {
        const std::uint32_t t = items_[i];
        const auto& tex = m.texTriangles[t];
        const Vec2 &a = m.texCoords[tex[0]], &b = m.texCoords[tex[1]], &c = m.texCoords[tex[2]];
        double w[3];
        barycentric(uv, a, b, c, w);
        const double inside = std::min({w[0], w[1], w[2]});
        const int rank = priority_[m.island[t]];
        double distance = 0.0;
        if (inside < -1e-12) { // outside: distance to the nearest edge, in (u,v)
            distance = std::numeric_limits<double>::max();
            const Vec2* corner[3] = {&a, &b, &c};
            for (int k = 0; k < 3; ++k) {
                const Vec2 &p = *corner[k], &q = *corner[(k + 1) % 3];
                const double s = segmentParameter(uv, p, q);
                distance = std::min(distance, (p + (q - p) * s - uv).norm());
            }
            if (distance > tolerance_) continue;
        }
        const bool better = distance < bestDistance - 1e-15 ||
                            (std::abs(distance - bestDistance) <= 1e-15 &&
                             (rank < bestRank || (rank == bestRank && inside > bestInside)));
        if (!better) continue;
        best.found = true;
        best.triangle = t;
        bestRank = rank;
        bestInside = inside;
        bestDistance = distance;
        // Weights clamped onto the triangle for points in a crack.
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) sum += (best.b[k] = std::max(0.0, w[k]));
        for (int k = 0; k < 3; ++k) best.b[k] /= sum;
    }
    if (best.found) {
        const auto& tri = m.triangles[best.triangle];
        best.position = m.positions[tri[0]] * best.b[0] + m.positions[tri[1]] * best.b[1] +
                        m.positions[tri[2]] * best.b[2];
    }
    return best;
}

UvHit closestSurfacePoint(const UvMesh& m, const Vec3& p, const std::vector<bool>& allowed) {
    UvHit best;
    double bestDistance = std::numeric_limits<double>::max();
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
        if (!allowed.empty() && !allowed[t]) continue;
        const auto& tri = m.triangles[t];
        double w[3];
        const Vec3 q =
            closestPointOnTriangle(p, m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]], w);
        const double d = (q - p).sqrnorm();
        if (d >= bestDistance) continue;
        bestDistance = d;
        best.found = true;
        best.triangle = t;
        std::copy(w, w + 3, best.b);
        best.position = q;
    }
    return best;
}

Vec2 uvOf(const UvMesh& m, const UvHit& hit) {
    const auto& tex = m.texTriangles[hit.triangle];
    return m.texCoords[tex[0]] * hit.b[0] + m.texCoords[tex[1]] * hit.b[1] + m.texCoords[tex[2]] * hit.b[2];
}

} // namespace vl::face
