// The head's parts carried to faces nobody here made (from VISEMELAB_SHARED_DATA_DIR, skipped loudly
// when absent): built as `visemelab face build` builds them (landmarks suggested, then buildFace), the
// teeth and tongue never pass through the skin and stay behind the lips and the skin around the mouth
// in the neutral face and every bundled Oculus viseme.
#include "core/face/FaceBuild.h"
#include "core/face/FaceDomain.h"
#include "core/face/HeadParts.h"
#include "core/face/LandmarkFinder.h"
#include "core/face/PartClearance.h"

#include "tests/face/SharedFaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace vl::face {
namespace {

using namespace test; // the shared faces

// Clearances in bundled-face centimetres (the face's units divided by its scale). VL_DEBUG=1 prints
// every viseme's and the smallest (docs/deformable-face.md quotes them).
void expectPartsBehindTheLips(const std::filesystem::path& path) {
    const UvMesh mesh = loadUvMesh(path);
    const BuiltFace built = buildFace(mesh, suggestLandmarks(mesh).landmarks);
    const auto parts = makeHeadParts(built.cascade);
    const MeshData domain = faceDomainMesh(38, DomainDensity::MouthFocused);
    const VisemeSet set = generateHeadVisemeSet(built.cascade, domain, oculusVisemes(), parts);
    const double scale = built.report.scale;
    double smallest = std::numeric_limits<double>::max(), closest = smallest;
    for (std::size_t k = 0; k <= set.size(); ++k) {
        const MeshData head = k == 0 ? set.neutral : set.meshOf(k - 1);
        const std::string name = k == 0 ? "neutral" : set.visemes[k - 1].name;
        for (const auto& c : partClearances(head, domain.positions.size(), parts, built.report.frame.forward,
                                            Vec2(0, 0), Vec2(1, 1))) {
            if (c.part != "teeth_upper" && c.part != "teeth_lower" && c.part != "tongue") continue;
            const std::string what = path.filename().string() + " " + name + " " + c.part;
            EXPECT_EQ(c.crossings, 0u) << what << ": edges through the skin";
            if (c.checked) {
                EXPECT_GT(c.clearance / scale, 0.05) << what << " vertex " << c.vertex;
                smallest = std::min(smallest, c.clearance / scale);
            }
            closest = std::min(closest, c.closest / scale);
            if (std::getenv("VL_DEBUG"))
                std::printf("%-8s %-12s clearance %6.3f cm (vertex %zu), closest %6.3f cm, %zu through the "
                            "mouth, %zu beyond the border\n",
                            name.c_str(), c.part.c_str(), c.clearance / scale, c.vertex, c.closest / scale,
                            c.throughMouth, c.beyondBorder);
        }
    }
    if (std::getenv("VL_DEBUG"))
        std::printf("%s: smallest clearance %.3f cm, closest approach %.3f cm\n", path.filename().c_str(),
                    smallest, closest);
}

TEST(OwnFaceClearance, MediaPipeFaceTeethAndTongueStayBehindTheLips) {
    SKIP_WITHOUT(kMediaPipe);
    expectPartsBehindTheLips(kMediaPipe);
}

TEST(OwnFaceClearance, IctHeadTeethAndTongueStayBehindTheLips) {
    SKIP_WITHOUT(kIct);
    expectPartsBehindTheLips(kIct);
}

} // namespace
} // namespace vl::face
