// The column-generation solver against the subset DP (itself checked against the textbook recursion
// and brute force): random structureless shapes, rig-like shapes and conflicts, every p. Its
// certificate must hold: lower bound <= the DP's optimum <= its cost, and optimal only at the optimum.
#include "core/reduce/ColumnGeneration.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/GroupCostModel.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/ReductionHeuristics.h"
#include "core/reduce/SubsetDp.h"
#include "tests/reduce/RandomShapes.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

GroupCostModel modelOf(const test::RandomInstance& inst, int n, const ReductionConstraints& constraints) {
    return makeGroupCostModel(centredGram(inst.shapes, inst.frequencies, inst.weights), inst.frequencies,
                              constraintUnits(constraints, n));
}

TEST(ColumnGeneration, AgreesWithTheDpAndItsCertificateHolds) {
    std::mt19937 rng(77);
    int proved = 0, cases = 0;
    for (int n = 5; n <= 13; ++n) {
        for (int variant = 0; variant < 4; ++variant) {
            const auto inst = variant == 1 ? test::rigInstance(rng, n, 12, 3)
                                           : test::randomInstance(rng, n, 9, variant == 2);
            ReductionConstraints constraints;
            if (variant == 3) constraints.apart = {{0, n - 1}, {1, 2}};
            const GroupCostModel model = modelOf(inst, n, constraints);
            const int units = model.size();
            const UnitCurve exact = solveSubsetDp(model, units);
            const auto starts = heuristicPartitions(model, units);
            for (int p = 1; p <= units; ++p) {
                const auto& start = starts[static_cast<std::size_t>(p - 1)];
                const UnitPartition& dp = exact[static_cast<std::size_t>(p - 1)];
                if (start.empty() || dp.groups.empty()) continue;
                const UnitPartition lp = solveByColumnGeneration(model, p, start, SearchLimits{});
                const double tol = 1e-9 * model.scale + 1e-300;
                ++cases;
                EXPECT_LE(lp.lowerBound, dp.cost + tol) << "n=" << n << " p=" << p;
                EXPECT_GE(lp.cost, dp.cost - tol) << "n=" << n << " p=" << p;
                EXPECT_LE(lp.lowerBound, lp.cost);
                ASSERT_EQ(static_cast<int>(lp.groups.size()), p);
                UnitMask all = 0;
                for (const UnitMask g : lp.groups) {
                    EXPECT_EQ(all & g, 0u);
                    EXPECT_TRUE(model.allowed(g));
                    all |= g;
                }
                EXPECT_EQ(all, (UnitMask{1} << units) - 1);
                EXPECT_NEAR(lp.cost, partitionCost(model, lp.groups), tol);
                if (lp.optimal) {
                    ++proved;
                    EXPECT_NEAR(lp.cost, dp.cost, tol) << "n=" << n << " p=" << p;
                    EXPECT_EQ(lp.lowerBound, lp.cost);
                }
            }
        }
    }
    // Without a time limit branch and price proves every case (the LP alone is usually integral).
    EXPECT_EQ(proved, cases);
}

TEST(ColumnGeneration, AnExpiredLimitReturnsTheStartWithAValidBound) {
    std::mt19937 rng(5);
    const auto inst = test::randomInstance(rng, 12, 9);
    const GroupCostModel model = modelOf(inst, 12, {});
    const auto starts = heuristicPartitions(model, 6);
    SearchLimits limits;
    limits.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    const UnitPartition lp = solveByColumnGeneration(model, 6, starts[5], limits);
    EXPECT_FALSE(lp.optimal);
    EXPECT_EQ(lp.groups, starts[5]);
    EXPECT_GE(lp.lowerBound, 0.0);
    EXPECT_LE(lp.lowerBound, lp.cost);
}

TEST(ColumnGeneration, PublishesTheWatchedTargetsResult) {
    // The editor's bound display (and bench_reduce BM_Certify's time to the target) reads the watch:
    // the LP fills it for the watched number of keys, in both models (rest-free: the rest group is
    // not a key), with the target's cost and proven bound.
    std::mt19937 rng(29);
    const auto inst = test::randomInstance(rng, 11, 12);
    for (const bool restFree : {false, true}) {
        const int m = 4;
        BoundWatch watch(m);
        ReductionOptions options;
        options.method = ReductionMethod::ColumnGeneration;
        options.watch = &watch;
        const RestPose rest{restFree, 0, {}};
        const auto result =
            reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m, {}, rest}, options);
        ASSERT_TRUE(result.best().optimal) << "rest free " << restFree;
        EXPECT_DOUBLE_EQ(watch.bestFound.load(), result.best().cost) << "rest free " << restFree;
        EXPECT_DOUBLE_EQ(watch.lowerBound.load(), result.best().cost) << "rest free " << restFree;
    }
}

} // namespace
} // namespace vl

