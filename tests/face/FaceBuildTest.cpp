// A user's own face as the deformable model (core/face): the texture-space locator against brute
// force, the thin-plate spline's defining properties, and buildFace on analytic surfaces whose
// geometry is known everywhere (so the sampled base geometry can be checked point by point).
#include "core/face/FaceBuild.h"
#include "core/common/Error.h"
#include "core/face/FaceAlignment.h"
#include "core/face/FaceFrame.h"
#include "core/face/FaceShape.h"
#include "core/face/ThinPlateSpline.h"
#include "core/face/UvMesh.h"

#include "tests/face/SharedFaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vl::face {
namespace {

using test::canonicalLandmarks;

// A smooth face-sized surface over texture space: x to the face's left, y up, z out of the face
// (symmetric in x, so the landmark frame's right axis is exactly +x).
Vec3 analyticSurface(const Vec2& uv) {
    const double x = 12.0 * (uv[0] - 0.5), y = 12.0 * (uv[1] - 0.5);
    return {x, y, 2.0 * std::cos(0.2 * x) + 0.5 * std::sin(0.3 * y)};
}

// A grid over [lo, hi]^2 in texture space with (u,v) = the grid point, positions on the analytic
// surface; triangles whose centroid `keep` rejects are left out (holes).
template <class Keep> MeshData analyticGrid(double lo, double hi, int cells, Keep keep) {
    MeshData mesh;
    const double h = (hi - lo) / cells;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const Vec2 uv(lo + i * h, lo + j * h);
            mesh.uvs.push_back(uv);
            mesh.positions.push_back(analyticSurface(uv));
        }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const Vec2 centre(lo + (i + 0.5) * h, lo + (j + 0.5) * h);
            if (!keep(centre)) continue;
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

// Brute force: the first triangle of the islands whose (u,v) triangle holds p.
UvHit locateByBruteForce(const UvMesh& mesh, const Vec2& p) {
    UvHit hit;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tex = mesh.texTriangles[t];
        double b[3];
        barycentric(p, mesh.texCoords[tex[0]], mesh.texCoords[tex[1]], mesh.texCoords[tex[2]], b);
        if (b[0] < -1e-12 || b[1] < -1e-12 || b[2] < -1e-12) continue;
        hit.found = true;
        hit.triangle = t;
        hit.position = Vec3(0, 0, 0);
        for (int k = 0; k < 3; ++k) {
            hit.b[k] = b[k];
            hit.position += mesh.positions[mesh.triangles[t][k]] * b[k];
        }
        return hit;
    }
    return hit;
}

bool outsideEyesAndMouth(const Vec2& c) {
    for (const double side : {-1.0, 1.0})
        if ((c - Vec2(0.5 + side * 0.144, 0.5875)).norm() < 0.04) return false;
    return !(std::abs(c[1] - 0.3) < 0.008 && std::abs(c[0] - 0.5) < 0.09);
}

TEST(UvLocator, AgreesWithBruteForceOnAMeshWithHoles) {
    const MeshData grid = analyticGrid(-0.2, 1.2, 70, outsideEyesAndMouth);
    const UvMesh mesh = makeUvMesh(grid, "grid");
    ASSERT_EQ(mesh.islandCount, 1u);
    const std::uint32_t islands[] = {0};
    const UvLocator locator(mesh, islands, 1e-9);
    std::mt19937 random(15);
    std::uniform_real_distribution<double> coordinate(-0.4, 1.4);
    std::size_t found = 0;
    for (int k = 0; k < 3000; ++k) {
        const Vec2 p(coordinate(random), coordinate(random));
        const UvHit fast = locator.locate(p), slow = locateByBruteForce(mesh, p);
        ASSERT_EQ(fast.found, slow.found) << "at (" << p[0] << ", " << p[1] << ")";
        if (!slow.found) continue;
        ++found;
        // On a shared edge the two may pick different triangles; the point is the same.
        EXPECT_LT((fast.position - slow.position).norm(), 1e-9) << "at (" << p[0] << ", " << p[1] << ")";
    }
    EXPECT_GT(found, 1000u); // the sample hit the mesh, and missed it around and in the holes
    EXPECT_LT(found, 3000u);
}

