#pragma once
// Helpers shared by the adaptive-mesh tests: exact snapshots of a mesh (to compare states as sets)
// and the invariant assertion.
#include "core/adaptive/AdaptiveMesh.h"
#include "core/adaptive/Invariants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <ostream>
#include <vector>

namespace vl::test {

// The mesh as sets: vertices (u,v, position) and triangles as rotated (u,v) corner triples, sorted.
struct Snapshot {
    std::vector<std::array<double, 5>> vertices;
    std::vector<std::array<double, 6>> triangles;
    bool operator==(const Snapshot&) const = default;
};

inline void PrintTo(const Snapshot& s, std::ostream* os) {
    *os << s.vertices.size() << " vertices, " << s.triangles.size() << " triangles";
}

inline Snapshot snapshot(const AdaptiveMesh& am) {
    Snapshot s;
    const auto& m = am.mesh();
    for (const auto v : m.vertices()) {
        const Vec2 uv = am.uv(v);
        const Vec3& p = am.position(v);
        s.vertices.push_back({uv[0], uv[1], p[0], p[1], p[2]});
    }
    for (const auto f : m.faces()) {
        std::vector<std::array<double, 2>> c;
        for (const auto v : m.fv_range(f)) c.push_back({am.uv(v)[0], am.uv(v)[1]});
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        s.triangles.push_back({c[0][0], c[0][1], c[1][0], c[1][1], c[2][0], c[2][1]});
    }
    std::sort(s.vertices.begin(), s.vertices.end());
    std::sort(s.triangles.begin(), s.triangles.end());
    return s;
}

#define EXPECT_MESH_VALID(am)                                                                                \
    do {                                                                                                     \
        const auto violations_ = ::vl::checkAdaptiveMesh(am);                                                \
        EXPECT_TRUE(violations_.empty()) << violations_.size() << " violations, first: " << violations_[0];  \
    } while (0)

} // namespace vl::test
