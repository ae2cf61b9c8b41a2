#include "AnalyticSurfaces.h"
#include "TestSupport.h"

#include "core/adaptive/Criteria.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

using test::BumpySurface;
using test::snapshot;

std::vector<OpenMesh::VertexHandle> weldableVertices(const AdaptiveMesh& am) {
    std::vector<OpenMesh::VertexHandle> out;
    for (const auto v : am.mesh().vertices())
        if (am.canWeld(v)) out.push_back(v);
    return out;
}

AdaptiveMesh& refineToDepth(AdaptiveMesh& am, int depth) {
    CriterionSettings settings;
    settings.depth.depth = depth;
    am.refine(*makeCriterion(settings));
    return am;
}

std::vector<OpenMesh::FaceHandle> liveFaces(const AdaptiveMesh& am) {
    std::vector<OpenMesh::FaceHandle> out;
    for (const auto f : am.mesh().faces()) out.push_back(f);
    return out;
}

TEST(AdaptiveMesh, BaseMeshSatisfiesTheInvariants) {
    for (const auto method : {RbmtMethod::Auto, RbmtMethod::SplitEdges}) {
        for (const auto& [name, domain] : test::testDomains()) {
            SCOPED_TRACE(name);
            const BumpySurface surface(domain);
            const AdaptiveMesh am(surface, method);
            EXPECT_EQ(am.faceCount(), am.base().triangles.size());
            EXPECT_EQ(am.vertexCount(), am.base().uvs.size());
            EXPECT_EQ(am.maxLevel(), 0);
            EXPECT_MESH_VALID(am);
        }
    }
}

TEST(AdaptiveMesh, UniformDepthDoublesTheFacesPerLevel) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const BumpySurface surface(domain);
        for (int depth = 0; depth <= 5; ++depth) {
            AdaptiveMesh am(surface);
            refineToDepth(am, depth);
            EXPECT_EQ(am.faceCount(), am.base().triangles.size() << depth) << "depth " << depth;
            EXPECT_EQ(am.maxLevel(), depth);
            for (const auto f : am.mesh().faces()) ASSERT_EQ(am.level(f), depth);
            EXPECT_MESH_VALID(am);
        }
    }
}

TEST(AdaptiveMesh, SplitThenWeldRestoresTheMeshExactly) {
    const BumpySurface surface(test::gridDomain(4, 4, test::Diagonals::Random, 0.25, false, 5));
    AdaptiveMesh am(surface);
    std::mt19937 rng(11);
    for (int step = 0; step < 60; ++step) {
        const auto faces = liveFaces(am);
        const auto f = faces[rng() % faces.size()];
        if (am.level(f) >= 6) continue;
        const auto before = snapshot(am);
        const auto firstNew = static_cast<int>(am.mesh().n_vertices());
        am.refineFace(f); // may force splits of coarser neighbours first
        // Undo in reverse creation order: each weld inverts the latest split.
        for (int v = static_cast<int>(am.mesh().n_vertices()) - 1; v >= firstNew; --v) {
            ASSERT_TRUE(am.canWeld(am.mesh().vertex_handle(v)));
            am.weld(am.mesh().vertex_handle(v));
        }
        EXPECT_EQ(snapshot(am), before);
        EXPECT_MESH_VALID(am);
        // Grow the mesh for the next round with some other refinement.
        am.collectGarbage();
        const auto next = liveFaces(am)[rng() % am.faceCount()];
        if (am.level(next) < 6) am.refineFace(next);
    }
}

TEST(AdaptiveMesh, ResplittingAWeldedBlockGivesBackTheSameVertex) {
    const BumpySurface surface(test::gridDomain(3, 3, test::Diagonals::Alternating));
    AdaptiveMesh am(surface);
    refineToDepth(am, 3);
    const auto refined = snapshot(am);
    for (const auto v : weldableVertices(am)) {
        const Vec3 position = am.position(v);
        const Vec2 uv = am.uv(v);
        const auto restored = am.weld(v);
        ASSERT_FALSE(restored.empty());
        const auto h = am.refinementHalfedge(restored.front());
        const auto again = am.splitBlock(am.mesh().edge_handle(h));
        EXPECT_EQ(am.uv(again), uv);
        EXPECT_EQ(am.position(again), position);
    }
    EXPECT_EQ(snapshot(am), refined);
    EXPECT_MESH_VALID(am);
}

