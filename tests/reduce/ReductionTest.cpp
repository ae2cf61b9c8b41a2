#include "BruteForce.h"
#include "RandomShapes.h"

#include "core/common/Error.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/SubsetDp.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <limits>

using namespace vl;

namespace {

ReductionResult reduce(const test::RandomInstance& inst, int m) {
    return reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m});
}

void expectIsPartition(const Grouping& g, int n, int p) {
    ASSERT_EQ(static_cast<int>(g.groups.size()), p);
    std::vector<int> seen(static_cast<std::size_t>(n), 0);
    for (const auto& group : g.groups) {
        ASSERT_FALSE(group.empty());
        for (const int i : group) ++seen[static_cast<std::size_t>(i)];
    }
    for (const int s : seen) EXPECT_EQ(s, 1);
}

} // namespace

TEST(Reduction, MergedMeshIsTheArgminUnderPerturbation) {
    std::mt19937 rng(7);
    const auto inst = test::randomInstance(rng, 5, 40);
    const std::vector<int> group = {0, 2, 3};
    const auto merged = mergeGroup(inst.shapes, inst.frequencies, group);
    auto groupCost = [&](const std::vector<Vec3>& b) {
        double sum = 0;
        for (const int i : group) sum += inst.frequencies[i] * dissimilarity(inst.shapes[i], b, inst.weights);
        return sum;
    };
    const double optimum = groupCost(merged);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (const double scale : {1e-1, 1e-3, 1e-5}) {
        for (int trial = 0; trial < 20; ++trial) {
            auto moved = merged;
            for (auto& v : moved) v += Vec3(noise(rng), noise(rng), noise(rng)) * scale;
            EXPECT_GT(groupCost(moved), optimum);
        }
    }
    // The closed form is independent of the weights: any positive weights give the same mean.
    const auto mergedAgain = mergeGroup(inst.shapes, inst.frequencies, group);
    EXPECT_EQ(merged, mergedAgain);
}

TEST(Reduction, DynamicProgrammeEqualsBruteForceOnRandomInstances) {
    std::mt19937 rng(12345);
    for (int n = 1; n <= 9; ++n) {
        for (int trial = 0; trial < (n <= 6 ? 4 : 1); ++trial) {
            const auto inst = test::randomInstance(rng, n, 12, trial == 1);
            const auto result = reduce(inst, n);
            ASSERT_EQ(static_cast<int>(result.curve.size()), n);
            for (int m = 1; m <= n; ++m) {
                const Grouping& g = result.curve[static_cast<std::size_t>(m - 1)];
                expectIsPartition(g, n, m);
                const double reference = *test::bruteForceBest(inst, m);
                const double tolerance = 1e-9 * std::max(1.0, reference);
                EXPECT_NEAR(g.cost, reference, tolerance) << "n=" << n << " m=" << m;
                // The reported cost is the direct cost of the reported grouping.
                EXPECT_NEAR(groupingCost(inst.shapes, inst.frequencies, inst.weights, g.groups), g.cost,
                            tolerance);
            }
        }
    }
}

TEST(Reduction, CurveIsNonIncreasingAndEndsAtZero) {
    std::mt19937 rng(99);
    const auto inst = test::randomInstance(rng, 10, 30);
    const auto result = reduce(inst, 10);
    for (std::size_t p = 1; p < result.curve.size(); ++p)
        EXPECT_LE(result.curve[p].cost, result.curve[p - 1].cost + 1e-12);
    EXPECT_NEAR(result.curve.back().cost, 0.0, 1e-9);
}

TEST(Reduction, TargetBelowNGivesSameCurvePrefixAsFullRun) {
    std::mt19937 rng(5);
    const auto inst = test::randomInstance(rng, 11, 20);
    const auto full = reduce(inst, 11);
    const auto partial = reduce(inst, 6);
    ASSERT_EQ(partial.curve.size(), 6u);
    for (std::size_t p = 0; p < 6; ++p) {
        EXPECT_DOUBLE_EQ(partial.curve[p].cost, full.curve[p].cost);
        EXPECT_EQ(partial.curve[p].groups, full.curve[p].groups);
    }
}

