#include "core/deform/VectorField.h"
#include "core/common/Error.h"
#include "tests/deform/ErrorMessage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vl {
namespace {

SampledField randomGrid(int w, int h, std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-5.0, 5.0);
    return sampleGrid(w, h, [&](double, double) { return Vec3(d(rng), d(rng), d(rng)); });
}

TEST(SampledField, BilinearIsExactAtGridPoints) {
    std::mt19937 rng(1);
    const SampledField grid = randomGrid(7, 5, rng);
    for (int j = 0; j < grid.height; ++j)
        for (int i = 0; i < grid.width; ++i)
            EXPECT_EQ(grid.at(i / 6.0, j / 4.0), grid.sample(i, j)) << i << "," << j;
}

TEST(SampledField, ReproducesBilinearFunctionsBetweenGridPoints) {
    const auto f = [](double u, double v) { return Vec3(1 + 2 * u - v, 3 * u * v, -u + 0.5 * v + u * v); };
    const SampledField grid = sampleGrid(9, 4, f);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> d(0.0, 1.0);
    for (int k = 0; k < 200; ++k) {
        const double u = d(rng), v = d(rng);
        EXPECT_NEAR((grid.at(u, v) - f(u, v)).norm(), 0.0, 1e-12);
    }
}

TEST(SampledField, ClampsOutsideTheDomain) {
    std::mt19937 rng(3);
    const SampledField grid = randomGrid(4, 4, rng);
    EXPECT_EQ(grid.at(-0.5, -2.0), grid.sample(0, 0));
    EXPECT_EQ(grid.at(1.5, 7.0), grid.sample(3, 3));
    EXPECT_EQ(grid.at(2.0, 0.0), grid.sample(3, 0));
}

TEST(SampledField, EmptyGridIsZero) {
    EXPECT_EQ(SampledField{}.at(0.3, 0.2), Vec3(0, 0, 0));
}

TEST(Falloff, EveryKindIsMonotoneFromOneToZero) {
    for (const Falloff f : {Falloff::Linear, Falloff::Smoothstep, Falloff::Cosine, Falloff::Gaussian}) {
        EXPECT_DOUBLE_EQ(falloffWeight(f, 0.0), 1.0) << toString(f);
        EXPECT_DOUBLE_EQ(falloffWeight(f, 1.0), 0.0) << toString(f);
        EXPECT_DOUBLE_EQ(falloffWeight(f, 1.5), 0.0) << toString(f);
        double previous = 1.0;
        for (int k = 1; k <= 1000; ++k) {
            const double w = falloffWeight(f, k / 1000.0);
            EXPECT_LE(w, previous) << toString(f) << " at " << k;
            EXPECT_GE(w, 0.0);
            previous = w;
        }
        EXPECT_LT(falloffWeight(f, 0.999), 0.01) << toString(f) << " must approach 0 continuously";
        EXPECT_EQ(parseEnum<Falloff>(toString(f), "test"), f);
    }
    EXPECT_THROW(parseEnum<Falloff>("quadratic", "field.falloff"), InputError);
}

InfluenceField sampleRegion() {
    InfluenceField r;
    r.centre = Vec2(0.4, 0.6);
    r.radii = Vec2(0.2, 0.1);
    r.rotation = 0.5;
    r.direction = Vec3(0, 3, 4);
    r.magnitude = 2.0;
    return r;
}

TEST(InfluenceField, FullMagnitudeAtTheCentreAlongTheNormalisedDirection) {
    const InfluenceField r = sampleRegion();
    const Vec3 v = r.at(0.4, 0.6);
    EXPECT_NEAR((v - Vec3(0, 1.2, 1.6)).norm(), 0.0, 1e-14);
}

