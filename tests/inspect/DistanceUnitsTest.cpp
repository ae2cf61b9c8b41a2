// Reduction cost as a distance (RMS, model units -> mm) and plot axis ticks.
#include "core/inspect/DistanceUnits.h"
#include "core/reduce/Reduction.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace vl {
namespace {

// Two visemes, one moved by d everywhere: merged into one group each vertex is d/2 from the mean,
// so the RMS distance of the grouping is d/2 whatever the weights.
TEST(DistanceUnits, RmsDistanceOfTwoMergedShapesIsHalfTheirOffset) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> any(-1.0, 1.0), positive(0.1, 3.0);
    for (int trial = 0; trial < 20; ++trial) {
        const std::size_t vertices = 5 + trial;
        std::vector<Vec3> a(vertices), b(vertices);
        const Vec3 offset{any(random), any(random), any(random)};
        std::vector<double> weights(vertices);
        double weightSum = 0.0;
        for (std::size_t k = 0; k < vertices; ++k) {
            a[k] = {any(random), any(random), any(random)};
            b[k] = {a[k][0] + offset[0], a[k][1] + offset[1], a[k][2] + offset[2]};
            weights[k] = positive(random);
            weightSum += weights[k];
        }
        const std::vector<std::vector<Vec3>> shapes = {a, b};
        const std::vector<double> frequencies = {0.5, 0.5};
        const double cost = groupingCost(shapes, frequencies, weights, {{0, 1}});
        const double d = std::sqrt(offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2]);
        EXPECT_NEAR(rmsDistance(cost, 1.0, weightSum), d / 2, 1e-9 * (1 + d));
    }
    EXPECT_EQ(rmsDistance(0.0, 1.0, 1.0), 0.0);
    EXPECT_EQ(rmsDistance(1.0, 0.0, 1.0), 0.0);
}

TEST(DistanceUnits, LengthUnitGuessedFromTheHeadSize) {
    EXPECT_EQ(guessLengthUnit(0.22), LengthUnit::Metre);      // MediaPipe-like, glTF
    EXPECT_EQ(guessLengthUnit(25.0), LengthUnit::Centimetre); // ICT FaceKit-like
    EXPECT_EQ(guessLengthUnit(240.0), LengthUnit::Millimetre);
    EXPECT_EQ(guessLengthUnit(0.0), LengthUnit::Metre);
    EXPECT_DOUBLE_EQ(millimetresPer(LengthUnit::Inch), 25.4);
    EXPECT_STREQ(lengthUnitName(LengthUnit::Centimetre), "cm");
}

TEST(DistanceUnits, AxisTicksAreNiceAndCoverTheRange) {
    double ticks[32];
    int count = axisTicks(0.0, 1.0, 5, false, ticks, 32);
    ASSERT_EQ(count, 6);
    EXPECT_DOUBLE_EQ(ticks[0], 0.0);
    EXPECT_NEAR(ticks[5], 1.0, 1e-12);
    count = axisTicks(0.0, 7.3, 4, false, ticks, 32); // step 2
    ASSERT_EQ(count, 4);
    EXPECT_NEAR(ticks[3], 6.0, 1e-12);
    count = axisTicks(1e-4, 0.3, 5, true, ticks, 32); // decades
    ASSERT_EQ(count, 4);
    EXPECT_NEAR(ticks[0], 1e-4, 1e-16);
    EXPECT_NEAR(ticks[3], 0.1, 1e-12);
    count = axisTicks(1e-8, 10.0, 4, true, ticks, 32); // ten decades: every third, 1e-6, 1e-3, 1
    ASSERT_EQ(count, 3);
    EXPECT_NEAR(ticks[0], 1e-6, 1e-18);
    EXPECT_NEAR(ticks[1], 1e-3, 1e-15);
    EXPECT_NEAR(ticks[2], 1.0, 1e-12);
    count = axisTicks(0.01, 10.0, 4, true, ticks, 32); // four decades: all of them
    EXPECT_EQ(count, 4);
    count = axisTicks(0.2, 0.5, 4, true, ticks, 32); // less than a decade: linear steps
    EXPECT_GE(count, 2);
    for (int i = 0; i < count; ++i) EXPECT_TRUE(ticks[i] >= 0.2 - 1e-12 && ticks[i] <= 0.5 + 1e-12);
    EXPECT_EQ(axisTicks(1.0, 0.0, 5, false, ticks, 32), 0);
    EXPECT_LE(axisTicks(0.0, 1e6, 5, false, ticks, 3), 3);
}

} // namespace
} // namespace vl
