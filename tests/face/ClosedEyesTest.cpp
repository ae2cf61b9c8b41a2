// Closed eyes found from the shape of the face: the MediaPipe canonical face read without its layout
// (from VISEMELAB_SHARED_DATA_DIR, skipped loudly when absent) and the bundled faces (built in-process)
// have no eye openings; their eye corners must come out near their own, found from the geometry and
// said to be.
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/face/LandmarkFinder.h"

#include "tests/face/SharedFaces.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace vl::face {
namespace {

using namespace test; // the shared faces

constexpr Landmark kEyeCorners[] = {Landmark::EyeOuterRight, Landmark::EyeInnerRight, Landmark::EyeInnerLeft,
                                    Landmark::EyeOuterLeft};

// Each eye corner found from the geometry within `inner` (inner corners) or `outer` (outer corners)
// inner eye distances of `truth`.
void expectEyeCorners(const FaceLandmarks& found, const std::array<Vec3, kLandmarkCount>& truth, double inner,
                      double outer) {
    const auto at = [&](Landmark l) { return truth[static_cast<std::size_t>(l)]; };
    const double eyes = (at(Landmark::EyeInnerLeft) - at(Landmark::EyeInnerRight)).norm();
    for (const auto l : kEyeCorners) {
        const double error = (found[l].position - at(l)).norm() / eyes;
        const bool isInner = l == Landmark::EyeInnerRight || l == Landmark::EyeInnerLeft;
        if (std::getenv("VL_DEBUG"))
            std::printf("%-16s %-9s %3.0f%%  %.3f inner eye distances off  (%s)\n",
                        std::string(toString(l)).c_str(), std::string(sourceName(found[l].source)).c_str(),
                        100.0 * found[l].confidence, error, found[l].method.c_str());
        EXPECT_EQ(found[l].source, LandmarkSource::Geometry) << toString(l) << ": " << found[l].method;
        EXPECT_LT(error, isInner ? inner : outer) << toString(l) << ": " << found[l].method;
        EXPECT_LE(found[l].confidence, 0.6) << toString(l); // below what an opening earns
    }
}

TEST(ClosedEyes, MediaPipeFaceEyeCornersFromItsGeometryMatchTheLayout) {
    SKIP_WITHOUT(kMediaPipe);
    const UvMesh mesh = loadUvMesh(kMediaPipe);
    const FaceLandmarks layout = suggestLandmarks(mesh).landmarks;
    std::array<Vec3, kLandmarkCount> truth{};
    for (const auto l : allLandmarks()) truth[static_cast<std::size_t>(l)] = layout[l].position;
    expectEyeCorners(suggestLandmarks(mesh, {}, false).landmarks, truth, 0.1, 0.2);
}

// A bundled face as a user would export it: the face domain's triangulation (the mouth a hole, the
// eyes without openings: the lids fold into the socket), about `resolution` cells across, at the
// individual's base geometry.
UvMesh bundledFaceMesh(Individual who, int resolution) {
    const SampledField geometry = makeFaceGeometry(who);
    MeshData mesh = faceDomainMesh(resolution);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        mesh.positions[v] = geometry.at(mesh.uvs[v][0], mesh.uvs[v][1]);
    return makeUvMesh(mesh, "bundled face");
}

// Built in-process, no shared data: the bundled face and its retargeted individual (other proportions,
// deeper eyes), cut coarse and fine. Along their socket lines the eyes show as a dip between two ridges
// (the lids fold into the socket), not as the MediaPipe face's bulge; the corners must still come out
// near the faces' own (those of their face domains). (Before the socket's window reached 2 nose-to-mouth
// distances up, the bundled face cut 300 cells across lost one socket to the side of the nose.)
TEST(ClosedEyes, BundledFacesEyeCornersFromTheirGeometry) {
    for (const Individual who : {Individual::Bundled, Individual::Retarget})
        for (const int grid : {40, 60, 150, 300}) {
            SCOPED_TRACE(std::string(toString(who)) + " face, " + std::to_string(grid) + " cells");
            const UvMesh mesh = bundledFaceMesh(who, grid);
            const auto truth = baseLandmarkPositions(makeFaceCascade(who));
            expectEyeCorners(suggestLandmarks(mesh, {}, false).landmarks, truth, 0.15, 0.2);
        }
}

} // namespace
} // namespace vl::face
