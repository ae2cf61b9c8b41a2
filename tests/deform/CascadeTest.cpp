#include "core/common/Error.h"
#include "core/deform/CascadeAtPose.h"
#include "core/deform/CascadeSampler.h"
#include "core/deform/DeformationCascade.h"
#include "core/face/BundledFace.h"
#include "tests/deform/ErrorMessage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace vl {
namespace {

using test::errorOf;

InfluenceField randomRegion(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
    InfluenceField r;
    r.centre = Vec2(unit(rng), unit(rng));
    r.radii = Vec2(0.05 + 0.4 * unit(rng), 0.05 + 0.4 * unit(rng));
    if (unit(rng) < 0.5) r.plateau = r.radii * (0.1 + 0.8 * unit(rng));
    r.rotation = 3 * sym(rng);
    r.direction = Vec3(sym(rng), sym(rng), sym(rng) + 0.1);
    r.magnitude = 2 * sym(rng);
    r.falloff = static_cast<Falloff>(static_cast<int>(unit(rng) * 4) % 4);
    return r;
}

// A random cascade: a sampled base (also a second Constant stage, which replaces the first), several
// parameters, some driving more than one stage, stages with sampled and analytic fields.
DeformationCascade randomCascade(std::mt19937& rng, int parameters) {
    std::uniform_real_distribution<double> d(-3.0, 3.0);
    DeformationCascade c;
    c.name = "random";
    for (int k = 0; k < parameters; ++k) c.parameters.push_back({"p" + std::to_string(k), -1.0, 2.0, 0.0});
    const auto grid = [&](int n) {
        return sampleGrid(n, n + 1, [&](double, double) { return Vec3(d(rng), d(rng), d(rng)); });
    };
    DeformationStage ignored;
    ignored.kind = StageKind::Constant;
    ignored.field.sampled = grid(3);
    c.stages.push_back(ignored);
    DeformationStage early; // before the last Constant stage: has no effect
    early.parameter = 0;
    early.field.sampled = grid(4);
    c.stages.push_back(early);
    DeformationStage base;
    base.kind = StageKind::Constant;
    base.field.sampled = grid(6);
    base.field.influences.push_back(randomRegion(rng));
    c.stages.push_back(base);
    for (int s = 0; s < 2 * parameters; ++s) {
        DeformationStage stage;
        stage.parameter = static_cast<std::size_t>(s % parameters);
        for (int r = 0; r < 1 + s % 3; ++r) stage.field.influences.push_back(randomRegion(rng));
        if (s % 5 == 0) stage.field.sampled = grid(5);
        c.stages.push_back(stage);
    }
    return c;
}

TEST(DeformationCascade, EvaluateFollowsTheEquations) {
    DeformationCascade c;
    c.name = "two";
    c.parameters = {{"a", 0, 1, 0}, {"b", -1, 1, 0.5}};
    DeformationStage base{StageKind::Constant, "base", 0, {}};
    base.field.sampled = sampleGrid(2, 2, [](double u, double v) { return Vec3(u, v, 0); });
    DeformationStage sa{StageKind::AddVector, "a", 0, {}};
    sa.field.sampled = sampleGrid(1, 1, [](double, double) { return Vec3(0, 0, 1); });
    DeformationStage sb{StageKind::AddVector, "b", 1, {}};
    sb.field.sampled = sampleGrid(1, 1, [](double, double) { return Vec3(2, 0, 0); });
    c.stages = {base, sa, sb};
    validateCascade(c);
    const std::vector<double> q{0.25, -0.5};
    const Vec3 p = c.evaluate(0.3, 0.7, q);
    EXPECT_NEAR((p - Vec3(0.3 - 1.0, 0.7, 0.25)).norm(), 0.0, 1e-15);
    EXPECT_EQ(c.defaults(), (std::vector<double>{0.0, 0.5}));
    EXPECT_EQ(c.findParameter("b"), 1);
    EXPECT_EQ(c.findParameter("c"), -1);
}

TEST(CascadeSampler, AgreesWithPerPointEvaluationOnRandomCascades) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0), q01(-1.0, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        const DeformationCascade c = randomCascade(rng, 1 + trial % 6);
        // More vertices than one block in some trials, so the parallel path runs too.
        std::vector<Vec2> uvs(trial % 4 == 0 ? 20000 : 500);
        for (auto& uv : uvs) uv = Vec2(1.2 * unit(rng) - 0.1, 1.2 * unit(rng) - 0.1);
        const CascadeSampler sampler(c, uvs);
        ASSERT_EQ(sampler.vertexCount(), uvs.size());
        for (int round = 0; round < 5; ++round) {
            std::vector<double> q(c.parameters.size());
            for (auto& x : q) x = unit(rng) < 0.2 ? 0.0 : q01(rng);
            const auto fast = sampler.evaluate(q);
            for (std::size_t i = 0; i < uvs.size(); ++i) {
                const Vec3 slow = c.evaluate(uvs[i][0], uvs[i][1], q);
                ASSERT_NEAR((fast[i] - slow).norm(), 0.0, 1e-12 * (1.0 + slow.norm()))
                    << "trial " << trial << " vertex " << i;
            }
        }
    }
}