TEST(Reduction, ResultIsDeterministicAcrossRuns) {
    std::mt19937 rng(3);
    const auto inst = test::randomInstance(rng, 14, 25);
    const auto a = reduce(inst, 8);
    const auto b = reduce(inst, 8);
    for (std::size_t p = 0; p < a.curve.size(); ++p) {
        EXPECT_EQ(a.curve[p].cost, b.curve[p].cost);
        EXPECT_EQ(a.curve[p].groups, b.curve[p].groups);
    }
}

TEST(Reduction, DynamicProgrammeDoesNotDependOnTheThreadCount) {
    // 13 visemes: 12 DP bits, 8 tiles run in parallel; ties broken by recovery order, not by timing.
    std::mt19937 rng(31);
    const auto inst = test::randomInstance(rng, 13, 20, true);
    auto solveWith = [&](std::size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return reduce(inst, 9);
    };
    const auto one = solveWith(1), two = solveWith(2);
    for (std::size_t p = 0; p < one.curve.size(); ++p) {
        EXPECT_EQ(one.curve[p].cost, two.curve[p].cost) << "p=" << p + 1;
        EXPECT_EQ(one.curve[p].groups, two.curve[p].groups) << "p=" << p + 1;
    }
}

TEST(Reduction, TiesAreBrokenDeterministically) {
    // Four identical shapes: every grouping into 2 groups costs 0; the answer must still be fixed.
    std::vector<std::vector<Vec3>> shapes(4, std::vector<Vec3>{Vec3(1, 2, 3), Vec3(4, 5, 6)});
    const std::vector<double> f(4, 0.25), w(2, 1.0);
    const auto r1 = reduceVisemes({shapes, f, w, 2});
    const auto r2 = reduceVisemes({shapes, f, w, 2});
    EXPECT_EQ(r1.best().groups, r2.best().groups);
    EXPECT_EQ(r1.best().cost, 0.0);
}

TEST(Reduction, GroupOfMapsEveryVisemeToItsGroup) {
    std::mt19937 rng(11);
    const auto inst = test::randomInstance(rng, 7, 10);
    const auto result = reduce(inst, 3);
    const auto groupOf = result.groupOf();
    ASSERT_EQ(groupOf.size(), 7u);
    for (std::size_t g = 0; g < result.best().groups.size(); ++g)
        for (const int i : result.best().groups[g]) EXPECT_EQ(groupOf[i], static_cast<int>(g));
}

TEST(Reduction, RejectsBadProblems) {
    std::mt19937 rng(1);
    auto inst = test::randomInstance(rng, 4, 5);
    auto expectError = [&](int m, const std::string& fragment) {
        try {
            reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m});
            ADD_FAILURE() << "expected an error containing '" << fragment << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectError(0, "outside 1..4");
    expectError(5, "outside 1..4");
    inst.frequencies[2] = -1;
    expectError(2, "frequency of viseme 2");
    inst.frequencies = {0, 0, 0, 0};
    expectError(2, "all frequencies are zero");
    inst.frequencies = {1, 1, 1, std::numeric_limits<double>::quiet_NaN()};
    expectError(2, "frequency of viseme 3");
    inst.frequencies = {1, 1, 1, 1};
    inst.weights[0] = -2;
    expectError(2, "weight of vertex 0");
    inst.weights[0] = 1;
    inst.shapes[3].pop_back();
    expectError(2, "viseme 3 has 4 vertices");

    auto big = test::randomInstance(rng, kMaxReductionVisemes + 1, 2);
    try {
        reduceVisemes({big.shapes, big.frequencies, big.weights, 3});
        ADD_FAILURE() << "n above the supported limit must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("at most 64"), std::string::npos) << e.what();
    }
    auto large = test::randomInstance(rng, kMaxSubsetDpUnits + 1, 2);
    ReductionOptions dp;
    dp.method = ReductionMethod::SubsetDp;
    try {
        reduceVisemes({large.shapes, large.frequencies, large.weights, 3}, dp);
        ADD_FAILURE() << "the DP must refuse sets above its limit when forced";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("use branch and bound"), std::string::npos) << e.what();
    }
}

