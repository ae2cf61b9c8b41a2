#include "core/face/HeadParts.h"
#include "core/deform/BundledFace.h"
#include "core/deform/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/face/PartClearance.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace vl::face {
namespace {

// The bundled head's teeth and tongue stay behind the lips (and the skin around the mouth) in every
// Oculus viseme: the signed distance of every tooth and tongue vertex to the nearest skin of the
// mouth region is positive (inside the head) or the vertex is seen through the opening, and no edge of
// them passes through the skin.
TEST(HeadParts, TeethNeverPenetrateTheLipsInAnyBundledViseme) {
    const auto cascade = makeBundledFace();
    const auto parts = makeHeadParts(cascade);
    for (const int resolution : {38, 90}) {
        const MeshData domain = faceDomainMesh(resolution, DomainDensity::MouthFocused);
        const auto visemes = oculusVisemes();
        const VisemeSet set = generateHeadVisemeSet(cascade, domain, visemes, parts);
        for (std::size_t k = 0; k <= set.size(); ++k) {
            const MeshData mesh = k == 0 ? set.neutral : set.meshOf(k - 1);
            const std::string name = k == 0 ? "neutral" : set.visemes[k - 1].name;
            for (const auto& c : partClearances(mesh, domain.positions.size(), parts, Vec3(0, 0, 1),
                                                Vec2(0.3, 0.12), Vec2(0.7, 0.45))) {
                if (c.part != "teeth_upper" && c.part != "teeth_lower" && c.part != "tongue") continue;
                if (std::getenv("VL_DEBUG"))
                    std::printf("%d %-8s %-12s %8.3f (vertex %zu)\n", resolution, name.c_str(),
                                c.part.c_str(), c.clearance, c.vertex);
                EXPECT_EQ(c.crossings, 0u) << name << " " << c.part << " at resolution " << resolution;
                EXPECT_GT(c.clearance, 0.05)
                    << name << " " << c.part << " vertex " << c.vertex << " at resolution " << resolution;
            }
        }
    }
}

} // namespace
} // namespace vl::face
