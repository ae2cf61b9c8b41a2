#include "AnalyticSurfaces.h"

#include "core/adaptive/RbmtBase.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <set>

namespace vl {
namespace {

double uvArea(const std::vector<Vec2>& uvs, const std::vector<Triangle>& tris) {
    double area = 0.0;
    for (const auto& t : tris) {
        const Vec2 e1 = uvs[t[1]] - uvs[t[0]], e2 = uvs[t[2]] - uvs[t[0]];
        area += 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
    }
    return area;
}

TEST(RbmtBase, PairsEveryTestDomainWithoutSplits) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const RbmtBase base = makeRbmtBase(domain);
        EXPECT_TRUE(isUnionOfBasicBlocks(base));
        EXPECT_EQ(base.splitEdges, 0u);
        EXPECT_EQ(base.triangles.size(), domain.triangles.size());
        EXPECT_NEAR(uvArea(base.uvs, base.triangles), uvArea(domain.uvs, domain.triangles), 1e-12);
    }
}

TEST(RbmtBase, GridWithAlternatingDiagonalsPairsAlongTheDiagonals) {
    const MeshData d = test::gridDomain(4, 4, test::Diagonals::Alternating);
    const RbmtBase base = makeRbmtBase(d);
    for (std::size_t t = 0; t < base.triangles.size(); ++t) {
        const auto& tri = base.triangles[t];
        const Vec2 e =
            base.uvs[tri[(base.refinementEdge[t] + 1) % 3]] - base.uvs[tri[base.refinementEdge[t]]];
        EXPECT_NEAR(e.norm(), std::sqrt(2.0) / 4, 1e-12) << "triangle " << t;
    }
}

TEST(RbmtBase, SplitConstructionMakesTwoOrFourTrianglesEach) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const RbmtBase base = makeRbmtBase(domain, RbmtMethod::SplitEdges);
        EXPECT_TRUE(isUnionOfBasicBlocks(base));
        EXPECT_GT(base.splitEdges, 0u);
        // Every triangle has 1 or 3 split edges: 2m <= triangles <= 4m and the count is m + splits
        // counted per triangle side, i.e. the parity argument of the construction.
        EXPECT_GE(base.triangles.size(), 2 * domain.triangles.size());
        EXPECT_LE(base.triangles.size(), 4 * domain.triangles.size());
        std::vector<Vec2> used; // the domain's used vertices, in order, come first
        std::set<std::uint32_t> usedIndex;
        for (const auto& t : domain.triangles) usedIndex.insert(t.begin(), t.end());
        for (const auto i : usedIndex) used.push_back(domain.uvs[i]);
        EXPECT_EQ(base.uvs.size(), used.size() + base.splitEdges);
        EXPECT_NEAR(uvArea(base.uvs, base.triangles), uvArea(domain.uvs, domain.triangles), 1e-12);
        for (std::size_t i = 0; i < used.size(); ++i) EXPECT_EQ(base.uvs[i], used[i]);
    }
}

// Irregular triangulations (random flips of jittered grids, with and without a hole): the automatic
// construction always yields blocks, usually without splitting anything.
TEST(RbmtBase, IrregularDomainsAlwaysBecomeBlocks) {
    int splitDomains = 0;
    for (unsigned seed = 0; seed < 60; ++seed) {
        SCOPED_TRACE(seed);
        const MeshData grid = test::gridDomain(7, 6, test::Diagonals::Random, 0.3, seed % 3 == 0, seed);
        const MeshData d = test::flipRandomEdges(grid, 40, seed);
        EXPECT_NE(d.triangles, grid.triangles);
        const RbmtBase base = makeRbmtBase(d);
        EXPECT_TRUE(isUnionOfBasicBlocks(base));
        EXPECT_NEAR(uvArea(base.uvs, base.triangles), uvArea(d.uvs, d.triangles), 1e-12);
        splitDomains += base.splitEdges > 0;
    }
    EXPECT_LE(splitDomains, 6); // the pairing steps find blocks for (nearly) all of them
}

TEST(RbmtBase, AcceptsClockwiseDomainsAndDropsUnusedVertices) {
    MeshData d = test::gridDomain(2, 2, test::Diagonals::Same);
    for (auto& t : d.triangles) std::swap(t[1], t[2]);
    d.uvs.emplace_back(5.0, 5.0); // unused
    const RbmtBase base = makeRbmtBase(d);
    EXPECT_EQ(base.uvs.size(), 9u);
    EXPECT_NEAR(uvArea(base.uvs, base.triangles), 1.0, 1e-12);
    EXPECT_TRUE(isUnionOfBasicBlocks(base));
}

void expectInputError(const MeshData& d, const std::string& fragment) {
    try {
        (void)makeRbmtBase(d);
        FAIL() << "no error, expected: " << fragment;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(RbmtBase, RejectsBadDomainsNamingTheTriangle) {
    MeshData empty;
    expectInputError(empty, "no triangles");
    MeshData d = test::gridDomain(2, 2, test::Diagonals::Same);
    MeshData degenerate = d;
    degenerate.triangles[3] = {0, 1, 2}; // collinear corners along v = 0
    expectInputError(degenerate, "triangle 3 is degenerate");
    MeshData flipped = d;
    std::swap(flipped.triangles[5][1], flipped.triangles[5][2]);
    expectInputError(flipped, "triangle 5 is oriented opposite");
    MeshData outOfRange = d;
    outOfRange.triangles[2][0] = 99;
    expectInputError(outOfRange, "triangle 2 has a vertex");
    MeshData nonFinite = d;
    nonFinite.uvs[4][0] = std::nan("");
    expectInputError(nonFinite, "vertex 4 has a non-finite");
}

} // namespace
} // namespace vl
