#include "AnalyticSurfaces.h"
#include "TestSupport.h"

#include "core/adaptive/ContourError.h"
#include "core/adaptive/Criteria.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace vl {
namespace {

using test::BumpySurface;
using test::snapshot;

// Reference contour error of one face: its own loop over the barycentric grid (sub-triangle corners
// enumerated, centroid taken), not the library's pattern.
TriangleError referenceError(const Surface& s, const AdaptiveMesh& am, OpenMesh::FaceHandle f, int n) {
    std::array<Vec2, 3> uv;
    std::array<Vec3, 3> p;
    int k = 0;
    for (const auto v : am.mesh().fv_range(f)) {
        uv[k] = am.uv(v);
        p[k++] = am.position(v);
    }
    auto corner = [&](int i, int j) { return Vec3(n - i - j, i, j) / double(n); };
    TriangleError e;
    int count = 0;
    auto visit = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 w = (a + b + c) / 3.0;
        const double err =
            (s.sample(w[0] * uv[0] + w[1] * uv[1] + w[2] * uv[2]) - (w[0] * p[0] + w[1] * p[1] + w[2] * p[2]))
                .norm();
        e.average += err;
        e.maximum = std::max(e.maximum, err);
        ++count;
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            visit(corner(i, j), corner(i + 1, j), corner(i, j + 1));
            if (i + j + 2 <= n) visit(corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
        }
    e.average /= count;
    return e;
}

void expectContourSatisfied(const AdaptiveMesh& am, const CriterionSettings& s) {
    int refinedToCap = 0;
    for (const auto f : am.mesh().faces()) {
        const auto e = referenceError(am.surface(), am, f, s.contour.samplesPerSide);
        const bool ok = e.average <= s.contour.averageError && e.maximum <= s.contour.maximumError;
        if (!ok) ++refinedToCap;
        EXPECT_TRUE(ok || am.level(f) == s.maxDepth) << "face " << f.idx() << " level " << am.level(f);
    }
    (void)refinedToCap;
}

// Reference normals test on the exported arrays: face normals, averaged vertex normals, every edge.
void expectNormalsSatisfied(const AdaptiveMesh& am, const CriterionSettings& s) {
    const MeshData d = am.toMeshData();
    std::vector<Vec3> faceN(d.triangles.size()), vertexSum(d.positions.size(), Vec3(0, 0, 0));
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const auto& tri = d.triangles[t];
        Vec3 n = OpenMesh::cross(d.positions[tri[1]] - d.positions[tri[0]],
                                 d.positions[tri[2]] - d.positions[tri[0]]);
        faceN[t] = n / n.norm();
        for (const auto v : tri) vertexSum[v] += faceN[t];
    }
    auto angle = [](Vec3 a, Vec3 b) {
        return std::acos(std::clamp(OpenMesh::dot(a.normalized(), b.normalized()), -1.0, 1.0));
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edgeFaces;
    for (std::size_t t = 0; t < d.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            auto a = d.triangles[t][k], b = d.triangles[t][(k + 1) % 3];
            edgeFaces[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    // Face levels in export order (the export lists live faces in handle order).
    std::vector<int> level;
    for (const auto f : am.mesh().faces()) level.push_back(am.level(f));
    const double dihedral = s.normals.dihedralAngleDeg * std::numbers::pi / 180;
    const double endpoint = s.normals.normalAngleDeg * std::numbers::pi / 180;
    const double slack = 1e-9;
    for (const auto& [edge, faces] : edgeFaces) {
        bool bad = angle(vertexSum[edge.first], vertexSum[edge.second]) > endpoint + slack;
        if (faces.size() == 2) bad = bad || angle(faceN[faces[0]], faceN[faces[1]]) > dihedral + slack;
        if (!bad) continue;
        for (const auto t : faces)
            EXPECT_EQ(level[t], s.maxDepth) << "edge " << edge.first << "-" << edge.second;
    }
}

// Adapting again without a change of the surface changes nothing.
void expectAdaptChangesNothing(AdaptiveMesh& am, const Criterion& criterion) {
    const auto settled = snapshot(am);
    const auto again = am.adapt(criterion);
    EXPECT_EQ(again.splits, 0u);
    EXPECT_EQ(again.welds, 0u);
    EXPECT_EQ(snapshot(am), settled);
}

CriterionSettings contourSettings(double average, double maximum, int maxDepth = 9) {
    CriterionSettings s;
    s.kind = CriterionKind::Contour;
    s.maxDepth = maxDepth;
    s.contour.averageError = average;
    s.contour.maximumError = maximum;
    return s;
}

CriterionSettings normalsSettings(double dihedral, double endpoint, int maxDepth = 7) {
    CriterionSettings s;
    s.kind = CriterionKind::Normals;
    s.maxDepth = maxDepth;
    s.normals.dihedralAngleDeg = dihedral;
    s.normals.normalAngleDeg = endpoint;
    return s;
}

TEST(Refinement, ContourCriterionHoldsOnEveryFaceOrTheCap) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const BumpySurface surface(domain);
        for (const auto& s : {contourSettings(0.004, 0.015), contourSettings(0.001, 0.004, 6)}) {
            AdaptiveMesh am(surface);
            const auto stats = am.refine(*makeCriterion(s));
            EXPECT_GT(stats.splits, 0u);
            expectContourSatisfied(am, s);
            EXPECT_MESH_VALID(am);
            EXPECT_LE(am.maxLevel(), s.maxDepth);
        }
    }
}

TEST(Refinement, ContourRefinementIsAdaptiveAndMeetsTheMeasuredError) {
    const BumpySurface surface(test::gridDomain(4, 4, test::Diagonals::Alternating));
    const auto s = contourSettings(0.002, 0.01, 12);
    AdaptiveMesh am(surface);
    am.refine(*makeCriterion(s));
    // Finer near the sharp bump than on the ripples: levels differ across the domain.
    int lo = 99, hi = 0;
    for (const auto f : am.mesh().faces()) lo = std::min(lo, am.level(f)), hi = std::max(hi, am.level(f));
    EXPECT_GE(hi - lo, 3);
    const auto measured = measureContourError(am.toMeshData(), surface, 8);
    EXPECT_LT(measured.average, s.contour.averageError);
    EXPECT_LT(measured.maximum, 2 * s.contour.maximumError); // other sample points than the test's
}

// The mesh as a set of (u,v) triangles with their positions, independent of element order.
std::vector<std::array<double, 15>> canonicalTriangles(const AdaptiveMesh& am) {
    const MeshData m = am.toMeshData();
    std::vector<std::array<double, 15>> out;
    for (const auto& t : m.triangles) {
        std::array<std::array<double, 5>, 3> corners;
        for (int k = 0; k < 3; ++k) {
            const auto v = t[static_cast<std::size_t>(k)];
            corners[static_cast<std::size_t>(k)] = {m.uvs[v][0], m.uvs[v][1], m.positions[v][0],
                                                    m.positions[v][1], m.positions[v][2]};
        }
        std::sort(corners.begin(), corners.end());
        std::array<double, 15> row;
        for (int k = 0; k < 15; ++k)
            row[static_cast<std::size_t>(k)] =
                corners[static_cast<std::size_t>(k / 5)][static_cast<std::size_t>(k % 5)];
        out.push_back(row);
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Refinement, RoundsGiveTheMeshOfTheOneFaceAtATimeReference) {
    // refine() tests a round of faces in parallel and splits afterwards; the obvious reference splits
    // any face that fails, one at a time, until a pass over all faces splits nothing. For a criterion
    // that reads only the face itself (contour, depth) the refined mesh is unique: both must agree.
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const BumpySurface surface(domain);
        CriterionSettings depth;
        depth.kind = CriterionKind::Depth;
        depth.depth.depth = 4;
        for (const auto& s : {contourSettings(0.004, 0.015), contourSettings(0.001, 0.004, 6), depth}) {
            const auto criterion = makeCriterion(s);
            AdaptiveMesh rounds(surface);
            rounds.refine(*criterion);
            AdaptiveMesh reference(surface);
            for (bool split = true; split;) {
                split = false;
                std::vector<AdaptiveMesh::FaceHandle> faces(reference.mesh().faces_begin(),
                                                            reference.mesh().faces_end());
                for (const auto f : faces)
                    if (!reference.mesh().status(f).deleted() && reference.level(f) < criterion->maxDepth() &&
                        criterion->needsRefinement(reference, f)) {
                        reference.refineFace(f);
                        split = true;
                    }
            }
            EXPECT_EQ(rounds.faceCount(), reference.faceCount());
            EXPECT_TRUE(canonicalTriangles(rounds) == canonicalTriangles(reference));
        }
    }
}

TEST(Refinement, NormalsCriterionHoldsOnEveryEdgeOrTheCap) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const BumpySurface surface(domain);
        for (const auto& s : {normalsSettings(15, 15), normalsSettings(8, 30, 6)}) {
            AdaptiveMesh am(surface);
            am.refine(*makeCriterion(s));
            expectNormalsSatisfied(am, s);
            EXPECT_MESH_VALID(am);
        }
    }
}

