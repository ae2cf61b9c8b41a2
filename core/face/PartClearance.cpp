#include "core/face/PartClearance.h"

#include "core/face/MeshGeometry.h"

#include "core/face/FaceDomain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace vl::face {

namespace {

// The skin's triangles with unit normals pointing out of the head, and the pseudo-normals of its edges
// (the sum of the two triangles' normals) and vertices (incident normals weighted by their angles).
class Skin {
  public:
    Skin(const MeshData& head, std::size_t skinVertices, const Vec3& forward, const Vec2& lo, const Vec2& hi)
        : head_(head) {
        const auto inRegion = [&](std::uint32_t v) {
            const Vec2& uv = head.uvs[v];
            return uv[0] >= lo[0] && uv[0] <= hi[0] && uv[1] >= lo[1] && uv[1] <= hi[1];
        };
        double facing = 0.0;
        for (const auto& t : head.triangles) {
            if (t[0] >= skinVertices || t[1] >= skinVertices || t[2] >= skinVertices) continue;
            const Vec3 n = OpenMesh::cross(head.positions[t[1]] - head.positions[t[0]],
                                           head.positions[t[2]] - head.positions[t[0]]);
            triangles_.push_back(t);
            Box box{head.positions[t[0]], head.positions[t[0]]};
            for (int c = 1; c < 3; ++c) {
                box.lo.minimize(head.positions[t[c]]);
                box.hi.maximize(head.positions[t[c]]);
            }
            boxes_.push_back(box);
            region_.push_back(inRegion(t[0]) && inRegion(t[1]) && inRegion(t[2]));
            normals_.push_back(n.norm() > 0.0 ? n.normalized() : n);
            if (region_.back()) facing += OpenMesh::dot(n, forward);
        }
        // A triangulated domain is wound consistently: one sign turns every normal outward.
        if (facing < 0.0)
            for (auto& n : normals_) n = -n;
        vertexNormals_.assign(skinVertices, Vec3(0, 0, 0));
        for (std::size_t k = 0; k < triangles_.size(); ++k) {
            const Triangle& t = triangles_[k];
            for (int c = 0; c < 3; ++c) {
                // try_emplace: a default-constructed OpenMesh vector is not zeroed.
                edgeNormals_.try_emplace(edgeKey(t[c], t[(c + 1) % 3]), 0.0, 0.0, 0.0).first->second +=
                    normals_[k];
                edgeUse_[edgeKey(t[c], t[(c + 1) % 3])]++;
                const Vec3 a = head.positions[t[(c + 1) % 3]] - head.positions[t[c]];
                const Vec3 b = head.positions[t[(c + 2) % 3]] - head.positions[t[c]];
                if (a.norm() > 0.0 && b.norm() > 0.0)
                    vertexNormals_[t[c]] +=
                        normals_[k] *
                        std::acos(std::clamp(OpenMesh::dot(a.normalized(), b.normalized()), -1.0, 1.0));
            }
        }
        // Border vertices: 1 on the mouth's rim, 2 on the outer border (the loop of largest (u,v) extent).
        border_.assign(skinVertices, 0);
        const auto loops = boundaryLoops(triangles_);
        std::size_t outer = 0;
        double largest = -1.0;
        for (std::size_t k = 0; k < loops.size(); ++k) {
            Vec2 a = head.uvs[loops[k].front()], b = a;
            for (const auto v : loops[k]) {
                a.minimize(head.uvs[v]);
                b.maximize(head.uvs[v]);
            }
            if ((b - a).norm() > largest) {
                largest = (b - a).norm();
                outer = k;
            }
        }
        for (std::size_t k = 0; k < loops.size(); ++k)
            for (const auto v : loops[k]) border_[v] = k == outer ? 2 : 1;
    }

    struct Nearest {
        double distance = 0.0; // signed: positive inside
        int border = 0;        // 0 inside the skin, 1 the mouth's rim, 2 the outer border
        bool inRegion = false;
        Vec2 uv{0, 0};        // of the nearest point
        Vec3 offset{0, 0, 0}; // from the nearest point to the part vertex
    };

    Nearest nearest(const Vec3& p) const {
        double best = std::numeric_limits<double>::max(), w[3] = {0, 0, 0};
        std::size_t at = 0;
        Vec3 q(0, 0, 0);
        for (std::size_t k = 0; k < triangles_.size(); ++k) {
            const Triangle& t = triangles_[k];
            double b[3];
            const Vec3 c = closestPointOnTriangle(p, head_.positions[t[0]], head_.positions[t[1]],
                                                  head_.positions[t[2]], b);
            const double d = (c - p).sqrnorm();
            if (d < best) {
                best = d;
                at = k;
                q = c;
                std::copy(b, b + 3, w);
            }
        }
        Nearest n;
        n.inRegion = region_[at];
        // The feature the nearest point lies on: a corner, an edge or the triangle's inside.
        const Triangle& t = triangles_[at];
        constexpr double kOn = 1e-9;
        Vec3 normal = normals_[at];
        int corners = 0, corner = 0;
        for (int c = 0; c < 3; ++c)
            if (w[c] > kOn) {
                ++corners;
                corner = c;
            }
        if (corners == 1) {
            normal = vertexNormals_[t[corner]];
            n.border = border_[t[corner]];
        } else if (corners == 2) {
            const int off = w[0] <= kOn ? 0 : w[1] <= kOn ? 1 : 2; // the corner the edge is opposite
            const std::uint32_t a = t[(off + 1) % 3], b = t[(off + 2) % 3];
            normal = edgeNormals_.at(edgeKey(a, b));
            if (edgeUse_.at(edgeKey(a, b)) == 1) n.border = std::max(border_[a], border_[b]);
        }
        n.distance = std::sqrt(best) * (OpenMesh::dot(p - q, normal) > 0.0 ? -1.0 : 1.0);
        n.offset = p - q;
        n.uv = head_.uvs[t[0]] * w[0] + head_.uvs[t[1]] * w[1] + head_.uvs[t[2]] * w[2];
        return n;
    }

