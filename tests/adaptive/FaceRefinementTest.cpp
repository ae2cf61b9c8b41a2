// The adaptive mesh on the bundled deformable face: the face domain (with its mouth hole) as base,
// the cascade as sampling function.
#include "TestSupport.h"

#include "core/adaptive/CascadeSurface.h"
#include "core/adaptive/ContourError.h"
#include "core/common/Error.h"
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

namespace vl {
namespace {

CascadeSurface bundledSurface(int resolution = 10) {
    const DeformationCascade cascade = face::makeBundledFace();
    return CascadeSurface(cascade, face::faceBaseDomain(resolution), cascade.defaults());
}

CriterionSettings settingsFor(CriterionKind kind) {
    CriterionSettings s;
    s.kind = kind;
    s.maxDepth = 7;
    return s;
}

TEST(FaceRefinement, BaseDomainIsPairedWithoutSplits) {
    const CascadeSurface surface = bundledSurface();
    const AdaptiveMesh mesh(surface);
    EXPECT_EQ(mesh.base().splitEdges, 0u);
    EXPECT_EQ(mesh.faceCount(), face::faceBaseDomain(10).triangles.size());
    EXPECT_MESH_VALID(mesh);
}

TEST(FaceRefinement, EveryCriterionKeepsTheInvariantsAndLowersTheError) {
    const CascadeSurface surface = bundledSurface();
    const AdaptiveMesh base(surface);
    const double baseError = measureContourError(base.toMeshData(), surface).average;
    for (const auto kind : {CriterionKind::Depth, CriterionKind::Normals, CriterionKind::Contour}) {
        SCOPED_TRACE(std::string(toString(kind)));
        AdaptiveMesh mesh(surface);
        mesh.refine(*makeCriterion(settingsFor(kind)));
        EXPECT_MESH_VALID(mesh);
        EXPECT_GT(mesh.faceCount(), base.faceCount());
        EXPECT_LT(measureContourError(mesh.toMeshData(), surface).average, baseError / 2);
        // No vertex falls inside the mouth hole (the hole's rim is made of straight (u,v) edges).
        for (const auto v : mesh.mesh().vertices())
            EXPECT_FALSE(face::insideMouthHole(mesh.uv(v)[0], mesh.uv(v)[1]));
    }
}

TEST(FaceRefinement, ReadaptsWhenTheJawOpens) {
    CascadeSurface surface = bundledSurface();
    const auto criterion = makeCriterion(settingsFor(CriterionKind::Contour));
    AdaptiveMesh mesh(surface);
    mesh.refine(*criterion);
    auto q = surface.parameters();
    q[static_cast<std::size_t>(surface.cascade().findParameter("jaw_open"))] = 1.0;
    surface.setParameters(q);
    const auto stats = mesh.adapt(*criterion);
    EXPECT_GT(stats.splits + stats.welds, 0u);
    EXPECT_MESH_VALID(mesh);
    // Closing it again returns to a mesh that satisfies the criterion for the neutral face.
    surface.setParameters(surface.cascade().defaults());
    mesh.adapt(*criterion);
    EXPECT_MESH_VALID(mesh);
    for (const auto f : mesh.mesh().faces())
        ASSERT_TRUE(mesh.level(f) == 7 || !criterion->needsRefinement(mesh, f));
    const auto again = mesh.adapt(*criterion);
    EXPECT_EQ(again.splits + again.welds, 0u);
}

TEST(FaceRefinement, OutsideTheChangedBoxEverySampleStaysTheSameToTheBit) {
    // setParameters names where the surface may have changed; re-adaptation trusts everything outside.
    CascadeSurface surface = bundledSurface();
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto& parameters = surface.cascade().parameters;
    for (std::size_t k = 0; k < parameters.size(); ++k) {
        SCOPED_TRACE(parameters[k].name);
        const auto before = surface.parameters();
        std::vector<Vec2> points(4000);
        for (auto& p : points) p = Vec2(unit(rng), unit(rng));
        std::vector<Vec3> old;
        for (const auto& p : points) old.push_back(surface.sample(p));
        auto q = before;
        q[k] = parameters[k].max;
        const UvBox changed = surface.setParameters(q);
        if (q[k] == before[k]) {
            EXPECT_TRUE(changed.empty());
            continue;
        }
        int outside = 0, moved = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Vec3 now = surface.sample(points[i]);
            if (!changed.contains(points[i])) {
                ++outside;
                EXPECT_TRUE(now == old[i]) << "(u,v) " << points[i];
            } else if (!(now == old[i])) {
                ++moved;
            }
        }
        EXPECT_GT(outside, 0) << "a muscle's field reaches all of the face";
        const bool movesSkin = surface.cascade().stages.end() !=
                               std::find_if(surface.cascade().stages.begin(), surface.cascade().stages.end(),
                                            [&](const DeformationStage& st) {
                                                return st.kind == StageKind::AddVector && st.parameter == k;
                                            });
        if (movesSkin) {
            EXPECT_GT(moved, 0);
        }
        EXPECT_TRUE(surface.setParameters(before).lo == changed.lo); // back: the same box
    }
}

TEST(FaceRefinement, LocalReadaptationTouchesOnlyTheChangedBoxAndSatisfiesTheCriterion) {
    CascadeSurface surface = bundledSurface();
    const auto criterion = makeCriterion(settingsFor(CriterionKind::Contour));
    AdaptiveMesh mesh(surface);
    mesh.refine(*criterion);
    const MeshData before = mesh.toMeshData();
    auto q = surface.parameters();
    q[static_cast<std::size_t>(surface.cascade().findParameter("frontalis_l"))] = 1.0; // one brow
    const UvBox changed = surface.setParameters(q);
    ASSERT_FALSE(changed.empty());
    const AdaptStats stats = mesh.adapt(*criterion, changed);
    EXPECT_FALSE(stats.rebuilt);
    EXPECT_GT(stats.splits, 0u);
    EXPECT_MESH_VALID(mesh);
    for (const auto f : mesh.mesh().faces())
        ASSERT_TRUE(mesh.level(f) == 7 || !criterion->needsRefinement(mesh, f));
    for (const auto v : mesh.mesh().vertices()) ASSERT_TRUE(mesh.position(v) == surface.sample(mesh.uv(v)));
    // Outside the box nothing is welded: every vertex farther from it than a ring's reach (the base
    // grid's spacing is 0.1) is still there; triangles there change only where the level restriction
    // forces a split next to a finer box.
    const MeshData after = mesh.toMeshData();
    std::set<std::pair<double, double>> afterUvs;
    for (const auto& uv : after.uvs) afterUvs.insert({uv[0], uv[1]});
    UvBox near = changed;
    near.lo -= Vec2(0.15, 0.15);
    near.hi += Vec2(0.15, 0.15);
    int far = 0;
    for (const auto& uv : before.uvs) {
        if (near.contains(uv)) continue;
        ++far;
        EXPECT_TRUE(afterUvs.count({uv[0], uv[1]})) << "(u,v) " << uv;
    }
    EXPECT_GT(far, static_cast<int>(before.uvs.size()) / 2);
    std::set<std::array<double, 6>> kept;
    const auto key = [](const MeshData& m, const Triangle& t) {
        std::array<std::pair<double, double>, 3> c;
        for (int k = 0; k < 3; ++k) c[k] = {m.uvs[t[k]][0], m.uvs[t[k]][1]};
        std::sort(c.begin(), c.end());
        return std::array<double, 6>{c[0].first,  c[0].second, c[1].first,
                                     c[1].second, c[2].first,  c[2].second};
    };
    for (const auto& t : after.triangles) kept.insert(key(after, t));
    int outside = 0, unchanged = 0;
    for (const auto& t : before.triangles) {
        UvBox box;
        for (int k = 0; k < 3; ++k) box.include({before.uvs[t[k]], before.uvs[t[k]]});
        if (changed.meets(box.lo, box.hi)) continue;
        ++outside;
        unchanged += kept.count(key(before, t)) ? 1 : 0;
    }
    EXPECT_GT(outside, static_cast<int>(before.triangles.size()) / 2);
    EXPECT_GT(unchanged, outside * 9 / 10);
}

TEST(FaceRefinement, AChangeReachingMostOfTheMeshRebuildsItAsAFreshRefinementWould) {
    CascadeSurface surface = bundledSurface();
    const auto criterion = makeCriterion(settingsFor(CriterionKind::Contour));
    AdaptiveMesh mesh(surface);
    mesh.refine(*criterion);
    std::vector<double> q; // every muscle at its maximum: the change reaches all of the face
    for (const auto& p : surface.cascade().parameters) q.push_back(p.max);
    const AdaptStats stats = mesh.adapt(*criterion, surface.setParameters(q));
    EXPECT_TRUE(stats.rebuilt);
    EXPECT_MESH_VALID(mesh);
    AdaptiveMesh fresh(surface);
    fresh.refine(*criterion);
    const MeshData a = mesh.toMeshData(), b = fresh.toMeshData();
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.positions, b.positions);
}