namespace vl {
namespace {

TEST(ColumnGeneration, AutoProvesAStructurelessSetBeyondTheDp) {
    // 23 random shapes: branch and bound's share is not enough, the DP does not take them, the LP
    // proves every p.
    std::mt19937 rng(23);
    const auto inst = test::randomInstance(rng, kMaxSubsetDpUnits + 1, 12);
    const auto result = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 4});
    EXPECT_EQ(result.method, ReductionMethod::ColumnGeneration);
    for (std::size_t p = 0; p < result.curve.size(); ++p) {
        EXPECT_TRUE(result.curve[p].optimal) << "p=" << p + 1;
        EXPECT_TRUE(
            test::isValidGrouping(result.curve[p].groups, kMaxSubsetDpUnits + 1, static_cast<int>(p) + 1));
    }
}

} // namespace
} // namespace vl

namespace vl {
namespace {

TEST(ColumnGeneration, TakesSetsBeyondTheOldLimitOf26Units) {
    // Pricing no longer lists all 2^n groups: 34 rig-like shapes by the LP alone, with a valid
    // certificate for every p and the target proved, and the same optimum as branch and bound.
    std::mt19937 rng(34);
    const auto inst = test::rigInstance(rng, 34, 30, 4);
    ReductionOptions options;
    options.method = ReductionMethod::ColumnGeneration;
    options.timeLimitSeconds = 120; // a safety net: the LP proves this in about a second
    const auto lp = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 8}, options);
    EXPECT_EQ(lp.method, ReductionMethod::ColumnGeneration);
    EXPECT_TRUE(lp.best().optimal);
    options.method = ReductionMethod::BranchAndBound;
    const auto bnb = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 8}, options);
    for (std::size_t p = 0; p < lp.curve.size(); ++p) {
        const Grouping& g = lp.curve[p];
        EXPECT_TRUE(test::isValidGrouping(g.groups, 34, static_cast<int>(p) + 1));
        EXPECT_LE(g.lowerBound, g.cost);
        if (bnb.curve[p].optimal) {
            EXPECT_LE(g.lowerBound, bnb.curve[p].cost * (1 + 1e-9)) << "p=" << p + 1;
            if (g.optimal) {
                EXPECT_NEAR(g.cost, bnb.curve[p].cost, 1e-9 * g.cost) << "p=" << p + 1;
            }
        }
    }
}

} // namespace
} // namespace vl

namespace vl {
namespace {

TEST(ColumnGeneration, BranchAndPriceClosesFractionalRoots) {
    // Small random sets whose root LP is fractional (found by search: the run needed more than one
    // node), each proved at the DP's optimum by branching.
    std::mt19937 rng(2025);
    int branched = 0;
    for (int trial = 0; trial < 3000 && branched < 6; ++trial) {
        const int n = 6 + trial % 6;
        const auto inst = test::randomInstance(rng, n, 2 + trial % 3); // low dimension: fractional roots
        const GroupCostModel model = modelOf(inst, n, {});
        const auto starts = heuristicPartitions(model, n);
        const UnitCurve exact = solveSubsetDp(model, n);
        for (int p = 2; p < n; ++p) {
            ColumnGenerationStats stats;
            const UnitPartition lp = solveByColumnGeneration(
                model, p, starts[static_cast<std::size_t>(p - 1)], SearchLimits{}, nullptr, &stats);
            const double tol = 1e-9 * model.scale + 1e-300;
            ASSERT_TRUE(lp.optimal) << "n=" << n << " p=" << p;
            EXPECT_NEAR(lp.cost, exact[static_cast<std::size_t>(p - 1)].cost, tol) << "n=" << n << " p=" << p;
            if (stats.nodes > 1) ++branched;
        }
    }
    EXPECT_GE(branched, 6) << "no fractional root found: the branching is untested";
}

} // namespace
} // namespace vl
