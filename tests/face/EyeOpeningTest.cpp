// The eyes of a face built from a user's mesh are open as the bundled face's are (issue 32: they came
// out as closed slits): seen from the front, the eyeball shows between the lids over a height that is
// a fair fraction of the eye's width. Measured with rays from in front of the face along each eye's
// vertical line through its centre: where the first surface a ray meets is the eyeball (the head part
// eye_right / eye_left) and not the skin, the eye is open. On the bundled face (the reference), the
// bundled sample's neutral (assets/sample) and the MediaPipe canonical face (shared data, skipped loudly
// when absent).
#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceBuild.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/face/FaceShape.h"
#include "core/face/HeadParts.h"
#include "core/face/LandmarkFinder.h"
#include "core/paint/RayPick.h"

#include "tests/face/SharedFaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vl::face {
namespace {

using namespace test; // the shared faces

struct EyeOpening {
    double height = 0.0; // visible eyeball along the eye's vertical line, in the face's units
    double width = 0.0;  // corner to corner
};

// The eye on `side` (0 the face's right, 1 its left) of the face `cascade` at rest.
EyeOpening measureEye(const DeformationCascade& cascade, int side) {
    const auto landmarks = baseLandmarkPositions(cascade);
    const FaceFrame frame = frameFromLandmarks(landmarks);
    const Vec3 inner =
        landmarks[static_cast<std::size_t>(side == 0 ? Landmark::EyeInnerRight : Landmark::EyeInnerLeft)];
    const Vec3 outer =
        landmarks[static_cast<std::size_t>(side == 0 ? Landmark::EyeOuterRight : Landmark::EyeOuterLeft)];
    EyeOpening eye;
    eye.width = (outer - inner).norm();
    const Vec3 centre = 0.5 * (inner + outer);

    // The skin at rest on a fine domain mesh, and the eyeball.
    MeshData skin = faceDomainMesh(160, DomainDensity::MouthFocused);
    const std::vector<double> rest = cascade.defaults();
    for (std::size_t v = 0; v < skin.uvs.size(); ++v)
        skin.positions[v] = cascade.evaluate(skin.uvs[v][0], skin.uvs[v][1], rest);
    const std::vector<HeadPart> parts = makeHeadParts(cascade);
    const auto ball = std::find_if(parts.begin(), parts.end(), [&](const HeadPart& p) {
        return p.name == (side == 0 ? "eye_right" : "eye_left");
    });
    if (ball == parts.end()) throwInputError("eye opening", "the face has no eyeball part");

    // Rays along -forward through points of the eye's vertical line; the longest run of rays that
    // meet the eyeball first.
    const int steps = 400;
    const double span = 1.2 * eye.width, step = span / steps;
    int run = 0, longest = 0;
    for (int k = 0; k <= steps; ++k) {
        const Vec3 origin = centre + frame.up * (-0.5 * span + k * step) + frame.forward * (3.0 * eye.width);
        const Vec3 direction = -frame.forward;
        const auto skinHit = intersectRay(skin.positions, skin.triangles, origin, direction);
        const auto ballHit = intersectRay(ball->rest.positions, ball->rest.triangles, origin, direction);
        const bool eyeball = ballHit && (!skinHit || ballHit->distance < skinHit->distance);
        run = eyeball ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    eye.height = longest * step;
    return eye;
}

// Both eyes open by at least `fraction` of their width; returns the smaller ratio.
double expectOpenEyes(const DeformationCascade& cascade, double fraction, const std::string& what) {
    double smallest = 1e9;
    for (int side = 0; side < 2; ++side) {
        const EyeOpening eye = measureEye(cascade, side);
        const double ratio = eye.height / eye.width;
        std::printf("%s, %s eye: open %.2f of its width (%.3g of %.3g face units)\n", what.c_str(),
                    side == 0 ? "right" : "left", ratio, eye.height, eye.width);
        EXPECT_GT(ratio, fraction) << what << (side == 0 ? " right" : " left") << " eye";
        smallest = std::min(smallest, ratio);
    }
    return smallest;
}

// A real palpebral fissure is about a third of the eye's width (Farkas: about 10 mm high, 30 mm wide);
// a slit shows next to none of the eyeball.
constexpr double kOpen = 0.2;

TEST(EyeOpening, BundledFaceEyesAreOpen) {
    expectOpenEyes(makeBundledFace(), kOpen, "bundled face");
}

TEST(EyeOpening, FaceBuiltFromTheBundledSampleHasOpenEyes) {
    const std::filesystem::path sample =
        std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "neutral.obj";
    const UvMesh mesh = loadUvMesh(sample);
    const BuiltFace built = buildFace(mesh, canonicalLandmarks(mesh));
    expectOpenEyes(built.cascade, kOpen, "sample neutral");
}

// The sample with its eyes shut: every skin vertex of the eye openings (and a little around them)
// brought in front of the eyeball by a lid's thickness, as a mesh with closed eyes has them.
TEST(EyeOpening, FaceBuiltFromASampleWithClosedEyesHasOpenEyes) {
    UvMesh mesh = loadUvMesh(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "neutral.obj");
    std::vector<bool> lid(mesh.positions.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Vec2 uv = mesh.texCoords[mesh.texTriangles[t][k]];
            if (uv[0] < 0.0 || uv[0] > 1.0 || uv[1] < 0.0 || uv[1] > 1.0) continue; // a part's tile
            if (detail::eyeLens(uv[0], uv[1]).inside() > -0.3) lid[mesh.triangles[t][k]] = true;
        }
    std::size_t closed = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!lid[v]) continue;
        const Vec3 ball = eyeballCentre(Individual::Bundled, mesh.positions[v][0] >= 0.0 ? 1.0 : -1.0);
        const double dx = mesh.positions[v][0] - ball[0], dy = mesh.positions[v][1] - ball[1];
        const double front =
            ball[2] + std::sqrt(std::max(0.0, kEyeballRadius * kEyeballRadius - dx * dx - dy * dy));
        mesh.positions[v][2] = std::max(mesh.positions[v][2], front + 0.12);
        ++closed;
    }
    ASSERT_GT(closed, 20u);
    const BuiltFace built = buildFace(mesh, canonicalLandmarks(mesh));
    expectOpenEyes(built.cascade, kOpen, "sample with closed eyes");
}

TEST(EyeOpening, FaceBuiltFromMediaPipeHasOpenEyes) {
    SKIP_WITHOUT(kMediaPipe);
    const UvMesh mesh = loadUvMesh(kMediaPipe);
    const BuiltFace built = buildFace(mesh, suggestLandmarks(mesh).landmarks);
    expectOpenEyes(built.cascade, kOpen, "MediaPipe canonical face");
}

} // namespace
} // namespace vl::face
