#include "core/face/BundledFace.h"
#include "core/common/Error.h"
#include "core/deform/CascadeSampler.h"
#include "core/face/FaceDomain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace vl {
namespace {

double signedArea(const MeshData& m, const Triangle& t) {
    const Vec2 a = m.uvs[t[0]], b = m.uvs[t[1]], c = m.uvs[t[2]];
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

// Boundary edges (used by one triangle) as directed edges, following each triangle's orientation.
std::vector<std::pair<std::uint32_t, std::uint32_t>> boundaryEdges(const MeshData& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k)
            if (count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}] == 1)
                edges.emplace_back(t[k], t[(k + 1) % 3]);
    return edges;
}

bool onSquareBorder(const Vec2& uv) {
    return uv[0] == 0.0 || uv[0] == 1.0 || uv[1] == 0.0 || uv[1] == 1.0;
}

class FaceDomainTest : public ::testing::TestWithParam<std::pair<int, face::DomainDensity>> {};

TEST_P(FaceDomainTest, IsAValidTriangulationOfTheSquareWithTheMouthHole) {
    const auto [resolution, density] = GetParam();
    const MeshData m = face::faceDomainMesh(resolution, density);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    EXPECT_NO_THROW(toTriMesh(m, "domain")); // manifold, valid indices
    double total = 0.0;
    for (const auto& t : m.triangles) {
        const double a = signedArea(m, t);
        EXPECT_GT(a, 0.0); // counter-clockwise in (u,v), none flipped by the mouth opening
        total += a;
    }
    // The flat hexagon: a rectangle over the flat part, a triangle at each corner.
    const double hole = 2.0 * face::kMouthHalfWidth * face::kMouthHalfHeight * (1.0 + face::kMouthFlat);
    EXPECT_NEAR(total, 1.0 - hole, 1e-9);
    for (const auto& uv : m.uvs) {
        EXPECT_TRUE(uv[0] >= 0.0 && uv[0] <= 1.0 && uv[1] >= 0.0 && uv[1] <= 1.0);
        EXPECT_FALSE(face::insideMouthHole(uv[0], uv[1]))
            << uv[0] << " " << uv[1] << " h=" << face::mouthHoleHalfHeight(uv[0]);
    }
    // Every boundary edge is on the square or on the hexagon; the hexagon's rim is a closed loop.
    int rim = 0;
    for (const auto& [a, b] : boundaryEdges(m)) {
        const Vec2 pa = m.uvs[a], pb = m.uvs[b];
        if (onSquareBorder(pa) && onSquareBorder(pb)) continue;
        ++rim;
        for (const Vec2& p : {pa, pb, (pa + pb) * 0.5})
            EXPECT_NEAR(std::abs(p[1] - face::kMouthV), face::mouthHoleHalfHeight(p[0]), 1e-12);
    }
    EXPECT_GE(rim, 4);
}

INSTANTIATE_TEST_SUITE_P(Resolutions, FaceDomainTest,
                         ::testing::Values(std::pair{10, face::DomainDensity::Uniform},
                                           std::pair{23, face::DomainDensity::Uniform},
                                           std::pair{38, face::DomainDensity::MouthFocused},
                                           std::pair{80, face::DomainDensity::MouthFocused}));

TEST(FaceDomain, BaseDomainHasSimilarSizedTriangles) {
    const MeshData m = face::faceBaseDomain(10);
    double lo = 1e9, hi = 0.0;
    for (const auto& t : m.triangles) {
        lo = std::min(lo, signedArea(m, t));
        hi = std::max(hi, signedArea(m, t));
    }
    // 10 x 10 cells, and a narrow column each side where the lips' flat rims bend to the corners.
    EXPECT_EQ(m.triangles.size(), 240u);
    EXPECT_LT(hi / lo, 5.0);
    EXPECT_THROW(face::faceDomainMesh(5), InputError);
}

TEST(BundledFace, CascadeIsValidWithTheDocumentedParameters) {
    const auto c = face::makeBundledFace();
    EXPECT_NO_THROW(validateCascade(c));
    for (const char* name :
         {"frontalis_l", "frontalis_r", "zygomatic_l", "zygomatic_r", "risorius_l", "risorius_r", "jaw_open",
          "lip_pucker", "lip_press", "upper_lip_raise", "lower_lip_tuck"})
        EXPECT_GE(c.findParameter(name), 0) << name;
}