TEST(AdaptiveMesh, RandomSplitWeldSequencesKeepTheInvariants) {
    const auto domains = test::testDomains();
    for (const auto method : {RbmtMethod::Auto, RbmtMethod::SplitEdges}) {
        for (std::size_t d = 0; d < domains.size(); ++d) {
            SCOPED_TRACE(domains[d].name);
            const BumpySurface surface(domains[d].domain);
            AdaptiveMesh am(surface, method);
            const auto base = snapshot(am);
            std::mt19937 rng(static_cast<unsigned>(100 + d));
            for (int step = 0; step < 250; ++step) {
                if (rng() % 10 < 6) {
                    const auto faces = liveFaces(am);
                    const auto f = faces[rng() % faces.size()];
                    if (am.level(f) < 7) am.refineFace(f);
                } else if (const auto weldable = weldableVertices(am); !weldable.empty()) {
                    am.weld(weldable[rng() % weldable.size()]);
                }
                if (step % 50 == 49) am.collectGarbage();
                const auto violations = checkAdaptiveMesh(am);
                ASSERT_TRUE(violations.empty()) << "step " << step << ": " << violations[0];
            }
            // Welding whatever can be welded, repeatedly, returns to the base mesh.
            for (auto weldable = weldableVertices(am); !weldable.empty(); weldable = weldableVertices(am))
                for (const auto v : weldable)
                    if (am.canWeld(v)) am.weld(v);
            EXPECT_EQ(snapshot(am), base);
            EXPECT_MESH_VALID(am);
        }
    }
}

TEST(AdaptiveMesh, OperatorsRejectWhatTheStructureForbids) {
    const BumpySurface surface(test::gridDomain(2, 2, test::Diagonals::Alternating));
    AdaptiveMesh am(surface);
    for (const auto v : am.mesh().vertices()) {
        EXPECT_FALSE(am.canWeld(v));
        EXPECT_THROW(am.weld(v), std::logic_error);
    }
    int blockEdges = 0;
    for (const auto e : am.mesh().edges()) {
        if (am.isBlockEdge(e))
            ++blockEdges;
        else
            EXPECT_THROW(am.splitBlock(e), std::logic_error);
    }
    EXPECT_EQ(blockEdges, 4); // one diagonal per cell
    // A refined vertex whose children were split further cannot be welded.
    const auto v = am.refineFace(*am.mesh().faces().begin());
    EXPECT_TRUE(am.canWeld(v));
    const auto child = *am.mesh().vf_range(v).begin();
    am.refineFace(child);
    EXPECT_FALSE(am.canWeld(v));
    EXPECT_MESH_VALID(am);
}

TEST(AdaptiveMesh, ExportsLiveVerticesAndTriangles) {
    const BumpySurface surface(test::gridDomain(3, 2, test::Diagonals::Same));
    AdaptiveMesh am(surface);
    refineToDepth(am, 2);
    am.weld(weldableVertices(am).front());
    const MeshData data = am.toMeshData();
    EXPECT_EQ(data.positions.size(), am.vertexCount());
    EXPECT_EQ(data.uvs.size(), am.vertexCount());
    EXPECT_EQ(data.triangles.size(), am.faceCount());
    for (std::size_t i = 0; i < data.positions.size(); ++i)
        EXPECT_EQ(data.positions[i], surface.sample(data.uvs[i]));
    for (const auto& t : data.triangles)
        for (const auto v : t) EXPECT_LT(v, data.positions.size());
}

} // namespace
} // namespace vl