TEST(FaceRefinement, PoseRefinementSatisfiesTheCriterionForEveryPose) {
    CascadeSurface surface = bundledSurface();
    const auto settings = settingsFor(CriterionKind::Contour);
    const auto criterion = makeCriterion(settings);
    std::vector<std::vector<double>> poses{surface.cascade().defaults()};
    for (const auto& v : oculusVisemes()) poses.push_back(parameterVector(surface.cascade(), v));
    AdaptiveMesh mesh(surface);
    refineForPoses(mesh, surface, *criterion, poses);
    EXPECT_MESH_VALID(mesh);
    for (const auto& q : poses) {
        surface.setParameters(q);
        mesh.resample();
        for (const auto f : mesh.mesh().faces())
            ASSERT_TRUE(mesh.level(f) == settings.maxDepth || !criterion->needsRefinement(mesh, f));
    }
    // refineFaceMesh is the same construction in one call.
    const MeshData oneCall = refineFaceMesh(surface.cascade(), 10, settings, poses);
    EXPECT_EQ(oneCall.triangles.size(), mesh.faceCount());
    EXPECT_THROW(refineFaceMesh(surface.cascade(), 10, settings, {}), InputError);
}

TEST(FaceRefinement, SurfaceChecksParameters) {
    CascadeSurface surface = bundledSurface();
    auto q = surface.parameters();
    q[0] = 99.0;
    EXPECT_THROW(surface.setParameters(q), InputError);
    q.pop_back();
    EXPECT_THROW(surface.setParameters(q), InputError);
}

} // namespace
} // namespace vl