    // The triangles whose bounding boxes overlap the box [lo, hi].
    std::vector<std::size_t> overlapping(const Vec3& lo, const Vec3& hi) const {
        std::vector<std::size_t> out;
        for (std::size_t k = 0; k < triangles_.size(); ++k)
            if (overlaps(boxes_[k], lo, hi)) out.push_back(k);
        return out;
    }

    // Whether the segment a-b passes through one of the `candidates` (Moeller and Trumbore's
    // ray-triangle test restricted to the segment).
    bool crosses(const Vec3& a, const Vec3& b, const std::vector<std::size_t>& candidates) const {
        Vec3 lo = a, hi = a;
        lo.minimize(b);
        hi.maximize(b);
        const Vec3 d = b - a;
        for (const auto k : candidates) {
            if (!overlaps(boxes_[k], lo, hi)) continue;
            const Triangle& t = triangles_[k];
            const Vec3 &p0 = head_.positions[t[0]], e1 = head_.positions[t[1]] - p0,
                       e2 = head_.positions[t[2]] - p0;
            const Vec3 h = OpenMesh::cross(d, e2);
            const double det = OpenMesh::dot(e1, h);
            if (std::abs(det) < 1e-14 * e1.sqrnorm() * d.norm()) continue; // parallel
            const Vec3 s0 = a - p0;
            const double u = OpenMesh::dot(s0, h) / det;
            if (u < 0.0 || u > 1.0) continue;
            const Vec3 q = OpenMesh::cross(s0, e1);
            const double v = OpenMesh::dot(d, q) / det;
            if (v < 0.0 || u + v > 1.0) continue;
            const double along = OpenMesh::dot(e2, q) / det;
            if (along >= 0.0 && along <= 1.0) return true;
        }
        return false;
    }

  private:
    struct Box {
        Vec3 lo, hi;
    };
    static bool overlaps(const Box& box, const Vec3& lo, const Vec3& hi) {
        return box.hi[0] >= lo[0] && box.hi[1] >= lo[1] && box.hi[2] >= lo[2] && box.lo[0] <= hi[0] &&
               box.lo[1] <= hi[1] && box.lo[2] <= hi[2];
    }
    const MeshData& head_;
    std::vector<Box> boxes_;
    std::vector<Triangle> triangles_;
    std::vector<bool> region_;
    std::vector<Vec3> normals_, vertexNormals_;
    std::unordered_map<std::uint64_t, Vec3> edgeNormals_;
    std::unordered_map<std::uint64_t, int> edgeUse_;
    std::vector<int> border_;
};

} // namespace

std::vector<PartClearance> partClearances(const MeshData& head, std::size_t skinVertices,
                                          std::span<const HeadPart> parts, const Vec3& forward,
                                          const Vec2& lo, const Vec2& hi) {
    const Skin skin(head, skinVertices, forward, lo, hi);
    std::vector<PartClearance> result;
    std::size_t offset = skinVertices;
    for (const auto& part : parts) {
        PartClearance c;
        c.part = part.name;
        c.clearance = c.closest = std::numeric_limits<double>::max();
        for (std::size_t i = 0; i < part.rest.positions.size(); ++i) {
            const auto n = skin.nearest(head.positions[offset + i]);
            if (!n.inRegion) continue;
            if (n.border == 2) {
                ++c.beyondBorder;
                continue;
            }
            // Outside the skin but behind its nearest point, by the lips: in the mouth's opening,
            // where the lips' rim (or, on lips that roll in, their inner side) is nearest. Seen through
            // the open mouth, not through the lips.
            const double du = (n.uv[0] - kMouthU) / (kMouthHalfWidth + 0.03);
            const double dv = (n.uv[1] - kMouthV) / (kMouthHalfHeight + 0.05);
            const bool byTheLips = du * du + dv * dv <= 1.0;
            c.closest = std::min(c.closest, std::abs(n.distance));
            const bool behind = OpenMesh::dot(n.offset, forward) <= 0.0;
            if ((n.border == 1 || (n.distance < 0.0 && byTheLips)) && behind) {
                ++c.throughMouth;
                continue;
            }
            // In front of the lips' rim: out of the mouth, however the rim's edge happens to face.
            const double distance = n.border == 1 ? -n.offset.norm() : n.distance;
            c.checked = true;
            if (distance < c.clearance) {
                c.clearance = distance;
                c.vertex = i;
            }
        }
        if (!c.checked) c.clearance = 0.0;
        if (c.closest == std::numeric_limits<double>::max()) c.closest = 0.0;
        Vec3 boxLo = head.positions[offset], boxHi = boxLo;
        for (std::size_t i = 0; i < part.rest.positions.size(); ++i) {
            boxLo.minimize(head.positions[offset + i]);
            boxHi.maximize(head.positions[offset + i]);
        }
        const auto candidates = skin.overlapping(boxLo, boxHi);
        std::unordered_set<std::uint64_t> edges;
        for (const auto& t : part.rest.triangles)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = t[k], b = t[(k + 1) % 3];
                if (edges.insert(edgeKey(a, b)).second &&
                    skin.crosses(head.positions[offset + a], head.positions[offset + b], candidates))
                    ++c.crossings;
            }
        result.push_back(c);
        offset += part.rest.positions.size();
    }
    return result;
}

} // namespace vl::face
