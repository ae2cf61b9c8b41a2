// Mouth measures of viseme meshes (core/face/MouthMeasures.h): the landmarks are the cascade's points,
// the front view counts exactly the part of the teeth the mouth's opening shows, and the bundled
// visemes have the mouth shapes their references give (docs/viseme-review.md).
#include "core/face/MouthMeasures.h"
#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/HeadParts.h"
#include "core/face/Landmarks.h"
#include "core/io/MeshIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace vl::face {
namespace {

class MouthMeasuresOfTheBundledHead : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        cascade_ = makeBundledFace();
        domain_ = faceDomainMesh(38, DomainDensity::MouthFocused);
        const auto parts = makeHeadParts(cascade_);
        set_ = generateHeadVisemeSet(cascade_, domain_, oculusVisemes(), parts);
        neutral_ = measureMouth(set_.neutral);
        EXPECT_TRUE(neutral_.teethGap && neutral_.tongueAhead && neutral_.lowerLipToUpperTeeth);
        for (std::size_t k = 0; k < set_.size(); ++k)
            measures_[set_.visemes[k].name] = measureMouth(set_.meshOf(k));
    }
    static const MouthMeasures& of(const std::string& name) { return measures_.at(name); }

    static inline DeformationCascade cascade_;
    static inline MeshData domain_;
    static inline VisemeSet set_;
    static inline MouthMeasures neutral_;
    static inline std::map<std::string, MouthMeasures> measures_;
};

TEST_F(MouthMeasuresOfTheBundledHead, LandmarksAreTheCascadeAtTheirUV) {
    for (const auto& v : oculusVisemes()) {
        const auto q = parameterVector(cascade_, v);
        const auto at = [&](Landmark l) {
            const Vec2 uv = canonicalPosition(l);
            return cascade_.evaluate(uv[0], uv[1], q);
        };
        const MouthMeasures& m = of(v.name);
        EXPECT_LT((m.upperLip - at(Landmark::UpperLipMid)).norm(), 1e-9) << v.name;
        EXPECT_LT((m.lowerLip - at(Landmark::LowerLipMid)).norm(), 1e-9) << v.name;
        EXPECT_LT((m.cornerLeft - at(Landmark::MouthCornerLeft)).norm(), 1e-9) << v.name;
        EXPECT_LT((m.cornerRight - at(Landmark::MouthCornerRight)).norm(), 1e-9) << v.name;
        EXPECT_NEAR(m.opening, m.upperLip[1] - m.lowerLip[1], 1e-12) << v.name;
        EXPECT_GE(m.upperLipFront, m.upperLip[2]) << v.name;
        EXPECT_GE(m.lowerLipFront, m.lowerLip[2]) << v.name;
    }
}

TEST_F(MouthMeasuresOfTheBundledHead, RestAndBilabialMouthsAreClosed) {
    // The rest face's lips almost touch (a slit of 0.06 cm); PP's are pressed shut and rolled back.
    // Neither shows the lower teeth or the tongue; through the rest face's slit a sliver of the upper
    // teeth is seen (docs/viseme-review.md), less through PP's corners.
    EXPECT_GT(of("sil").opening, 0.0);
    EXPECT_LT(of("sil").opening, 0.1);
    EXPECT_LT(of("sil").upperTeethSeen, 0.2);
    EXPECT_LT(std::abs(of("PP").opening), 0.02);
    EXPECT_LT(of("PP").upperTeethSeen, 0.05);
    EXPECT_LT(of("PP").upperLipFront, of("sil").upperLipFront - 0.2);
    for (const auto* name : {"sil", "PP"}) {
        EXPECT_EQ(of(name).lowerTeethSeen, 0.0) << name;
        EXPECT_EQ(of(name).tongueSeen, 0.0) << name;
        EXPECT_LT(*of(name).teethGap, 0.0) << name; // the upper incisors overlap the lower ones
    }
}

