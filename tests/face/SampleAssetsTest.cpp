// The committed sample (assets/sample) must be what scripts/generate-sample.sh makes from the current
// face model: a change to the fields or visemes without regenerating the sample fails here.
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/HeadParts.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

const std::filesystem::path kSample = std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample";

TEST(SampleAssets, MatchTheGeneratorAndAreInterpolable) {
    const auto files = listVisemeFolder(kSample, kSample / "neutral.obj");
    const VisemeSet loaded = loadVisemeSet(kSample / "neutral.obj", files);
    EXPECT_EQ(loaded.size(), 15u);
    EXPECT_GT(loaded.vertexCount(), 2300u);
    EXPECT_LT(loaded.vertexCount(), 2800u);

    // The generator's command line: --face bundled --resolution 38 --density mouth (--decimals 6),
    // the whole head (skin, then eyeballs, teeth, tongue and mouth cavity).
    const auto visemes = oculusVisemes();
    const auto cascade = face::makeBundledFace();
    const VisemeSet generated =
        face::generateHeadVisemeSet(cascade, face::faceDomainMesh(38, face::DomainDensity::MouthFocused),
                                    visemes, face::makeHeadParts(cascade));
    ASSERT_EQ(generated.vertexCount(), loaded.vertexCount());
    EXPECT_EQ(generated.neutral.triangles, loaded.neutral.triangles);
    const double tolerance = 1e-6; // the files are rounded to 6 decimals
    for (std::size_t i = 0; i < loaded.vertexCount(); ++i) {
        ASSERT_NEAR((generated.neutral.positions[i] - loaded.neutral.positions[i]).norm(), 0.0, tolerance)
            << i;
        ASSERT_NEAR((generated.neutral.uvs[i] - loaded.neutral.uvs[i]).norm(), 0.0, tolerance) << i;
    }
    for (std::size_t k = 0; k < generated.size(); ++k) {
        const int index = loaded.find(generated.visemes[k].name);
        ASSERT_GE(index, 0) << generated.visemes[k].name;
        const auto& positions = loaded.visemes[static_cast<std::size_t>(index)].positions;
        for (std::size_t i = 0; i < positions.size(); ++i)
            ASSERT_NEAR((generated.visemes[k].positions[i] - positions[i]).norm(), 0.0, tolerance)
                << generated.visemes[k].name << " vertex " << i << ": run scripts/generate-sample.sh";
    }
}

} // namespace
} // namespace vl
