#include "AnalyticSurfaces.h"

#include "core/adaptive/ContourError.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

TEST(ContourError, PatternIsTheCentroidRuleOfTheBarycentricGrid) {
    for (int n = 1; n <= 7; ++n) {
        const auto pattern = contourSamplePattern(n);
        ASSERT_EQ(pattern.size(), static_cast<std::size_t>(n * n));
        Vec3 mean(0, 0, 0);
        for (const auto& w : pattern) {
            EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-15);
            for (int k = 0; k < 3; ++k) EXPECT_GT(w[k], 0.0);
            mean += w / static_cast<double>(pattern.size());
        }
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], 1.0 / 3.0, 1e-14) << "n " << n;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(contourSamplePattern(1).front()[k], 1.0 / 3.0, 1e-15);
}

TEST(ContourError, PlanesHaveNoError) {
    const test::FunctionSurface plane(test::gridDomain(1, 1, test::Diagonals::Same), test::tiltedPlane);
    const std::array<Vec2, 3> uv{Vec2(0.1, 0.1), Vec2(0.9, 0.2), Vec2(0.3, 0.8)};
    const std::array<Vec3, 3> p{plane.sample(uv[0]), plane.sample(uv[1]), plane.sample(uv[2])};
    const auto e = triangleContourError(plane, uv, p, contourSamplePattern(5));
    EXPECT_NEAR(e.average, 0.0, 1e-15);
    EXPECT_NEAR(e.maximum, 0.0, 1e-15);
}

TEST(ContourError, TheEarlyStoppingTestAgreesWithTheFullErrorOnRandomTriangles) {
    // The refinement test stops at the first sample over the maximum or once the running sum alone
    // puts the average over its limit; the answer must be that of the full computation, also for
    // limits right at a triangle's own average or maximum.
    const test::BumpySurface surface(test::gridDomain(1, 1, test::Diagonals::Same));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int exceeded = 0, held = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::array<Vec2, 3> uv;
        std::array<Vec3, 3> p;
        const double size = 0.02 + 0.3 * unit(rng);
        const Vec2 origin(unit(rng) * (1 - size), unit(rng) * (1 - size));
        for (int k = 0; k < 3; ++k) {
            uv[k] = origin + size * Vec2(unit(rng), unit(rng));
            p[k] = surface.sample(uv[k]) + Vec3(0, 0, 0.01 * (unit(rng) - 0.5)); // off the surface too
        }
        const auto pattern = contourSamplePattern(1 + trial % 6);
        const TriangleError full = triangleContourError(surface, uv, p, pattern);
        const double limits[] = {
            0.0, full.average, full.maximum, full.average * unit(rng), full.maximum * (1 + unit(rng)), 1e9};
        for (const double average : limits)
            for (const double maximum : limits) {
                const bool expected = full.average > average || full.maximum > maximum;
                EXPECT_EQ(triangleContourErrorExceeds(surface, uv, p, pattern, average, maximum), expected)
                    << "trial " << trial;
                (expected ? exceeded : held) += 1;
            }
    }
    EXPECT_GT(exceeded, 1000);
    EXPECT_GT(held, 1000);
}

// On the paraboloid z = u^2 + v^2 the error of a triangle at x is sum_i w_i |x_i - x|^2, whose exact
// mean over the triangle is (sum of squared edge lengths) / 12; the centroid rule on n x n
// sub-triangles misses each sub-triangle's second moment, adding (sum of squared edges) / (36 n^2).
TEST(ContourError, AverageMatchesTheClosedFormOnAParaboloid) {
    const test::FunctionSurface paraboloid(test::gridDomain(1, 1, test::Diagonals::Same),
                                           [](const Vec2& uv) { return Vec3(uv[0], uv[1], uv.sqrnorm()); });
    const std::array<Vec2, 3> uv{Vec2(0.2, 0.1), Vec2(0.9, 0.3), Vec2(0.4, 0.7)};
    const std::array<Vec3, 3> p{paraboloid.sample(uv[0]), paraboloid.sample(uv[1]), paraboloid.sample(uv[2])};
    const double edges2 = (uv[1] - uv[0]).sqrnorm() + (uv[2] - uv[1]).sqrnorm() + (uv[0] - uv[2]).sqrnorm();
    for (int n = 1; n <= 6; ++n) {
        const auto e = triangleContourError(paraboloid, uv, p, contourSamplePattern(n));
        EXPECT_NEAR(e.average, edges2 / 12.0 + edges2 / (36.0 * n * n), 1e-13) << "n " << n;
        EXPECT_LE(e.maximum, edges2 / 3.0); // the error is at most the largest squared distance / 4
        EXPECT_GE(e.maximum, e.average);
    }
}

TEST(ContourError, MeasurementWeightsTrianglesByTheirDomainArea) {
    // z = 0 on the left half, a ridge z = max(0, u - 0.5) on the right: two triangles with different
    // areas and known errors, measured against a flat mesh (all positions z = 0).
    const test::FunctionSurface ridge(test::gridDomain(1, 1, test::Diagonals::Same), [](const Vec2& uv) {
        return Vec3(uv[0], uv[1], std::max(0.0, uv[0] - 0.5));
    });
    MeshData flat;
    flat.uvs = {Vec2(0, 0), Vec2(0.5, 0), Vec2(0.5, 1), Vec2(1.5, 0), Vec2(1.5, 1)};
    for (const auto& uv : flat.uvs) flat.positions.emplace_back(uv[0], uv[1], 0.0);
    flat.triangles = {{0, 1, 2}, {1, 3, 4}}; // area 0.25 with no error, area 0.5 with error u - 0.5
    const auto stats = measureContourError(flat, ridge, 6);
    // Mean of u - 0.5 over the right triangle (corners u = 0.5, 1.5, 1.5) is 2/3 exactly (linear).
    EXPECT_NEAR(stats.average, (0.25 * 0.0 + 0.5 * (2.0 / 3.0)) / 0.75, 1e-12);
    EXPECT_LT(stats.maximum, 1.0);
    EXPECT_GT(stats.maximum, 0.9);
    EXPECT_EQ(stats.samples, 72u);
    MeshData noUV = flat;
    noUV.uvs.clear();
    EXPECT_THROW(measureContourError(noUV, ridge), InputError);
}

} // namespace
} // namespace vl