TEST_F(MouthMeasuresOfTheBundledHead, OpenMouthsShowTeethAndRoundedOnesNarrow) {
    // aa: the widest opening of all and the teeth furthest apart; lower teeth and tongue in view.
    for (const auto& [name, m] : measures_) {
        if (name == "aa") continue;
        EXPECT_LT(m.opening, of("aa").opening) << name;
        EXPECT_LT(*m.teethGap, *of("aa").teethGap) << name;
    }
    EXPECT_GT(of("aa").opening, 1.0);
    EXPECT_GT(of("aa").lowerTeethSeen, 0.1);
    EXPECT_GT(of("aa").tongueSeen, 0.5);
    // SS: the teeth nearly together, the upper ones shown between spread lips.
    EXPECT_LT(std::abs(*of("SS").teethGap), 0.1);
    EXPECT_GT(of("SS").upperTeethSeen, 0.5);
    // TH: the tongue's tip out to the incisors' front; every other tongue stays behind the teeth.
    for (const auto& [name, m] : measures_) {
        if (name == "TH")
            EXPECT_GT(*m.tongueAhead, -0.1);
        else
            EXPECT_LT(*m.tongueAhead, -0.4) << name;
    }
    // Rounded visemes are narrower than the rest face, spread ones wider.
    for (const auto* name : {"ou", "oh", "CH", "RR"}) EXPECT_LT(of(name).width, neutral_.width - 0.2) << name;
    for (const auto* name : {"SS", "E", "ih"}) EXPECT_GT(of(name).width, neutral_.width + 0.2) << name;
    // ou pushes the lips forward the most.
    for (const auto& [name, m] : measures_) {
        if (name != "ou") {
            EXPECT_LE(m.upperLipFront, of("ou").upperLipFront) << name;
        }
    }
    // FF: the lower lip drawn back to the upper incisors, nearer them than in any other viseme.
    EXPECT_LT(of("FF").lowerLipFront, neutral_.lowerLipFront - 0.3);
    for (const auto& [name, m] : measures_) {
        if (name != "FF") {
            EXPECT_LT(*of("FF").lowerLipToUpperTeeth, *m.lowerLipToUpperTeeth) << name;
        }
    }
}

// The open mouths' outline is rounded (issue 15: "no polygonal hole"): seen from the front, the
// opening's height falls off from the middle towards the corners like an ellipse's (about 0.87 of the
// middle's half-way out, 0.66 three quarters out), steadily (monotone and concave up to the corner,
// where it is 0); not a trapezoid that keeps the middle's height most of the way and drops at the
// corners.
void expectRoundedOutline(const MouthMeasures& m, const std::string& name) {
    const auto& p = m.openingProfile;
    ASSERT_GT(p[0], 0.3) << name << ": not open";
    for (std::size_t k = 1; k < p.size(); ++k) EXPECT_LE(p[k], p[k - 1] + 0.01) << name << " at " << k;
    EXPECT_GE(p[2] / p[0], 0.6) << name << ": half-way out";
    EXPECT_LE(p[2] / p[0], 0.92) << name << ": half-way out";
    EXPECT_GE(p[3] / p[0], 0.35) << name << ": three quarters out";
    EXPECT_LE(p[3] / p[0], 0.8) << name << ": three quarters out";
    // Concave: each step towards the corner drops at least as much as the one before (0 at the corner).
    const double at[] = {p[0], p[1], p[2], p[3], 0.0};
    for (std::size_t k = 1; k + 1 < 5; ++k)
        EXPECT_LE(at[k - 1] - 2.0 * at[k] + at[k + 1], 0.02 * p[0]) << name << ": kinked at " << k;
}

TEST_F(MouthMeasuresOfTheBundledHead, OpenMouthsAreRoundedNotTrapezoids) {
    // The visemes that open the jaw furthest (before the modioli held the corners, aa's opening kept
    // its middle's height half-way out and 0.90 of it three quarters out; oh's 0.96 and 0.82).
    for (const auto* name : {"aa", "oh", "E", "kk"}) expectRoundedOutline(of(name), name);
}

