#include "core/adaptive/RbmtBase.h"

#include "core/common/Error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace vl {
namespace {

constexpr int kNone = -1;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

double cross2(const Vec2& a, const Vec2& b) {
    return a[0] * b[1] - a[1] * b[0];
}

std::string triangleName(std::size_t t) {
    return "triangle " + std::to_string(t);
}

// The domain with unused vertices dropped and every triangle counter-clockwise in (u,v).
struct CleanDomain {
    std::vector<Vec2> uvs;
    std::vector<Triangle> triangles;
};

CleanDomain cleanDomain(const MeshData& domain) {
    const std::string_view where = "base domain";
    if (domain.triangles.empty()) throwInputError(where, "has no triangles");
    const std::size_t n = domain.uvs.size();
    int orientation = 0;
    std::vector<std::uint32_t> remap(n, UINT32_MAX);
    CleanDomain out;
    for (std::size_t t = 0; t < domain.triangles.size(); ++t) {
        Triangle tri = domain.triangles[t];
        for (const auto v : tri) {
            if (v >= n)
                throwInputError(where, triangleName(t) + " has a vertex without (u,v) or out of range");
            if (!std::isfinite(domain.uvs[v][0]) || !std::isfinite(domain.uvs[v][1]))
                throwInputError(where, "vertex " + std::to_string(v) + " has a non-finite (u,v)");
        }
        const Vec2& a = domain.uvs[tri[0]];
        const double area = cross2(domain.uvs[tri[1]] - a, domain.uvs[tri[2]] - a);
        if (!(area != 0.0)) throwInputError(where, triangleName(t) + " is degenerate in (u,v)");
        const int sign = area > 0 ? 1 : -1;
        if (orientation == 0) orientation = sign;
        if (sign != orientation)
            throwInputError(where, triangleName(t) + " is oriented opposite to triangle 0 in (u,v)");
        if (sign < 0) std::swap(tri[1], tri[2]);
        for (const auto v : tri) remap[v] = 0;
        out.triangles.push_back(tri);
    }
    for (std::size_t v = 0; v < n; ++v) { // keep the order of the used vertices
        if (remap[v] == UINT32_MAX) continue;
        remap[v] = static_cast<std::uint32_t>(out.uvs.size());
        out.uvs.push_back(domain.uvs[v]);
    }
    for (auto& tri : out.triangles)
        for (auto& v : tri) v = remap[v];
    // OpenMesh rejects non-manifold vertices and edges; reuse its checks for the error message.
    MeshData flat;
    for (const auto& uv : out.uvs) flat.positions.emplace_back(uv[0], uv[1], 0.0);
    flat.triangles = out.triangles;
    (void)toTriMesh(flat, where);
    return out;
}

// neighbour[t][k]: the triangle across edge k (from t[k] to t[k+1]), kNone on the border.
std::vector<std::array<int, 3>> buildAdjacency(const std::vector<Triangle>& triangles) {
    std::vector<std::array<int, 3>> neighbour(triangles.size(), {kNone, kNone, kNone});
    std::unordered_map<std::uint64_t, int> firstSide; // edge -> 3 * triangle + k
    firstSide.reserve(triangles.size() * 2);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const auto key = edgeKey(triangles[t][k], triangles[t][(k + 1) % 3]);
            const auto [it, inserted] = firstSide.emplace(key, static_cast<int>(3 * t + k));
            if (inserted) continue;
            const int other = it->second / 3;
            if (neighbour[other][it->second % 3] != kNone)
                throwInputError("base domain",
                                triangleName(t) + " shares an edge with more than one triangle");
            neighbour[other][it->second % 3] = static_cast<int>(t);
            neighbour[t][k] = other;
        }
    }
    return neighbour;
}

// Edge index of `t` whose endpoints are those of edge k of `s`.
int matchingEdge(const std::vector<Triangle>& tris, int t, int s, int k) {
    const auto key = edgeKey(tris[s][k], tris[s][(k + 1) % 3]);
    for (int j = 0; j < 3; ++j)
        if (edgeKey(tris[t][j], tris[t][(j + 1) % 3]) == key) return j;
    throw std::logic_error("RBMT base: adjacency is inconsistent");
}

double edgeLength(const CleanDomain& d, int t, int k) {
    const auto& tri = d.triangles[t];
    return (d.uvs[tri[(k + 1) % 3]] - d.uvs[tri[k]]).norm();
}

int longestEdge(const CleanDomain& d, int t, bool borderOnly, const std::array<int, 3>& nb) {
    int best = kNone;
    for (int k = 0; k < 3; ++k) {
        if (borderOnly && nb[k] != kNone) continue;
        if (best == kNone || edgeLength(d, t, k) > edgeLength(d, t, best)) best = k;
    }
    return best;
}

