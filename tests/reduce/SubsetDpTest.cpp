// The subset DP's SIMD kernel against the DP written the obvious way: every subset, every split
// containing its lowest unit, one layer and one double at a time. Sizes from the plain loop (up to 8
// units: one tile) to several tiles, every width of a row (m), with and without units that may not
// share a group.
#include "core/reduce/SubsetDp.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/GroupCostModel.h"
#include "tests/reduce/RandomShapes.h"

#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <random>

namespace vl {
namespace {

// best[p - 1] = the optimal cost of partitioning all units into p groups (+inf when none respects the
// conflicts), by the textbook recursion over all 2^n subsets.
std::vector<double> plainDp(const GroupCostModel& model, int m) {
    const int n = model.size();
    const std::size_t count = std::size_t{1} << n;
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> cost(count, inf);
    for (std::size_t s = 1; s < count; ++s)
        if (model.allowed(s)) cost[s] = model.cost(s);
    std::vector<double> layer = cost, result{cost[count - 1]};
    for (int p = 2; p <= m; ++p) {
        std::vector<double> next(count, inf);
        for (std::size_t s = 1; s < count; ++s) {
            const std::size_t lowest = s & (~s + 1), others = s ^ lowest;
            for (std::size_t r = others;; r = (r - 1) & others) {
                if (r != 0) next[s] = std::min(next[s], cost[s ^ r] + layer[r]);
                if (r == 0) break;
            }
        }
        layer = std::move(next);
        result.push_back(layer[count - 1]);
    }
    return result;
}

TEST(SubsetDp, LayerKernelAgreesWithThePlainRecursion) {
    std::mt19937 rng(2026);
    for (int n = 6; n <= 14; ++n) {
        for (int variant = 0; variant < 4; ++variant) {
            const auto inst = test::randomInstance(rng, n, 9, variant == 1);
            ReductionConstraints constraints;
            if (variant >= 2) constraints.apart = {{0, n - 1}, {n - 1, 3}, {0, 3}, {2, 5}}; // p >= 3
            const GroupCostModel model =
                makeGroupCostModel(centredGram(inst.shapes, inst.frequencies, inst.weights), inst.frequencies,
                                   constraintUnits(constraints, n));
            const std::vector<double> reference = plainDp(model, n);
            // m sets how many layers share a row: 1 (m = 2), one vector (3..6), two, and up to n.
            for (const int m : {2, 3, 6, 7, 10, n}) {
                if (m > n) continue;
                const UnitCurve curve = solveSubsetDp(model, m);
                ASSERT_EQ(curve.size(), static_cast<std::size_t>(m));
                for (int p = 1; p <= m; ++p) {
                    const UnitPartition& entry = curve[static_cast<std::size_t>(p - 1)];
                    const double expected = reference[static_cast<std::size_t>(p - 1)];
                    EXPECT_TRUE(entry.optimal);
                    if (!(expected < std::numeric_limits<double>::infinity())) {
                        EXPECT_TRUE(entry.groups.empty()) << "n=" << n << " p=" << p;
                        continue;
                    }
                    ASSERT_EQ(static_cast<int>(entry.groups.size()), p) << "n=" << n << " p=" << p;
                    UnitMask all = 0;
                    for (const UnitMask g : entry.groups) {
                        EXPECT_NE(g, 0u);
                        EXPECT_EQ(all & g, 0u);
                        EXPECT_TRUE(model.allowed(g));
                        all |= g;
                    }
                    EXPECT_EQ(all, (UnitMask{1} << n) - 1);
                    EXPECT_NEAR(entry.cost, expected, 1e-12 * model.scale + 1e-300)
                        << "n=" << n << " p=" << p;
                }
            }
        }
    }
}

} // namespace
} // namespace vl