TEST(InfluenceField, ZeroOnAndOutsideTheRotatedEllipse) {
    for (const double plateau : {0.0, 0.5}) {
        InfluenceField r = sampleRegion();
        r.plateau = r.radii * plateau;
        const double c = std::cos(r.rotation), s = std::sin(r.rotation);
        for (int k = 0; k < 360; ++k) {
            const double a = k * M_PI / 180.0;
            // A point on the outer ellipse in its local frame, rotated into (u,v).
            const double x = r.radii[0] * std::cos(a), y = r.radii[1] * std::sin(a);
            const double u = r.centre[0] + c * x - s * y, v = r.centre[1] + s * x + c * y;
            EXPECT_NEAR(r.weight(u, v), 0.0, 1e-12);
            EXPECT_EQ(
                r.weight(r.centre[0] + 1.01 * (u - r.centre[0]), r.centre[1] + 1.01 * (v - r.centre[1])),
                0.0);
            EXPECT_GT(
                r.weight(r.centre[0] + 0.97 * (u - r.centre[0]), r.centre[1] + 0.97 * (v - r.centre[1])),
                0.0);
        }
    }
}

TEST(InfluenceField, PlateauIsConstantAndFalloffMonotoneAlongRays) {
    InfluenceField r = sampleRegion();
    r.plateau = Vec2(0.12, 0.03);
    r.falloff = Falloff::Cosine;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
    for (int k = 0; k < 100; ++k) {
        const double a = angle(rng);
        double previous = 1.0;
        for (int step = 0; step <= 400; ++step) {
            const double t = step * 0.3 / 400;
            const double w = r.weight(r.centre[0] + t * std::cos(a), r.centre[1] + t * std::sin(a));
            EXPECT_LE(w, previous + 1e-15);
            previous = w;
        }
    }
    // Inside the plateau ellipse (local frame, rotated) the weight is exactly 1.
    const double c = std::cos(r.rotation), s = std::sin(r.rotation);
    const double x = 0.1, y = 0.01; // (0.1/0.12)^2 + (0.01/0.03)^2 < 1
    EXPECT_EQ(r.weight(r.centre[0] + c * x - s * y, r.centre[1] + s * x + c * y), 1.0);
}

TEST(VectorField, SumsTheSampledPartAndTheRegions) {
    VectorField f;
    f.sampled = sampleGrid(2, 2, [](double u, double v) { return Vec3(u, v, 1); });
    InfluenceField a = sampleRegion(), b = sampleRegion();
    b.centre = Vec2(0.5, 0.55);
    b.direction = Vec3(1, 0, 0);
    f.influences = {a, b};
    const Vec3 expected = f.sampled.at(0.45, 0.58) + a.at(0.45, 0.58) + b.at(0.45, 0.58);
    EXPECT_NEAR((f.at(0.45, 0.58) - expected).norm(), 0.0, 1e-15);
    EXPECT_FALSE(f.isZero());
    EXPECT_TRUE(VectorField{}.isZero());
}

TEST(VectorField, ValidationNamesTheProblem) {
    const auto message = [](const VectorField& f) {
        return test::errorOf([&] { validateField(f, "stage 'jaw'"); });
    };
    VectorField f;
    f.influences.push_back(sampleRegion());
    EXPECT_EQ(message(f), "no error");
    f.influences[0].radii = Vec2(0.0, 0.1);
    EXPECT_NE(message(f).find("stage 'jaw': influence 0"), std::string::npos) << message(f);
    f.influences[0] = sampleRegion();
    f.influences[0].plateau = Vec2(0.3, 0.05);
    EXPECT_NE(message(f).find("plateau"), std::string::npos);
    f.influences[0] = sampleRegion();
    f.influences[0].direction = Vec3(0, 0, 0);
    EXPECT_NE(message(f).find("direction"), std::string::npos);
    f.influences[0] = sampleRegion();
    f.influences[0].magnitude = std::nan("");
    EXPECT_NE(message(f).find("not finite"), std::string::npos);
    VectorField g;
    g.sampled.width = 3;
    g.sampled.height = 2;
    g.sampled.samples.resize(5);
    EXPECT_NE(message(g).find("5 samples, expected 6"), std::string::npos) << message(g);
}

} // namespace
} // namespace vl
