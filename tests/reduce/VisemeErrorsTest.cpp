#include "core/reduce/VisemeErrors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vl;

TEST(VisemeErrors, DistancesToTheKeyMeanOrTheRestPose) {
    // Two vertices; the second does not count (weight 0).
    const std::vector<std::vector<Vec3>> shapes = {
        {Vec3(0, 0, 0), Vec3(9, 9, 9)},  // rests
        {Vec3(3, 0, 0), Vec3(0, 0, 0)},  // key 0 with viseme 2: mean (1,0,0) at frequencies 1:2
        {Vec3(0, 0, 0), Vec3(0, 0, 0)},  //
        {Vec3(0, 4, 0), Vec3(0, 0, 0)}}; // key 1 alone
    const std::vector<Vec3> rest = {Vec3(0, 0, 1), Vec3(0, 0, 0)};
    const std::vector<double> frequencies = {5, 1, 2, 1}, weights = {2, 0};
    const std::vector<int> groupOf = {-1, 0, 0, 1};
    const auto errors = visemeErrors(shapes, rest, frequencies, weights, groupOf);
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_DOUBLE_EQ(errors[0].max, 1.0); // to the rest pose
    EXPECT_DOUBLE_EQ(errors[1].max, 2.0); // |3 - 1|
    EXPECT_DOUBLE_EQ(errors[2].max, 1.0);
    EXPECT_DOUBLE_EQ(errors[3].max, 0.0);
    EXPECT_DOUBLE_EQ(errors[1].rms, 2.0); // one counted vertex
    EXPECT_DOUBLE_EQ(errors[1].largestDisplacement, std::sqrt(10.0));
    EXPECT_DOUBLE_EQ(errors[3].largestDisplacement, std::sqrt(17.0));
    // Without frequencies, a key shows the plain mean.
    const auto plain = visemeErrors(shapes, rest, std::vector<double>{1, 0, 0, 1}, weights, groupOf);
    EXPECT_DOUBLE_EQ(plain[1].max, 1.5);
}