TEST(BundledFace, LooksLikeAFaceInProfile) {
    const auto c = face::makeBundledFace();
    const auto q = c.defaults();
    const auto at = [&](double u, double v) { return c.evaluate(u, v, q); };
    const Vec3 noseTip = at(0.5, 0.415), eye = at(0.365, 0.585), cheek = at(0.3, 0.44), chin = at(0.5, 0.16);
    const Vec3 forehead = at(0.5, 0.8), upperLip = at(0.5, 0.333);
    EXPECT_GT(noseTip[2], eye[2] + 1.5);   // the nose stands out of the eye sockets
    EXPECT_GT(noseTip[2], upperLip[2]);    // and out of the lips
    EXPECT_GT(upperLip[2], chin[2] - 0.5); // lips are not behind the chin
    EXPECT_GT(noseTip[2], cheek[2]);
    EXPECT_GT(forehead[1], noseTip[1]); // up is +y
    EXPECT_GT(noseTip[1], chin[1]);
    EXPECT_LT(at(0.365, 0.585)[0], 0.0); // the face's right eye is on the viewer's left (-x)
    // Mirror symmetry of the bundled face.
    for (const double v : {0.2, 0.45, 0.6, 0.8}) {
        const Vec3 l = at(0.3, v), r = at(0.7, v);
        EXPECT_NEAR(l[0], -r[0], 1e-9);
        EXPECT_NEAR(l[1], r[1], 1e-9);
        EXPECT_NEAR(l[2], r[2], 1e-9);
    }
}

TEST(BundledFace, LipsAlmostCloseOverTheMouthHoleAndTheJawOpensThem) {
    const auto c = face::makeBundledFace();
    auto q = c.defaults();
    const double u = face::kMouthU;
    const auto gap = [&](double du) {
        const double hh = face::mouthHoleHalfHeight(u + du);
        return c.evaluate(u + du, face::kMouthV + hh, q)[1] - c.evaluate(u + du, face::kMouthV - hh, q)[1];
    };
    EXPECT_GT(gap(0.0), 0.0);  // not crossing
    EXPECT_LT(gap(0.0), 0.15); // centimetres: a closed mouth
    EXPECT_GT(gap(0.05), 0.0);
    q[static_cast<std::size_t>(c.findParameter("jaw_open"))] = 1.0;
    EXPECT_GT(gap(0.0), 1.5); // wide open
    // A rounded U, not a V: nearly as open half-way to the corners as in the middle, then closing.
    EXPECT_GE(gap(0.0), gap(0.05) - 1e-9);
    EXPECT_GT(gap(0.05), 0.8 * gap(0.0));
    EXPECT_GT(gap(0.05), gap(0.09));
}

TEST(RetargetFace, UsesTheSameFieldsOnAnotherBase) {
    const auto a = face::makeBundledFace();
    const auto b = face::makeRetargetFace();
    ASSERT_EQ(a.stages.size(), b.stages.size());
    ASSERT_EQ(a.parameters.size(), b.parameters.size());
    EXPECT_EQ(b.stages[0].kind, StageKind::Constant);
    EXPECT_NE(a.stages[0].field.sampled.samples, b.stages[0].field.sampled.samples);
    for (std::size_t s = 1; s < a.stages.size(); ++s) {
        EXPECT_EQ(a.stages[s].parameter, b.stages[s].parameter);
        ASSERT_EQ(a.stages[s].field.influences.size(), b.stages[s].field.influences.size());
        for (std::size_t r = 0; r < a.stages[s].field.influences.size(); ++r) {
            const auto &x = a.stages[s].field.influences[r], &y = b.stages[s].field.influences[r];
            EXPECT_EQ(x.centre, y.centre);
            EXPECT_EQ(x.radii, y.radii);
            EXPECT_EQ(x.direction, y.direction);
            EXPECT_EQ(x.magnitude, y.magnitude);
        }
    }
    // Another individual: a wider face, and the same displacement for the same parameters.
    const auto q0 = a.defaults();
    EXPECT_GT(b.evaluate(0.9, 0.5, q0)[0], a.evaluate(0.9, 0.5, q0)[0] + 0.3);
    auto q = q0;
    q[static_cast<std::size_t>(a.findParameter("lip_pucker"))] = 0.8;
    const Vec3 da = a.evaluate(0.5, 0.34, q) - a.evaluate(0.5, 0.34, q0);
    const Vec3 db = b.evaluate(0.5, 0.34, q) - b.evaluate(0.5, 0.34, q0);
    EXPECT_NEAR((da - db).norm(), 0.0, 1e-12);
    EXPECT_GT(da.norm(), 0.3);
}

TEST(FaceColours, TintLipsAndEyes) {
    const std::vector<Vec2> uvs{Vec2(0.5, 0.9), Vec2(0.5, 0.268), Vec2(0.365, 0.585)};
    const auto c = face::faceColours(uvs);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_GT(c[0][1], c[1][1] + 0.1);   // lips are redder (less green) than the forehead
    EXPECT_LT(c[2].norm(), c[0].norm()); // the iris is darker than skin
}

} // namespace
} // namespace vl
