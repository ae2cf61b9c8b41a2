// The adaptive mesh on the bundled deformable face: the face domain (with its mouth hole) as base,
// the cascade as sampling function.
#include "TestSupport.h"

#include "core/adaptive/CascadeSurface.h"
#include "core/adaptive/ContourError.h"
#include "core/common/Error.h"
#include "core/deform/BundledFace.h"
#include "core/deform/FaceDomain.h"
#include "core/deform/Visemes.h"

#include <gtest/gtest.h>

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
        SCOPED_TRACE(std::string(criterionName(kind)));
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
