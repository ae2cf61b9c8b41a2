// Faces nobody here made (from VISEMELAB_SHARED_DATA_DIR, skipped loudly when absent): the MediaPipe
// canonical face builds from its known layout and from its geometry alone (the two agree), deforms
// with the bundled visemes and refines; the ICT head (82 UV islands, open mouth and eyes) builds from
// its geometry. (The CLI end to end: tests/cli/FaceCliTest.cpp.)
#include "core/adaptive/CascadeSurface.h"
#include "core/adaptive/ContourError.h"
#include "core/deform/Visemes.h"
#include "core/face/FaceBuild.h"
#include "core/face/FaceDomain.h"
#include "core/face/LandmarkFinder.h"

#include "tests/face/SharedFaces.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl::face {
namespace {

using namespace test; // the shared faces

const VisemeParameters& viseme(const std::vector<VisemeParameters>& all, const std::string& name) {
    return *std::find_if(all.begin(), all.end(), [&](const VisemeParameters& v) { return v.name == name; });
}

TEST(OwnFaceData, MediaPipeLayoutAndGeometryFinderAgree) {
    SKIP_WITHOUT(kMediaPipe);
    const UvMesh mesh = loadUvMesh(kMediaPipe);
    const LandmarkSuggestion layout = suggestLandmarks(mesh);
    EXPECT_EQ(layout.layout, "mediapipe");
    ASSERT_TRUE(layout.landmarks.hasRequired());
    for (const auto l : allLandmarks()) EXPECT_EQ(layout.landmarks[l].source, LandmarkSource::Layout);

    const LandmarkSuggestion geometry = suggestLandmarks(mesh, {}, false);
    EXPECT_EQ(geometry.layout, "");
    ASSERT_TRUE(geometry.landmarks.hasRequired());
    const double eyes = (layout.landmarks[Landmark::EyeInnerLeft].position -
                         layout.landmarks[Landmark::EyeInnerRight].position)
                            .norm();
    // The canonical face's mouth and eyes are closed: the mouth is found from the groove between the
    // lips, the nose from the symmetry plane, the eyes from their sockets (ClosedEyesTest.cpp), all
    // within a fifth of the inner eye distance of the layout's vertices. Estimates say they are.
    for (const auto l : allLandmarks()) {
        if (!isRequired(l)) continue;
        const auto& found = geometry.landmarks[l];
        if (found.source == LandmarkSource::Estimate) {
            EXPECT_LE(found.confidence, 0.35) << toString(l);
            continue;
        }
        EXPECT_EQ(found.source, LandmarkSource::Geometry) << toString(l);
        EXPECT_LT((found.position - layout.landmarks[l].position).norm(), 0.2 * eyes)
            << toString(l) << ": " << found.method;
    }
    EXPECT_EQ(geometry.landmarks[Landmark::NoseTip].source, LandmarkSource::Geometry);
    EXPECT_EQ(geometry.landmarks[Landmark::MouthCornerLeft].source, LandmarkSource::Geometry);
}

TEST(OwnFaceData, MediaPipeFaceBuildsDeformsAndRefines) {
    SKIP_WITHOUT(kMediaPipe);
    const UvMesh mesh = loadUvMesh(kMediaPipe);
    const BuiltFace built = buildFace(mesh, suggestLandmarks(mesh).landmarks);
    EXPECT_TRUE(built.report.warnings.empty()) << built.report.warnings.front();
    const auto& frame = built.report.frame;
    EXPECT_GT(built.report.scale, 0.5);
    EXPECT_LT(built.report.scale, 2.0);

    // "aa" opens the jaw: the lower lip moves down the face, the upper lip much less; "ou" rounds the
    // lips forward.
    const auto visemes = oculusVisemes();
    const auto neutral = built.cascade.defaults();
    const auto aa = parameterVector(built.cascade, viseme(visemes, "aa"));
    const auto ou = parameterVector(built.cascade, viseme(visemes, "ou"));
    const Vec2 lowerLip(kMouthU, kMouthV - 0.04), upperLip(kMouthU, kMouthV + 0.04);
    const auto move = [&](const std::vector<double>& q, const Vec2& uv) {
        return built.cascade.evaluate(uv[0], uv[1], q) - built.cascade.evaluate(uv[0], uv[1], neutral);
    };
    const double down = -(move(aa, lowerLip) | frame.up);
    EXPECT_GT(down, 0.08 * frame.eyeMouthDistance);
    EXPECT_LT(std::abs(move(aa, upperLip) | frame.up), 0.5 * down);
    EXPECT_GT(move(ou, lowerLip) | frame.forward, 0.0);

    // Adaptive refinement for the visemes: the mouth is refined, and the error on the refined mesh
    // meets the thresholds (scaled with the face) that a 10-cell base mesh misses.
    CriterionSettings settings;
    settings.kind = CriterionKind::Contour;
    settings.maxDepth = 6;
    settings.contour.averageError = 0.04 * built.report.scale;
    settings.contour.maximumError = 0.16 * built.report.scale;
    const std::vector<std::vector<double>> poses = {neutral, aa, ou};
    AdaptStats stats;
    const MeshData refined = refineFaceMesh(built.cascade, 10, settings, poses, &stats);
    const MeshData base = faceBaseDomain(10);
    EXPECT_GT(stats.splits, 0u);
    EXPECT_GT(refined.positions.size(), base.positions.size());
    const CascadeSurface surface(built.cascade, base, aa);
    MeshData refinedAtAa = refined;
    for (std::size_t v = 0; v < refined.positions.size(); ++v)
        refinedAtAa.positions[v] = surface.sample(refined.uvs[v]);
    MeshData baseAtAa = base;
    for (std::size_t v = 0; v < base.positions.size(); ++v)
        baseAtAa.positions[v] = surface.sample(base.uvs[v]);
    const auto before = measureContourError(baseAtAa, surface, 4);
    const auto after = measureContourError(refinedAtAa, surface, 4);
    EXPECT_GT(before.maximum, settings.contour.maximumError);
    EXPECT_LT(after.average, settings.contour.averageError);
    EXPECT_LT(after.average, before.average / 2);
}

TEST(OwnFaceData, IctHeadBuildsFromItsGeometry) {
    SKIP_WITHOUT(kIct);
    const UvMesh mesh = loadUvMesh(kIct);
    EXPECT_GT(mesh.islandCount, 10u);
    const LandmarkSuggestion found = suggestLandmarks(mesh);
    ASSERT_TRUE(found.landmarks.hasRequired());
    const BuiltFace built = buildFace(mesh, found.landmarks, {129, "ict"});
    std::vector<std::string> roles;
    for (const auto& h : built.report.holes) roles.push_back(h.role);
    for (const std::string role : {"eye_right", "eye_left", "mouth"})
        EXPECT_NE(std::find(roles.begin(), roles.end(), role), roles.end()) << role << " not filled";
    std::size_t used = 0;
    for (const auto& is : built.report.islands) used += is.used;
    EXPECT_GT(used, 1u); // the face continues across UV seams
    EXPECT_LT(used, built.report.islands.size());
    EXPECT_EQ(built.report.foldedSamples, 0u);
    // The mouth corners are where the mesh's mouth opening ends, either side of the symmetry plane.
    const Vec3 r = found.landmarks[Landmark::MouthCornerRight].position,
               l = found.landmarks[Landmark::MouthCornerLeft].position;
    EXPECT_LT(r[0], 0.0);
    EXPECT_GT(l[0], 0.0);
    EXPECT_NEAR(r[0], -l[0], 0.05 * (l - r).norm());
}

} // namespace
} // namespace vl::face