// The opening profile measures the outline seen from the front: a flat face domain whose lower lip
// drops by an ellipse's profile (2 units in the middle) has the hole's own height (its flat rims,
// sloping to the corners) plus that drop at every fraction of the way to the corners.
TEST(MouthMeasures, OpeningProfileIsTheOutlineBetweenTheRims) {
    MeshData head = faceDomainMesh(40, DomainDensity::MouthFocused);
    const auto drop = [](double u) {
        const double t = (u - kMouthU) / kMouthHalfWidth;
        return std::abs(t) < 1.0 ? 2.0 * std::sqrt(1.0 - t * t) : 0.0;
    };
    for (std::size_t i = 0; i < head.positions.size(); ++i) {
        const Vec2& uv = head.uvs[i];
        head.positions[i] = Vec3(10.0 * uv[0], 10.0 * uv[1] - (uv[1] < kMouthV ? drop(uv[0]) : 0.0), 0.0);
    }
    const MouthMeasures m = measureMouth(head);
    for (std::size_t k = 0; k < kOpeningProfileAt.size(); ++k) {
        const double u = kMouthU + kOpeningProfileAt[k] * kMouthHalfWidth;
        EXPECT_NEAR(m.openingProfile[k], 20.0 * mouthHoleHalfHeight(u) + drop(u), 0.03) << k;
    }
    EXPECT_NEAR(m.openingProfile[0], m.opening, 1e-9);
    expectRoundedOutline(m, "an elliptic drop");
}

// docs/viseme-review.md's table of measures is `visemelab face mouth` on the bundled sample
// (assets/sample, scripts/viseme-review.sh): every number within the rounding of its two decimals.
TEST(MouthMeasures, TheReviewTableIsTheSampleMeasured) {
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    std::ifstream in(assets.parent_path() / "docs" / "viseme-review.md");
    ASSERT_TRUE(in) << "docs/viseme-review.md not found";
    const MouthMeasures neutral = measureMouth(readMesh(assets / "sample" / "neutral.obj"));
    bool inSection = false;
    std::size_t rows = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) inSection = line == "## Measures";
        if (!inSection || line.rfind("| ", 0) != 0 || line.rfind("| mesh", 0) == 0 ||
            line.rfind("| ---", 0) == 0)
            continue;
        std::vector<std::string> cells;
        std::stringstream row(line.substr(2));
        for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
        ASSERT_GE(cells.size(), 15u) << line;
        const auto name = cells[0].substr(0, cells[0].find(' '));
        const MouthMeasures m =
            name == "(neutral)" ? neutral : measureMouth(readMesh(assets / "sample" / (name + ".obj")));
        const double expected[] = {m.opening,
                                   m.opening - neutral.opening,
                                   m.openingProfile[2],
                                   m.openingProfile[3],
                                   m.width,
                                   m.width / neutral.width,
                                   m.upperLipFront - neutral.upperLipFront,
                                   m.lowerLipFront - neutral.lowerLipFront,
                                   m.teethGap.value_or(-1.0),
                                   m.upperTeethSeen,
                                   m.lowerTeethSeen,
                                   m.tongueSeen,
                                   m.tongueAhead.value_or(-1.0),
                                   m.lowerLipToUpperTeeth.value_or(-1.0)};
        for (std::size_t k = 0; k < std::size(expected); ++k)
            EXPECT_NEAR(std::stod(cells[k + 1]), expected[k], 0.0051) << name << " column " << k + 2;
        ++rows;
    }
    EXPECT_EQ(rows, 16u); // the neutral and the 15 visemes
}