TEST(ThinPlateSpline, InterpolatesItsControlsAndReproducesAffineMaps) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<Vec2> controls, warped, affine;
    const auto affineMap = [](const Vec2& p) {
        return Vec2(0.3 + 1.2 * p[0] - 0.4 * p[1], -0.1 + 0.2 * p[0] + 0.9 * p[1]);
    };
    for (int k = 0; k < 12; ++k) {
        const Vec2 c(coordinate(random), coordinate(random));
        controls.push_back(c);
        affine.push_back(affineMap(c));
        warped.push_back(affineMap(c) + Vec2(0.05 * std::sin(9 * c[0]), 0.04 * std::cos(7 * c[1])));
    }
    const ThinPlateSpline exactlyAffine(controls, affine), bent(controls, warped);
    for (std::size_t k = 0; k < controls.size(); ++k)
        EXPECT_LT((bent(controls[k]) - warped[k]).norm(), 1e-9) << "control " << k;
    // The least bending map through points of an affine map is that map, everywhere.
    for (int k = 0; k < 200; ++k) {
        const Vec2 p(2 * coordinate(random) - 0.5, 2 * coordinate(random) - 0.5);
        EXPECT_LT((exactlyAffine(p) - affineMap(p)).norm(), 1e-9);
        EXPECT_NEAR(exactlyAffine.jacobianDeterminant(p), 1.2 * 0.9 + 0.4 * 0.2, 1e-6);
    }
    const std::vector<Vec2> collinear = {{0, 0}, {0.5, 0.5}, {1, 1}, {0.25, 0.25}};
    EXPECT_THROW(ThinPlateSpline(collinear, collinear), InputError);
}

// Sampling a known surface reproduces it: the base geometry field at every domain sample is the
// surface at the canonical point the alignment sends it to (no holes, so nothing is filled).
TEST(FaceBuild, SamplingAnAnalyticSurfaceReproducesIt) {
    const UvMesh mesh =
        makeUvMesh(analyticGrid(-0.6, 1.6, 220, [](const Vec2&) { return true; }), "analytic");
    const FaceLandmarks landmarks = canonicalLandmarks(mesh);
    FaceBuildOptions options;
    options.gridSize = 129;
    const BuiltFace built = buildFace(mesh, landmarks, options);
    EXPECT_TRUE(built.report.holes.empty());
    EXPECT_NEAR(built.report.domainCoverage, 1.0, 1e-9);
    EXPECT_EQ(built.report.filledSamples, 0u);
    EXPECT_EQ(built.report.foldedSamples, 0u);
    EXPECT_LT((built.report.frame.right - Vec3(1, 0, 0)).norm(), 1e-9);
    EXPECT_GT(built.report.frame.forward[2], 0.95);

    const std::uint32_t islands[] = {0};
    const UvLocator locator(mesh, islands, 1e-6);
    const FaceAlignment alignment(mesh, locator, landmarks);
    const SampledField* base = nullptr;
    for (const auto& stage : built.cascade.stages)
        if (stage.kind == StageKind::Constant) base = &stage.field.sampled;
    ASSERT_NE(base, nullptr);
    ASSERT_EQ(base->width, options.gridSize);
    double worst = 0.0;
    const int n = options.gridSize;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // The eye openings are opened into sockets behind the eyeballs (EyeOpeningTest.cpp).
            if (detail::eyeLens(double(i) / (n - 1), double(j) / (n - 1)).inside() > -0.5) continue;
            const Vec2 c = alignment.canonical(Vec2(double(i) / (n - 1), double(j) / (n - 1)));
            const Vec3 expected = analyticSurface(c);
            worst = std::max(worst, (base->samples[static_cast<std::size_t>(j) * n + i] - expected).norm());
        }
    // Linear interpolation on a 0.01 grid of a surface with curvature below 0.1 per unit, plus the
    // rounding of the stored samples: far below a millimetre on a 12-unit face.
    EXPECT_LT(worst, 2e-3);

    // The landmarks sit on the base geometry where the domain puts them. The eye corners are the tips
    // of the openings: interpolated with samples opened into the sockets one grid step away, they
    // may move back by up to a twentieth of the eye's width (1.6 units here).
    const auto onBase = baseLandmarkPositions(built.cascade);
    for (const auto l : allLandmarks()) {
        if (!isRequired(l)) continue;
        const bool eyeCorner = l == Landmark::EyeOuterLeft || l == Landmark::EyeOuterRight ||
                               l == Landmark::EyeInnerLeft || l == Landmark::EyeInnerRight;
        EXPECT_LT((onBase[static_cast<std::size_t>(l)] - landmarks[l].position).norm(),
                  eyeCorner ? 0.08 : 0.05)
            << toString(l);
    }
}

