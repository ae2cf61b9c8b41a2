#include "core/face/HeadParts.h"
#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/face/PartClearance.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// The sampler's linear form (what the editor's morph shader draws) is evaluate() for any q: the
// rest positions plus q_k times each parameter's displacement. jaw_open moves the lower teeth down
// and leaves the upper teeth (the skull) where they are.
TEST(HeadParts, LinearFormReproducesTheEvaluationAndJawOpenMovesOnlyTheJawsParts) {
    const auto cascade = makeBundledFace();
    const auto parts = makeHeadParts(cascade);
    const HeadPartsSampler sampler(cascade, parts);
    ASSERT_EQ(sampler.rest().size(), sampler.vertexCount());
    const auto visemes = oculusVisemes();
    for (const auto& viseme : visemes) {
        const std::vector<double> q = parameterVector(cascade, viseme);
        std::vector<Vec3> linear = sampler.rest();
        for (std::size_t k = 0; k < q.size(); ++k) {
            const std::vector<Vec3> d = sampler.displacement(k);
            ASSERT_EQ(d.size(), linear.size());
            for (std::size_t i = 0; i < d.size(); ++i) linear[i] += d[i] * q[k];
        }
        const std::vector<Vec3> evaluated = sampler.evaluate(q);
        for (std::size_t i = 0; i < linear.size(); ++i)
            ASSERT_LT((linear[i] - evaluated[i]).norm(), 1e-9) << viseme.name << " vertex " << i;
    }
    const int jaw = cascade.findParameter("jaw_open");
    ASSERT_GE(jaw, 0);
    const std::vector<Vec3> d = sampler.displacement(static_cast<std::size_t>(jaw));
    std::size_t first = 0;
    for (const auto& part : parts) {
        double meanY = 0.0, largest = 0.0;
        for (std::size_t i = first; i < first + part.rest.positions.size(); ++i) {
            meanY += d[i][1];
            largest = std::max(largest, d[i].norm());
        }
        meanY /= static_cast<double>(part.rest.positions.size());
        if (part.name == "teeth_lower" || part.name == "tongue") {
            EXPECT_LT(meanY, -0.1) << part.name;
        }
        if (part.name == "teeth_upper" || part.name.starts_with("eye_")) {
            EXPECT_EQ(largest, 0.0) << part.name;
        }
        first += part.rest.positions.size();
    }
    EXPECT_THROW((void)sampler.displacement(cascade.parameters.size()), InputError);
}

} // namespace
} // namespace vl::face
