#pragma once
// An axis-aligned box of the (u,v) domain: where a surface changed, so that re-adaptation tests only
// the part of the mesh it can affect (AdaptiveMesh::adapt).
#include "core/mesh/Mesh.h"

#include <algorithm>
#include <limits>

namespace vl {

struct UvBox {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

    static UvBox everywhere() {
        const double inf = std::numeric_limits<double>::infinity();
        return {Vec2(-inf, -inf), Vec2(inf, inf)};
    }
    bool isEverywhere() const {
        return lo[0] == -std::numeric_limits<double>::infinity() && lo[1] == lo[0] &&
               hi[0] == std::numeric_limits<double>::infinity() && hi[1] == hi[0];
    }
    bool empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1]); }
    bool contains(const Vec2& p) const {
        return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1];
    }
    // True when the box [a, b] meets this one (touching counts).
    bool meets(const Vec2& a, const Vec2& b) const {
        return a[0] <= hi[0] && b[0] >= lo[0] && a[1] <= hi[1] && b[1] >= lo[1];
    }
    void include(const UvBox& other) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], other.lo[k]);
            hi[k] = std::max(hi[k], other.hi[k]);
        }
    }
};

} // namespace vl