TEST(MouthMeasures, SkinWithoutPartsHasNoTeethToMeasure) {
    const auto cascade = makeBundledFace();
    const MeshData domain = faceDomainMesh(20, DomainDensity::MouthFocused);
    const VisemeSet set = generateVisemeSet(cascade, domain, oculusVisemes());
    const MouthMeasures m = measureMouth(set.meshOf(10)); // aa
    EXPECT_GT(m.opening, 1.0);
    EXPECT_FALSE(m.lowerLipToUpperTeeth.has_value());
    EXPECT_FALSE(m.teethGap.has_value());
    EXPECT_FALSE(m.tongueAhead.has_value());
    EXPECT_EQ(m.upperTeethSeen + m.lowerTeethSeen + m.tongueSeen, 0.0);
}

// A flat face domain (10 units across) with two rows of "teeth" behind it: flat plates covering the
// mouth's opening, the upper one above the mouth line, the lower one below. The front view sees each
// plate exactly where the opening is: the opening's area is the square's minus the skin's.
TEST(MouthMeasures, FrontViewSeesThePartsThroughTheOpening) {
    MeshData head = faceDomainMesh(30, DomainDensity::MouthFocused);
    double skinArea = 0.0;
    for (auto& p : head.positions) p = Vec3(10.0 * p[0], 10.0 * p[1], 0.0);
    for (const auto& t : head.triangles) {
        const Vec3 e1 = head.positions[t[1]] - head.positions[t[0]],
                   e2 = head.positions[t[2]] - head.positions[t[0]];
        skinArea += 0.5 * std::abs(e1[0] * e2[1] - e1[1] * e2[0]);
    }
    const double opening = 100.0 - skinArea;
    ASSERT_GT(opening, 0.3);
    const auto plate = [&](double y0, double y1, double tileV) {
        const auto first = static_cast<std::uint32_t>(head.positions.size());
        for (const double y : {y0, y1})
            for (const double x : {3.0, 7.0}) {
                head.positions.push_back(Vec3(x, y, -1.0));
                head.uvs.push_back(Vec2(double(HeadTile::Teeth) + 0.5, tileV));
            }
        head.triangles.push_back({first, first + 1, first + 3});
        head.triangles.push_back({first, first + 3, first + 2});
    };
    const double line = 10.0 * kMouthV;
    plate(line, line + 1.0, 0.5);
    plate(line - 1.0, line, 0.5);
    const MouthMeasures m = measureMouth(head);
    EXPECT_NEAR(m.width, 10.0 * 2 * kMouthHalfWidth, 1e-9);
    EXPECT_NEAR(m.upperTeethSeen + m.lowerTeethSeen, opening, 0.03 * opening);
    EXPECT_NEAR(m.upperTeethSeen, m.lowerTeethSeen, 0.03 * opening); // the opening is symmetric
    EXPECT_EQ(m.tongueSeen, 0.0);
    // A tongue plate in front of the skin hides it and is seen whole (1 x 1 units), the teeth behind it
    // only beside it.
    const auto first = static_cast<std::uint32_t>(head.positions.size());
    for (const double y : {line - 0.5, line + 0.5})
        for (const double x : {4.5, 5.5}) {
            head.positions.push_back(Vec3(x, y, 1.0));
            head.uvs.push_back(Vec2(double(HeadTile::Tongue) + 0.5, 0.5));
        }
    head.triangles.push_back({first, first + 1, first + 3});
    head.triangles.push_back({first, first + 3, first + 2});
    const MouthMeasures front = measureMouth(head);
    EXPECT_NEAR(front.tongueSeen, 1.0, 0.01);
    EXPECT_LT(front.upperTeethSeen + front.lowerTeethSeen, 0.5 * opening);
}

TEST(MouthMeasures, RejectsMeshesThatAreNotAFaceDomain) {
    MeshData mesh = faceDomainMesh(12);
    MeshData noUv = mesh;
    noUv.uvs.clear();
    EXPECT_THROW(measureMouth(noUv, "x.obj"), InputError);
    for (auto& uv : mesh.uvs) uv += Vec2(0.5, 0.0); // the mouth's right corner is on no vertex
    try {
        measureMouth(mesh, "half.obj");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("half.obj"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("mouth_corner_right"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace vl::face
