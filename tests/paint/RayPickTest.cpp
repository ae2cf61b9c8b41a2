#include "core/paint/RayPick.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

TEST(RayPick, HitsTheNearestTriangleWithItsBarycentrics) {
    // Two parallel triangles at z = 0 and z = -1, seen from z = +5.
    const std::vector<Vec3> positions = {Vec3(0, 0, 0),  Vec3(1, 0, 0),  Vec3(0, 1, 0),
                                         Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1)};
    const std::vector<Triangle> triangles = {Triangle{3, 4, 5}, Triangle{0, 1, 2}};
    const auto hit = intersectRay(positions, triangles, Vec3(0.25, 0.25, 5.0), Vec3(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangle, 1u);
    EXPECT_NEAR(hit->distance, 5.0, 1e-12);
    EXPECT_NEAR(hit->barycentric[0], 0.5, 1e-12);
    EXPECT_NEAR(hit->barycentric[1], 0.25, 1e-12);
    EXPECT_NEAR(hit->barycentric[2], 0.25, 1e-12);
    EXPECT_FALSE(intersectRay(positions, triangles, Vec3(0.9, 0.9, 5.0), Vec3(0, 0, -1)));  // outside
    EXPECT_FALSE(intersectRay(positions, triangles, Vec3(0.25, 0.25, 5.0), Vec3(0, 0, 1))); // behind
}

TEST(RayPick, HitPointLiesOnTheRayAndInTheTriangle) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<Vec3> positions = {Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)),
                                             Vec3(u(rng), u(rng), u(rng))};
        const std::vector<Triangle> triangles = {Triangle{0, 1, 2}};
        // Aim at a random interior point from a random origin.
        const double a = std::abs(u(rng)), b = std::abs(u(rng)) * (1.0 - a);
        const Vec3 target = positions[0] * (1.0 - a - b) + positions[1] * a + positions[2] * b;
        const Vec3 origin(3.0 * u(rng), 3.0 * u(rng), 5.0);
        const Vec3 direction = (target - origin).normalized();
        const auto hit = intersectRay(positions, triangles, origin, direction);
        if (!hit) continue; // grazing: numerically parallel
        EXPECT_NEAR((hit->point - target).norm(), 0.0, 1e-9);
        EXPECT_NEAR(hit->barycentric[1], a, 1e-6);
        EXPECT_NEAR(hit->barycentric[2], b, 1e-6);
    }
}

} // namespace
} // namespace vl
