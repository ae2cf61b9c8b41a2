#include "core/common/Error.h"
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "tests/deform/ErrorMessage.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vl {
namespace {

using test::errorOf;

TEST(Visemes, OculusSetHasFifteenNamedValidVectors) {
    const auto visemes = oculusVisemes();
    const std::vector<std::string> names{"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                         "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};
    ASSERT_EQ(visemes.size(), names.size());
    const auto face = face::makeBundledFace();
    for (std::size_t k = 0; k < names.size(); ++k) {
        EXPECT_EQ(visemes[k].name, names[k]);
        EXPECT_NO_THROW(checkParameterValues(face, parameterVector(face, visemes[k])));
    }
}

TEST(Visemes, ParameterVectorRejectsBadEntriesByName) {
    const auto face = face::makeBundledFace();
    EXPECT_EQ(errorOf([&] {
                  parameterVector(face, {"X", {{"jaw", 0.5}}});
              }),
              "viseme 'X': unknown parameter 'jaw'");
    EXPECT_EQ(errorOf([&] {
                  parameterVector(face, {"X", {{"jaw_open", 1.5}}});
              }),
              "viseme 'X': parameter 'jaw_open': value 1.5 is outside [0, 1]");
    EXPECT_NE(errorOf([&] {
                  parameterVector(face, {"X", {{"jaw_open", 0.5}, {"jaw_open", 0.2}}});
              }).find("twice"),
              std::string::npos);
    const auto q = parameterVector(face, {"X", {{"jaw_open", 0.5}}});
    EXPECT_EQ(q[static_cast<std::size_t>(face.findParameter("jaw_open"))], 0.5);
    EXPECT_EQ(q[static_cast<std::size_t>(face.findParameter("lip_press"))], 0.0);
}

class GeneratedSet : public ::testing::TestWithParam<face::Individual> {};

TEST_P(GeneratedSet, IsInterpolableAndEachVisemeMovesTheMouth) {
    const auto face = face::makeFaceCascade(GetParam());
    const MeshData uv = face::faceDomainMesh(30, face::DomainDensity::MouthFocused);
    const auto visemes = oculusVisemes();
    const VisemeSet set = generateVisemeSet(face, uv, visemes);
    ASSERT_EQ(set.size(), 15u);
    EXPECT_EQ(set.neutral.triangles, uv.triangles);
    EXPECT_EQ(set.neutral.uvs, uv.uvs);
    for (std::size_t k = 0; k < set.size(); ++k) {
        const MeshData m = set.meshOf(k);
        EXPECT_NO_THROW(checkInterpolable(set.neutral, "neutral", m, set.visemes[k].name));
        double nearMouth = 0.0, farAway = 0.0;
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const double d = (m.positions[i] - set.neutral.positions[i]).norm();
            const Vec2 p = uv.uvs[i];
            const double r = std::hypot((p[0] - face::kMouthU) / 0.15, (p[1] - face::kMouthV) / 0.08);
            if (r < 1.0) nearMouth = std::max(nearMouth, d);
            if (p[1] > 0.75 || p[0] < 0.05 || p[0] > 0.95) farAway = std::max(farAway, d);
        }
        if (set.visemes[k].name == "sil") {
            EXPECT_EQ(nearMouth, 0.0);
        } else {
            EXPECT_GT(nearMouth, 0.2) << set.visemes[k].name; // centimetres
        }
        EXPECT_LT(farAway, 0.3) << set.visemes[k].name;
    }
    // The set matches per-point evaluation of the cascade (the sampler is only a faster path).
    const auto q = parameterVector(face, visemes[10]);
    for (std::size_t i = 0; i < uv.uvs.size(); i += 37)
        EXPECT_NEAR((set.visemes[10].positions[i] - face.evaluate(uv.uvs[i][0], uv.uvs[i][1], q)).norm(), 0.0,
                    1e-12);
}

INSTANTIATE_TEST_SUITE_P(Individuals, GeneratedSet,
                         ::testing::Values(face::Individual::Bundled, face::Individual::Retarget));

TEST(GenerateVisemeSet, RejectsBadInput) {
    const auto face = face::makeBundledFace();
    const MeshData uv = face::faceBaseDomain(10);
    const auto visemes = oculusVisemes();
    MeshData noUV = uv;
    noUV.uvs.clear();
    EXPECT_NE(errorOf([&] { generateVisemeSet(face, noUV, visemes); }).find("(u,v)"), std::string::npos);
    EXPECT_NE(errorOf([&] { generateVisemeSet(face, uv, std::span(visemes).first(1)); }).find("at least 2"),
              std::string::npos);
    auto twice = visemes;
    twice[2].name = "PP";
    EXPECT_NE(errorOf([&] { generateVisemeSet(face, uv, twice); }).find("'PP' repeats"), std::string::npos);
}

} // namespace
} // namespace vl