TEST(Reduction, SetsAboveTwentyVisemesAreReducedWithACertificate) {
    std::mt19937 rng(21);
    const auto inst = test::rigInstance(rng, 30, 20, 8);
    // No time limit: with one, whether the certificate arrives depends on the machine's speed (it did
    // not within 20 s under the sanitizers on a loaded machine); the test's own timeout bounds it.
    const auto result = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 6});
    ASSERT_EQ(result.curve.size(), 6u);
    for (std::size_t p = 0; p < result.curve.size(); ++p) {
        const Grouping& g = result.curve[p];
        EXPECT_TRUE(g.optimal);
        EXPECT_TRUE(test::isValidGrouping(g.groups, 30, static_cast<int>(p) + 1));
        EXPECT_LE(g.lowerBound, g.cost * (1 + 1e-12));
        EXPECT_NEAR(groupingCost(inst.shapes, inst.frequencies, inst.weights, g.groups), g.cost,
                    1e-9 * g.cost);
    }
}

TEST(Reduction, EvaluatedGroupingsEqualTheDirectSumAndNeverBeatTheOptimum) {
    // A given grouping (a standard phoneme -> viseme map) is costed through the Gram matrix as the
    // solvers cost theirs; it must equal the sum over the meshes (groupingCost) for random partitions,
    // never undercut the proved optimum, and reproduce it for the optimal groups.
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 6; ++trial) {
        const int n = 3 + trial;
        const auto inst = test::randomInstance(rng, n, 15, trial % 2 == 1);
        std::vector<std::vector<std::vector<int>>> groupings;
        for (int k = 0; k < 5; ++k) {
            const int p = 1 + static_cast<int>(rng() % static_cast<unsigned>(n));
            std::vector<std::vector<int>> groups(static_cast<std::size_t>(p));
            for (int i = 0; i < n; ++i) // the first p visemes open the groups, the rest land anywhere
                groups[static_cast<std::size_t>(i < p ? i
                                                      : static_cast<int>(rng() % static_cast<unsigned>(p)))]
                    .push_back(i);
            groupings.push_back(groups);
        }
        const auto result = reduce(inst, n);
        for (const auto& g : result.curve) groupings.push_back(g.groups);
        const auto costs = evaluateGroupings(inst.shapes, inst.frequencies, inst.weights, groupings);
        ASSERT_EQ(costs.size(), groupings.size());
        for (std::size_t k = 0; k < groupings.size(); ++k) {
            const double direct = groupingCost(inst.shapes, inst.frequencies, inst.weights, groupings[k]);
            EXPECT_NEAR(costs[k], direct, 1e-9 * (1 + direct)) << "trial " << trial << " grouping " << k;
            const auto& optimum = result.curve[groupings[k].size() - 1];
            EXPECT_GE(costs[k], optimum.cost - 1e-9 * (1 + optimum.cost)) << "trial " << trial;
        }
        for (std::size_t p = 0; p < result.curve.size(); ++p)
            EXPECT_NEAR(costs[5 + p], result.curve[p].cost, 1e-12 * (1 + result.curve[p].cost))
                << "the solver's own cost, p = " << p + 1;
    }
}

TEST(Reduction, EvaluatedGroupingsMustPartitionTheVisemes) {
    std::mt19937 rng(5);
    const auto inst = test::randomInstance(rng, 4, 6);
    const auto errorOf = [&](std::vector<std::vector<int>> groups) {
        try {
            evaluateGroupings(inst.shapes, inst.frequencies, inst.weights,
                              std::vector<std::vector<std::vector<int>>>{groups});
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(errorOf({{0, 1}, {2}}).find("leaves out viseme 3"), std::string::npos);
    EXPECT_NE(errorOf({{0, 1}, {1, 2, 3}}).find("viseme 1 is in two groups"), std::string::npos);
    EXPECT_NE(errorOf({{0, 1, 2, 3}, {}}).find("empty group"), std::string::npos);
    EXPECT_NE(errorOf({{0, 1, 2, 7}}).find("outside 0..3"), std::string::npos);
}
