#include "core/inspect/VertexErrors.h"
#include "core/common/Error.h"
#include "core/reduce/Reduction.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

namespace vl {
namespace {

TEST(VertexErrors, SumIsTheDissimilarity) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> a, b;
    std::vector<double> w;
    for (int k = 0; k < 100; ++k) {
        a.emplace_back(u(rng), u(rng), u(rng));
        b.emplace_back(u(rng), u(rng), u(rng));
        w.push_back(std::abs(u(rng)));
    }
    const auto errors = vertexErrors(a, b, w);
    ASSERT_EQ(errors.size(), 100u);
    EXPECT_NEAR(std::accumulate(errors.begin(), errors.end(), 0.0), dissimilarity(a, b, w), 1e-12);
    EXPECT_DOUBLE_EQ(errors[3], w[3] * (a[3] - b[3]).sqrnorm());
}

TEST(VertexErrors, SizeMismatchIsAnInputError) {
    const std::vector<Vec3> a(3), b(2);
    const std::vector<double> w(3, 1.0);
    EXPECT_THROW(vertexErrors(a, b, w), InputError);
}

} // namespace
} // namespace vl