// Pairs triangles into basic blocks (steps 1-3). Returns false if some interior triangle stays alone.
class BlockPairing {
  public:
    BlockPairing(const CleanDomain& d, const std::vector<std::array<int, 3>>& nb)
        : d_(d), nb_(nb), m_(static_cast<int>(d.triangles.size())), edge_(d.triangles.size(), kNone),
          border_(d.triangles.size(), false) {
        for (int t = 0; t < m_; ++t)
            for (int k = 0; k < 3; ++k) border_[t] = border_[t] || nb_[t][k] == kNone;
    }

    bool run() {
        pairMutuallyLongest();
        pairGreedily();
        for (int t = 0; t < m_; ++t)
            if (edge_[t] == kNone && !border_[t]) augment(t);
        for (int t = 0; t < m_; ++t) {
            if (edge_[t] != kNone) continue;
            if (!border_[t]) return false;
            const int k = longestEdge(d_, t, false, nb_[t]);
            const int n = nb_[t][k];
            if (n != kNone && edge_[n] == kNone)
                pair(t, k);
            else
                edge_[t] = longestEdge(d_, t, true, nb_[t]);
        }
        return true;
    }
    const std::vector<int>& refinementEdges() const { return edge_; }

  private:
    int partner(int t) const { return edge_[t] == kNone ? kNone : nb_[t][edge_[t]]; }
    void pair(int t, int k) {
        const int n = nb_[t][k];
        edge_[t] = k;
        edge_[n] = matchingEdge(d_.triangles, n, t, k);
    }
    int edgeTo(int t, int n) const {
        for (int k = 0; k < 3; ++k)
            if (nb_[t][k] == n) return k;
        throw std::logic_error("RBMT base: triangles are not adjacent");
    }

    void pairMutuallyLongest() {
        for (int t = 0; t < m_; ++t) {
            const int k = longestEdge(d_, t, false, nb_[t]);
            const int n = nb_[t][k];
            if (n == kNone || edge_[t] != kNone || edge_[n] != kNone) continue;
            if (longestEdge(d_, n, false, nb_[n]) == matchingEdge(d_.triangles, n, t, k)) pair(t, k);
        }
    }

    int freeDegree(int t) const {
        int deg = 0;
        for (const int n : nb_[t]) deg += n != kNone && edge_[n] == kNone;
        return deg;
    }

    // Least-connected interior triangle first, paired with its neediest neighbour.
    void pairGreedily() {
        std::set<std::pair<int, int>> queue;
        std::vector<int> key(m_, 0);
        for (int t = 0; t < m_; ++t)
            if (edge_[t] == kNone && !border_[t]) queue.emplace(key[t] = freeDegree(t), t);
        auto refresh = [&](int t) {
            if (edge_[t] != kNone || border_[t]) return;
            queue.erase({key[t], t});
            queue.emplace(key[t] = freeDegree(t), t);
        };
        while (!queue.empty()) {
            // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
            const int degree = queue.begin()->first, t = queue.begin()->second;
            queue.erase(queue.begin());
            if (degree == 0) continue; // stuck: left to the augmenting-path search
            int best = kNone;
            auto better = [&](int k, int than) {
                const int a = nb_[t][k], b = nb_[t][than];
                if (border_[a] != border_[b]) return !border_[a];
                if (freeDegree(a) != freeDegree(b)) return freeDegree(a) < freeDegree(b);
                return edgeLength(d_, t, k) > edgeLength(d_, t, than);
            };
            for (int k = 0; k < 3; ++k) {
                const int n = nb_[t][k];
                if (n == kNone || edge_[n] != kNone) continue;
                if (best == kNone || better(k, best)) best = k;
            }
            const int n = nb_[t][best];
            queue.erase({key[n], n});
            pair(t, best);
            for (const int s : {t, n})
                for (const int r : nb_[s])
                    if (r != kNone) refresh(r);
        }
    }

    // Breadth-first search of an alternating chain from the lone triangle `start` to another lone
    // triangle, or to a paired triangle on the border that can become a single boundary block.
    void augment(int start) {
        std::vector<int> via(m_, kNone);
        std::vector<bool> seen(m_, false);
        std::deque<int> outer{start};
        seen[start] = true;
        while (!outer.empty()) {
            const int x = outer.front();
            outer.pop_front();
            for (const int y : nb_[x]) {
                if (y == kNone || seen[y]) continue;
                seen[y] = true;
                via[y] = x;
                const int z = partner(y);
                if (z == kNone) return flip(y, start, via);
                if (border_[z]) {
                    edge_[z] = kNone; // becomes a single boundary block later
                    return flip(y, start, via);
                }
                if (seen[z]) continue;
                seen[z] = true;
                outer.push_back(z);
            }
        }
    }
    void flip(int y, int start, const std::vector<int>& via) {
        while (true) {
            const int x = via[y];
            const int previous = x == start ? kNone : partner(x);
            pair(x, edgeTo(x, y));
            if (previous == kNone) return;
            y = previous;
        }
    }