// The refinement's sampling function: the indexed evaluation at one pose against the plain one, to
// the bit, on random cascades (rotated regions, regions reaching past the square, two Constant
// stages) and on the bundled face, at random points, points outside the square and points on the
// borders of regions and of the index's cells.
TEST(CascadeAtPose, EqualsThePlainEvaluationToTheBit) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0), q01(-1.0, 2.0);
    const auto check = [&](const DeformationCascade& c, const std::vector<double>& q,
                           const std::string& what) {
        const CascadeAtPose pose(c, q);
        std::vector<Vec2> points;
        for (int i = 0; i < 3000; ++i) points.emplace_back(1.2 * unit(rng) - 0.1, 1.2 * unit(rng) - 0.1);
        for (int i = 0; i <= 64; ++i) points.emplace_back(i / 64.0, unit(rng)); // cell borders, 0 and 1
        for (const auto& stage : c.stages)
            for (const auto& r : stage.field.influences)
                for (const double sign : {-1.0, 1.0}) {
                    points.emplace_back(r.centre[0] + sign * r.radii[0], r.centre[1]);
                    points.emplace_back(r.centre[0], r.centre[1] + sign * r.radii[1]);
                    points.emplace_back(std::nextafter(r.centre[0] + sign * r.radii[0], r.centre[0]),
                                        r.centre[1]);
                }
        for (const auto& uv : points) {
            const Vec3 plain = c.evaluateUnchecked(uv[0], uv[1], q), indexed = pose.at(c, uv[0], uv[1]);
            for (int a = 0; a < 3; ++a)
                ASSERT_EQ(indexed[a], plain[a]) << what << " at (" << uv[0] << ", " << uv[1] << ")";
        }
    };
    for (int trial = 0; trial < 20; ++trial) {
        const DeformationCascade c = randomCascade(rng, 1 + trial % 6);
        std::vector<double> q(c.parameters.size());
        for (auto& x : q) x = unit(rng) < 0.3 ? 0.0 : q01(rng);
        check(c, q, "random cascade " + std::to_string(trial));
    }
    const DeformationCascade face = face::makeBundledFace();
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<double> q(face.parameters.size());
        for (std::size_t k = 0; k < q.size(); ++k)
            q[k] = unit(rng) < 0.5 ? 0.0
                                   : face.parameters[k].min +
                                         unit(rng) * (face.parameters[k].max - face.parameters[k].min);
        check(face, q, "bundled face, pose " + std::to_string(trial));
    }
}