// Holes, seams and stray islands: the eye and mouth openings are reported and filled, an island that
// continues the face across a UV seam is used, a detached island overlapping the face in (u,v) (an
// eyeball, say) is not, and the report says why.
TEST(FaceBuild, ReportsIslandsAndFillsTheOpenings) {
    MeshData grid = analyticGrid(-0.6, 1.6, 220, outsideEyesAndMouth);
    // The columns past u = 1.2 get texture coordinates of their own, far away: a UV seam at u = 1.2.
    CornerTexCoords corners;
    corners.texCoords = grid.uvs;
    for (const auto& t : grid.triangles) {
        Triangle tex = t;
        const Vec2 centre = (grid.uvs[t[0]] + grid.uvs[t[1]] + grid.uvs[t[2]]) / 3.0;
        if (centre[0] > 1.2)
            for (int k = 0; k < 3; ++k) {
                corners.texCoords.push_back(grid.uvs[t[k]] + Vec2(5.0, 0.0));
                tex[k] = static_cast<std::uint32_t>(corners.texCoords.size() - 1);
            }
        corners.triangles.push_back(tex);
    }
    // A detached quad behind the face whose (u,v) lie on the face's.
    const auto first = static_cast<std::uint32_t>(grid.positions.size());
    for (const Vec2 uv : {Vec2(0.4, 0.4), Vec2(0.6, 0.4), Vec2(0.6, 0.6), Vec2(0.4, 0.6)}) {
        grid.positions.push_back(Vec3(uv[0], uv[1], -20.0));
        grid.uvs.push_back(uv);
        corners.texCoords.push_back(uv);
    }
    const auto firstTex = static_cast<std::uint32_t>(corners.texCoords.size() - 4);
    grid.triangles.push_back({first, first + 1, first + 2});
    grid.triangles.push_back({first, first + 2, first + 3});
    corners.triangles.push_back({firstTex, firstTex + 1, firstTex + 2});
    corners.triangles.push_back({firstTex, firstTex + 2, firstTex + 3});
    grid.uvs.clear();

    const UvMesh mesh = makeUvMesh(grid, corners, "seams.obj");
    ASSERT_EQ(mesh.islandCount, 3u);
    const BuiltFace built = buildFace(mesh, canonicalLandmarks(mesh));
    const auto& islands = built.report.islands;
    ASSERT_EQ(islands.size(), 3u);
    EXPECT_TRUE(islands[0].used);
    EXPECT_EQ(islands[0].landmarks, kLandmarkCount);
    int seam = -1, detached = -1;
    for (int k = 1; k < 3; ++k) (islands[k].island.triangles == 2 ? detached : seam) = k;
    ASSERT_GE(seam, 0);
    ASSERT_GE(detached, 0);
    EXPECT_TRUE(islands[seam].used) << islands[seam].reason;
    EXPECT_EQ(islands[seam].reason, "continues the face across a UV seam");
    EXPECT_FALSE(islands[detached].used);
    EXPECT_EQ(islands[detached].reason, "not joined to the face");

    std::vector<std::string> roles;
    for (const auto& h : built.report.holes) roles.push_back(h.role);
    for (const std::string role : {"eye_right", "eye_left", "mouth"})
        EXPECT_NE(std::find(roles.begin(), roles.end(), role), roles.end()) << role << " not reported";
    EXPECT_GT(built.report.filledSamples, 0u);
    // The detached quad sits 20 units behind the face: no sample may come from it.
    for (const auto& stage : built.cascade.stages) {
        if (stage.kind != StageKind::Constant) continue;
        for (const auto& s : stage.field.sampled.samples) ASSERT_GT(s[2], -5.0);
    }
}

TEST(FaceBuild, RefusesLandmarksThatDoNotDetermineAnAlignment) {
    const UvMesh mesh = makeUvMesh(analyticGrid(-0.6, 1.6, 60, [](const Vec2&) { return true; }), "flat");
    FaceLandmarks landmarks = canonicalLandmarks(mesh);
    landmarks[Landmark::NoseTip] = {};
    EXPECT_THROW(buildFace(mesh, landmarks), InputError);
    landmarks = canonicalLandmarks(mesh);
    // Mirrored layout: the left eye given the right eye's point.
    landmarks[Landmark::EyeOuterLeft] = landmarks[Landmark::EyeOuterRight];
    landmarks[Landmark::EyeInnerLeft] = landmarks[Landmark::EyeInnerRight];
    EXPECT_THROW(buildFace(mesh, landmarks), InputError);
}

} // namespace
} // namespace vl::face