    const CleanDomain& d_;
    const std::vector<std::array<int, 3>>& nb_;
    int m_;
    std::vector<int> edge_;
    std::vector<bool> border_;
};

// Step 4: edge splits so that every triangle has 1 or 3 split edges (a parity problem solved on a
// spanning forest of the adjacency rooted at the border), then the pieces pair up inside each triangle.
RbmtBase splitIntoBlocks(const CleanDomain& d, const std::vector<std::array<int, 3>>& nb) {
    const int m = static_cast<int>(d.triangles.size());
    std::vector<int> parentEdge(m, kNone), order;
    std::vector<bool> seen(m, false), root(m, false);
    order.reserve(m);
    std::deque<int> queue;
    auto grow = [&] {
        while (!queue.empty()) {
            const int x = queue.front();
            queue.pop_front();
            order.push_back(x);
            for (int k = 0; k < 3; ++k) {
                const int y = nb[x][k];
                if (y == kNone || seen[y]) continue;
                seen[y] = true;
                parentEdge[y] = matchingEdge(d.triangles, y, x, k);
                queue.push_back(y);
            }
        }
    };
    for (int t = 0; t < m; ++t) { // the border is the root: its triangles hang from a border edge
        const int k = longestEdge(d, t, true, nb[t]);
        if (k == kNone) continue;
        seen[t] = true;
        parentEdge[t] = k;
        queue.push_back(t);
    }
    grow();
    for (int t = 0; t < m; ++t) { // closed components: any triangle is the root
        if (seen[t]) continue;
        seen[t] = root[t] = true;
        queue.push_back(t);
        grow();
    }

    std::vector<std::array<bool, 3>> split(m, {false, false, false});
    std::vector<int> count(m, 0);
    std::size_t splitEdges = 0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const int t = *it;
        if (count[t] % 2 == 1) continue;
        if (root[t]) throw std::logic_error("RBMT base: closed component with an odd number of triangles");
        const int k = parentEdge[t];
        split[t][k] = true;
        ++count[t];
        ++splitEdges;
        if (const int n = nb[t][k]; n != kNone) {
            split[n][matchingEdge(d.triangles, n, t, k)] = true;
            ++count[n];
        }
    }

    RbmtBase out;
    out.uvs = d.uvs;
    out.splitEdges = splitEdges;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
        const auto [it, inserted] =
            midpoint.emplace(edgeKey(a, b), static_cast<std::uint32_t>(out.uvs.size()));
        if (inserted) out.uvs.push_back(0.5 * (d.uvs[a] + d.uvs[b]));
        return it->second;
    };
    auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int refinementEdge) {
        out.triangles.push_back({a, b, c});
        out.refinementEdge.push_back(static_cast<std::uint8_t>(refinementEdge));
    };
    for (int t = 0; t < m; ++t) {
        const auto& tri = d.triangles[t];
        if (count[t] == 1) { // halves (a,m,c) and (m,b,c) share the block edge m-c
            const int k =
                static_cast<int>(std::find(split[t].begin(), split[t].end(), true) - split[t].begin());
            const auto a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
            const auto m0 = mid(a, b);
            emit(a, m0, c, 1);
            emit(m0, b, c, 2);
        } else { // all three split, the longest first: blocks share edges m0-m1 and m0-m2
            const int k = longestEdge(d, t, false, nb[t]);
            const auto a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
            const auto m0 = mid(a, b), m1 = mid(b, c), m2 = mid(c, a);
            emit(m0, b, m1, 2);
            emit(m0, m1, c, 0);
            emit(a, m0, m2, 1);
            emit(m2, m0, c, 0);
        }
    }
    return out;
}

} // namespace

RbmtBase makeRbmtBase(const MeshData& domain, RbmtMethod method) {
    const CleanDomain d = cleanDomain(domain);
    const auto nb = buildAdjacency(d.triangles);
    RbmtBase out;
    if (method == RbmtMethod::Auto) {
        BlockPairing pairing(d, nb);
        if (pairing.run()) {
            out.uvs = d.uvs;
            out.triangles = d.triangles;
            for (const int k : pairing.refinementEdges())
                out.refinementEdge.push_back(static_cast<std::uint8_t>(k));
        }
    }
    if (out.triangles.empty()) out = splitIntoBlocks(d, nb);
    if (!isUnionOfBasicBlocks(out))
        throw std::logic_error("RBMT base: construction produced an unpaired triangle");
    return out;
}

bool isUnionOfBasicBlocks(const RbmtBase& base) {
    if (base.refinementEdge.size() != base.triangles.size()) return false;
    const auto nb = buildAdjacency(base.triangles);
    for (std::size_t t = 0; t < base.triangles.size(); ++t) {
        const int k = base.refinementEdge[t];
        if (k > 2) return false;
        const int n = nb[t][k];
        if (n == kNone) continue;
        if (base.refinementEdge[n] != matchingEdge(base.triangles, n, static_cast<int>(t), k)) return false;
    }
    return true;
}

} // namespace vl