TEST(CascadeSampler, StoresOnlyTheSupportOfInfluenceRegions) {
    DeformationCascade c;
    c.name = "sparse";
    c.parameters = {{"k", 0, 1, 0}};
    DeformationStage base{StageKind::Constant, "base", 0, {}};
    base.field.sampled = sampleGrid(2, 2, [](double u, double v) { return Vec3(u, v, 0); });
    DeformationStage s{StageKind::AddVector, "k", 0, {}};
    InfluenceField r;
    r.centre = Vec2(0.5, 0.5);
    r.radii = Vec2(0.1, 0.1);
    s.field.influences = {r};
    c.stages = {base, s};
    std::vector<Vec2> uvs;
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i) uvs.emplace_back((i + 0.5) / 100, (j + 0.5) / 100);
    const CascadeSampler sampler(c, uvs);
    // About pi * 0.1^2 of the unit square.
    EXPECT_GT(sampler.supportSize(0), 250u);
    EXPECT_LT(sampler.supportSize(0), 350u);
}

TEST(DeformationCascade, RejectsParameterValuesOutsideTheirRange) {
    std::mt19937 rng(5);
    const DeformationCascade c = randomCascade(rng, 3);
    EXPECT_EQ(errorOf([&] {
                  c.evaluate(0.5, 0.5, std::vector<double>{0, 2.5, 0});
              }),
              "parameter 'p1': value 2.5 is outside [-1, 2]");
    EXPECT_NE(errorOf([&] {
                  c.evaluate(0.5, 0.5, std::vector<double>{0, std::nan(""), 0});
              }).find("'p1'"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  c.evaluate(0.5, 0.5, std::vector<double>{0, 0});
              }).find("got 2 parameter values, expected 3"),
              std::string::npos);
    const CascadeSampler sampler(c, std::vector<Vec2>{Vec2(0.5, 0.5)});
    EXPECT_EQ(errorOf([&] {
                  sampler.evaluate(std::vector<double>{-1.5, 0, 0});
              }),
              "parameter 'p0': value -1.5 is outside [-1, 2]");
}

TEST(DeformationCascade, ValidationNamesTheStageOrParameter) {
    std::mt19937 rng(6);
    const DeformationCascade good = randomCascade(rng, 2);
    EXPECT_EQ(errorOf([&] { validateCascade(good); }), "no error");
    auto c = good;
    c.parameters[1].name = "p0";
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("parameter 1 'p0': repeats a name"),
              std::string::npos);
    c = good;
    c.parameters[0].defaultValue = 5;
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("default 5 is outside [-1, 2]"), std::string::npos);
    c = good;
    c.parameters[0].min = 3;
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("min > max"), std::string::npos);
    c = good;
    c.stages[4].parameter = 7;
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("stage 4"), std::string::npos);
    c = good;
    c.stages.erase(c.stages.begin());
    c.stages.erase(c.stages.begin() + 1);
    c.stages.front().kind = StageKind::AddVector;
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("first stage must be a Constant"), std::string::npos);
    c = good;
    c.stages[3].field.influences.at(0).radii = Vec2(-1, 1);
    EXPECT_NE(errorOf([&] { validateCascade(c); }).find("stage 3"), std::string::npos);
    EXPECT_THROW(CascadeSampler(c, std::vector<Vec2>{Vec2(0, 0)}), InputError);
}

TEST(DeformationCascade, RetargetReplacesOnlyTheBase) {
    std::mt19937 rng(7);
    const DeformationCascade c = randomCascade(rng, 2);
    VectorField other;
    other.sampled = sampleGrid(3, 3, [](double u, double v) { return Vec3(10 * u, 10 * v, 1); });
    const DeformationCascade r = retarget(c, other, "other");
    ASSERT_EQ(r.stages.size(), c.stages.size());
    const std::vector<double> zero(2, 0.0), q{0.7, -0.4};
    for (const auto& uv : {Vec2(0.2, 0.3), Vec2(0.8, 0.5)}) {
        EXPECT_NEAR((r.evaluate(uv[0], uv[1], zero) - other.at(uv[0], uv[1])).norm(), 0.0, 1e-12);
        // The deformation (point minus base) is the same for both individuals.
        const Vec3 dc = c.evaluate(uv[0], uv[1], q) - c.evaluate(uv[0], uv[1], zero);
        const Vec3 dr = r.evaluate(uv[0], uv[1], q) - r.evaluate(uv[0], uv[1], zero);
        EXPECT_NEAR((dc - dr).norm(), 0.0, 1e-12);
    }
}

} // namespace
} // namespace vl