TEST(Refinement, SphereCapErrorFallsWithDepth) {
    const test::FunctionSurface cap(test::gridDomain(2, 2, test::Diagonals::Alternating), test::sphereCap);
    double previous = 1e9;
    for (int depth = 0; depth <= 6; depth += 2) {
        AdaptiveMesh am(cap);
        CriterionSettings s;
        s.depth.depth = depth;
        am.refine(*makeCriterion(s));
        const auto e = measureContourError(am.toMeshData(), cap);
        EXPECT_LT(e.average, previous / 3.5) << "depth " << depth; // two bisections quarter the error
        previous = e.average;
    }
}

TEST(Refinement, SimplifyWeldsBackToTheShallowerDepth) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        const BumpySurface surface(domain);
        AdaptiveMesh am(surface);
        CriterionSettings s;
        s.depth.depth = 5;
        am.refine(*makeCriterion(s));
        s.depth.depth = 2;
        const auto stats = am.simplify(*makeCriterion(s));
        EXPECT_EQ(am.faceCount(), am.base().triangles.size() << 2);
        EXPECT_GT(stats.welds, 0u);
        EXPECT_MESH_VALID(am);
        AdaptiveMesh fresh(surface);
        fresh.refine(*makeCriterion(s));
        EXPECT_EQ(snapshot(am), snapshot(fresh));
    }
}

TEST(Refinement, ReadaptsAfterAParameterChange) {
    for (const auto& [name, domain] : test::testDomains()) {
        SCOPED_TRACE(name);
        BumpySurface surface(domain, 1.0);
        const auto s = contourSettings(0.003, 0.01, 8);
        const auto criterion = makeCriterion(s);
        AdaptiveMesh am(surface);
        const auto base = snapshot(am);
        am.refine(*criterion);
        const auto bumpy = am.faceCount();
        EXPECT_GT(bumpy, base.triangles.size());

        surface.setAmplitude(0.0); // flat: every weld is allowed, back to the base mesh
        am.adapt(*criterion);
        EXPECT_MESH_VALID(am);
        EXPECT_EQ(snapshot(am), snapshot(AdaptiveMesh(surface)));
        EXPECT_EQ(snapshot(am).triangles, base.triangles);

        surface.setAmplitude(0.5);
        am.adapt(*criterion);
        EXPECT_MESH_VALID(am);
        expectContourSatisfied(am, s);
        surface.setAmplitude(1.0);
        am.adapt(*criterion);
        EXPECT_MESH_VALID(am);
        expectContourSatisfied(am, s);
        expectAdaptChangesNothing(am, *criterion);
    }
}

TEST(Refinement, NormalsReadaptationIsStable) {
    BumpySurface surface(test::gridDomain(5, 5, test::Diagonals::Random, 0.2, false, 9), 1.0);
    const auto criterion = makeCriterion(normalsSettings(12, 12, 6));
    AdaptiveMesh am(surface);
    am.refine(*criterion);
    surface.setAmplitude(0.4);
    am.adapt(*criterion);
    EXPECT_MESH_VALID(am);
    expectNormalsSatisfied(am, normalsSettings(12, 12, 6));
    expectAdaptChangesNothing(am, *criterion);
}

TEST(Refinement, MaxDepthCapsEveryCriterion) {
    const BumpySurface surface(test::gridDomain(3, 3, test::Diagonals::Same));
    for (const auto kind : {CriterionKind::Depth, CriterionKind::Normals, CriterionKind::Contour}) {
        CriterionSettings s = contourSettings(0, 0, 4);
        s.kind = kind;
        s.depth.depth = 9;
        s.normals.dihedralAngleDeg = s.normals.normalAngleDeg = 0.0;
        AdaptiveMesh am(surface);
        am.refine(*makeCriterion(s));
        EXPECT_EQ(am.maxLevel(), 4) << toString(kind);
        EXPECT_EQ(am.faceCount(), am.base().triangles.size() << 4) << toString(kind);
    }
}

TEST(Refinement, SettingsAreValidatedAndNamed) {
    EXPECT_EQ(parseEnum<CriterionKind>("contour", "--criterion"), CriterionKind::Contour);
    EXPECT_THROW(parseEnum<CriterionKind>("curvature", "--criterion"), InputError);
    CriterionSettings s;
    s.maxDepth = 31;
    EXPECT_THROW(makeCriterion(s), InputError);
    s = CriterionSettings{};
    s.contour.averageError = -1;
    EXPECT_THROW(makeCriterion(s), InputError);
    s = CriterionSettings{};
    s.normals.dihedralAngleDeg = std::nan("");
    EXPECT_THROW(makeCriterion(s), InputError);
    s = CriterionSettings{};
    s.contour.samplesPerSide = 0;
    EXPECT_THROW(makeCriterion(s), InputError);
}

} // namespace
} // namespace vl
