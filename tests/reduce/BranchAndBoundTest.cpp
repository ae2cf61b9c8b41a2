// Branch and bound against the subset DP and brute force, its certificates, and its time limit.
#include "BruteForce.h"
#include "RandomShapes.h"
#include "TestModels.h"

#include "core/reduce/BranchAndBound.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/GroupCostModel.h"
#include "core/reduce/ReductionHeuristics.h"
#include "core/reduce/SubsetDp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

using namespace vl;

namespace {

ReductionResult solve(const test::RandomInstance& inst, int m, ReductionMethod method,
                      const ReductionConstraints& constraints = {}) {
    ReductionOptions options;
    options.method = method;
    return reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m, constraints}, options);
}

void expectCertificate(const Grouping& g) {
    EXPECT_LE(g.lowerBound, g.cost * (1 + 1e-12) + 1e-300);
    EXPECT_GE(g.lowerBound, 0.0);
    if (g.optimal) {
        EXPECT_EQ(g.gap(), 0.0);
        EXPECT_EQ(g.lowerBound, g.cost);
    }
}

} // namespace

TEST(BranchAndBound, AgreesWithDpAndBruteForceOnRandomInstances) {
    std::mt19937 rng(4242);
    for (int n = 1; n <= 10; ++n) {
        for (int trial = 0; trial < (n <= 7 ? 4 : 2); ++trial) {
            auto inst =
                trial % 2 ? test::rigInstance(rng, n, 15, 4) : test::randomInstance(rng, n, 10, trial == 2);
            if (trial == 3 && n >= 3) inst.shapes[2] = inst.shapes[0]; // duplicates tie many groupings
            const auto bnb = solve(inst, n, ReductionMethod::BranchAndBound);
            const auto dp = solve(inst, n, ReductionMethod::SubsetDp);
            EXPECT_EQ(bnb.method, ReductionMethod::BranchAndBound);
            EXPECT_EQ(dp.method, ReductionMethod::SubsetDp);
            for (int m = 1; m <= n; ++m) {
                const double reference = *test::bruteForceBest(inst, m);
                const double tolerance = 1e-9 * std::max(1.0, reference);
                for (const ReductionResult* result : {&bnb, &dp}) {
                    const Grouping& g = result->curve[static_cast<std::size_t>(m - 1)];
                    SCOPED_TRACE("n=" + std::to_string(n) + " m=" + std::to_string(m) + " " +
                                 toString(result->method));
                    EXPECT_TRUE(test::isValidGrouping(g.groups, n, m));
                    EXPECT_TRUE(g.optimal);
                    EXPECT_NEAR(g.cost, reference, tolerance);
                    EXPECT_NEAR(groupingCost(inst.shapes, inst.frequencies, inst.weights, g.groups), g.cost,
                                tolerance);
                    expectCertificate(g);
                }
            }
        }
    }
}

TEST(BranchAndBound, AgreesWithDpOnLargerSets) {
    std::mt19937 rng(77);
    for (const int n : {12, 14, 17}) {
        for (const bool rig : {false, true}) {
            if (n == 17 && !rig) continue; // structureless sets of this size are the DP's (seconds for B&B)
            const auto inst =
                rig ? test::rigInstance(rng, n, 60, 6) : test::randomInstance(rng, n, 30, n == 14);
            const int m = n / 2;
            const auto bnb = solve(inst, m, ReductionMethod::BranchAndBound);
            const auto dp = solve(inst, m, ReductionMethod::SubsetDp);
            for (int p = 1; p <= m; ++p) {
                const Grouping& a = bnb.curve[static_cast<std::size_t>(p - 1)];
                const Grouping& b = dp.curve[static_cast<std::size_t>(p - 1)];
                ASSERT_TRUE(a.optimal) << "n=" << n << " p=" << p;
                EXPECT_NEAR(a.cost, b.cost, 1e-9 * std::max(1.0, b.cost)) << "n=" << n << " p=" << p;
                EXPECT_TRUE(test::isValidGrouping(a.groups, n, p));
            }
        }
    }
}

TEST(BranchAndBound, TimeLimitReturnsAValidGroupingWithAGap) {
    // About equally distant shapes: the hardest case for the bounds, far from finishing in 0.2 s.
    std::mt19937 rng(5);
    const auto inst = test::randomInstance(rng, 36, 40);
    ReductionOptions options;
    options.method = ReductionMethod::BranchAndBound;
    options.timeLimitSeconds = 0.2;
    const int m = 12;
    const auto result = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m}, options);
    ASSERT_EQ(result.curve.size(), static_cast<std::size_t>(m));
    const Grouping& best = result.best();
    EXPECT_TRUE(test::isValidGrouping(best.groups, 36, m));
    EXPECT_FALSE(best.optimal);
    EXPECT_GT(best.gap(), 0.0);
    EXPECT_LT(best.gap(), 1.0);
    EXPECT_GT(best.lowerBound, 0.0);
    for (const auto& g : result.curve) expectCertificate(g);
    EXPECT_NEAR(groupingCost(inst.shapes, inst.frequencies, inst.weights, best.groups), best.cost,
                1e-9 * best.cost);
}

TEST(BranchAndBound, CancelledSearchStillReturnsAValidGrouping) {
    std::mt19937 rng(6);
    const auto inst = test::randomInstance(rng, 30, 20);
    std::atomic<bool> cancelled{true};
    ReductionOptions options;
    options.method = ReductionMethod::BranchAndBound;
    options.cancelled = &cancelled;
    const auto result = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 8}, options);
    EXPECT_TRUE(test::isValidGrouping(result.best().groups, 30, 8));
    for (const auto& g : result.curve) expectCertificate(g);
}

TEST(BranchAndBound, AThrowingProgressCallbackStopsTheSearchAtOnce) {
    // The editor cancels a reduction by throwing from the progress callback: the searches must stop
    // then, not run on to their time limit (120 s here) while the editor waits for the worker. The
    // caller's flag set while a progress callback is given stops them too. The elapsed-time bounds
    // only tell "stopped" from "ran to the limit" (half the limit: the sanitizer build on a loaded
    // machine took 6 s where the release build takes well under 1 s).
    std::mt19937 rng(5);
    const auto inst = test::randomInstance(rng, 36, 40); // far from finishing in 20 s
    ReductionOptions options;
    options.method = ReductionMethod::BranchAndBound;
    options.timeLimitSeconds = 120;
    struct Cancelled {};
    int calls = 0;
    auto start = std::chrono::steady_clock::now();
    EXPECT_THROW(reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 12}, options,
                               [&](double) {
                                   if (++calls == 3) throw Cancelled{};
                               }),
                 Cancelled);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);

    std::atomic<bool> cancelled{false};
    options.cancelled = &cancelled;
    calls = 0;
    start = std::chrono::steady_clock::now();
    const auto result =
        reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 12}, options, [&](double) {
            if (++calls == 3) cancelled = true;
        });
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
    EXPECT_TRUE(test::isValidGrouping(result.best().groups, 36, 12));
    EXPECT_FALSE(result.best().optimal);
}

TEST(BranchAndBound, AStoppedSearchBoundsTheUnitsBeforeItsSuffixByBlocks) {
    // Stopped at once, the search has proved a bound only for a short suffix of the placement order;
    // the units before it add the DP optima of blocks of them. The bound must stay valid (never above
    // the DP's optimum) and be a real share of it, on random sets and every p.
    std::mt19937 rng(11);
    for (int trial = 0; trial < 3; ++trial) {
        const auto inst = trial == 0 ? test::randomInstance(rng, 16, 30) : test::rigInstance(rng, 16, 60, 5);
        const int m = 8;
        ReductionOptions dp;
        dp.method = ReductionMethod::SubsetDp;
        const auto exact = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m}, dp);
        std::atomic<bool> cancelled{true};
        ReductionOptions stopped;
        stopped.method = ReductionMethod::BranchAndBound;
        stopped.cancelled = &cancelled;
        const auto result = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m}, stopped);
        for (int p = 2; p <= m; ++p) {
            const Grouping& g = result.curve[static_cast<std::size_t>(p - 1)];
            const double optimum = exact.curve[static_cast<std::size_t>(p - 1)].cost;
            EXPECT_LE(g.lowerBound, optimum * (1 + 1e-9)) << "trial " << trial << " p = " << p;
            EXPECT_GE(g.cost, optimum * (1 - 1e-9));
            EXPECT_GT(g.lowerBound, 0.25 * optimum)
                << "trial " << trial << " p = " << p << " gap " << g.gap();
        }
    }
}

TEST(BranchAndBound, ProvesStructuredSetsBeyondTheDp) {
    std::mt19937 rng(8);
    const auto inst = test::rigInstance(rng, 26, 80, 8);
    const auto result = solve(inst, 8, ReductionMethod::BranchAndBound);
    for (std::size_t p = 0; p < result.curve.size(); ++p) {
        EXPECT_TRUE(result.curve[p].optimal) << "p=" << p + 1;
        EXPECT_TRUE(test::isValidGrouping(result.curve[p].groups, 26, static_cast<int>(p) + 1));
        if (p > 0) {
            EXPECT_LE(result.curve[p].cost, result.curve[p - 1].cost * (1 + 1e-12));
        }
    }
}

TEST(BranchAndBound, AutoPicksTheDpForSmallSetsAndProvesLargerOnes) {
    std::mt19937 rng(9);
    const auto small = test::randomInstance(rng, 8, 10);
    EXPECT_EQ(reduceVisemes({small.shapes, small.frequencies, small.weights, 4}).method,
              ReductionMethod::SubsetDp);
    const auto large = test::rigInstance(rng, 24, 40, 6);
    const auto result = reduceVisemes({large.shapes, large.frequencies, large.weights, 6});
    EXPECT_EQ(result.method, ReductionMethod::BranchAndBound);
    EXPECT_TRUE(result.best().optimal);
}

TEST(BranchAndBound, AutoInTheDpRangeTriesBranchAndBoundFirstAndFallsBackToTheDp) {
    // n = 16: a set with structure (a rig's mouth shapes) is proved by branch and bound within its
    // share; a structureless one (random shapes) needs ~30x that share and goes to the DP. The share
    // is counted in search nodes, so both choices are the same on any machine and under sanitizers.
    std::mt19937 rng(21);
    const auto rig = test::rigInstance(rng, 16, 40, 5);
    const auto proved = reduceVisemes({rig.shapes, rig.frequencies, rig.weights, 10});
    EXPECT_EQ(proved.method, ReductionMethod::BranchAndBound);
    const auto random = test::randomInstance(rng, 16, 40);
    const auto fallback = reduceVisemes({random.shapes, random.frequencies, random.weights, 10});
    EXPECT_EQ(fallback.method, ReductionMethod::SubsetDp);
    for (const auto* result : {&proved, &fallback})
        for (const auto& grouping : result->curve) EXPECT_TRUE(grouping.optimal);
    // Whichever solver ran, the optimum is the DP's.
    const auto dp =
        reduceVisemes({rig.shapes, rig.frequencies, rig.weights, 10}, {ReductionMethod::SubsetDp});
    for (std::size_t p = 0; p < dp.curve.size(); ++p)
        EXPECT_NEAR(proved.curve[p].cost, dp.curve[p].cost, 1e-9 * (1 + dp.curve[p].cost)) << p;
}

TEST(ReductionHeuristics, PartitionsAreValidAndNeverBelowTheOptimum) {
    std::mt19937 rng(10);
    for (int trial = 0; trial < 6; ++trial) {
        const int n = 6 + trial;
        const auto inst = test::randomInstance(rng, n, 12, trial % 2 == 1);
        ReductionConstraints constraints;
        constraints.apart = {{0, 1}, {1, 2}};
        const ConstraintUnits units = constraintUnits(constraints, n);
        const GroupCostModel model = makeGroupCostModel(
            centredGram(inst.shapes, inst.frequencies, inst.weights), inst.frequencies, units);
        const auto partitions = heuristicPartitions(model, n);
        const auto exact = solve(inst, n, ReductionMethod::SubsetDp, constraints);
        for (int p = 2; p <= n; ++p) {
            const auto& groups = partitions[static_cast<std::size_t>(p - 1)];
            ASSERT_EQ(static_cast<int>(groups.size()), p);
            UnitMask all = 0;
            for (const UnitMask g : groups) {
                EXPECT_NE(g, 0u);
                EXPECT_EQ(all & g, 0u);
                EXPECT_TRUE(model.allowed(g));
                all |= g;
            }
            EXPECT_EQ(all, (UnitMask{1} << n) - 1);
            EXPECT_GE(partitionCost(model, groups),
                      exact.curve[static_cast<std::size_t>(p - 1)].cost * (1 - 1e-12));
        }
    }
}

TEST(BranchAndBound, TheWatchedBoundOnlyRisesStaysBelowTheOptimumAndEndsAtTheResult) {
    // The editor's progress bar of the bound: sampled while the search runs, the watched lower bound
    // never decreases and never passes the optimum (the DP's, on sets it still solves); the best found
    // never increases and ends as the result's cost, the bound as its proven bound.
    std::mt19937 rng(17);
    for (int trial = 0; trial < 3; ++trial) {
        const auto inst = trial == 0 ? test::randomInstance(rng, 18, 30) : test::rigInstance(rng, 18, 60, 5);
        const int m = 6 + trial;
        ReductionOptions dp;
        dp.method = ReductionMethod::SubsetDp;
        const double optimum =
            reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m}, dp).best().cost;
        BoundWatch watch(m);
        ReductionOptions options;
        options.method = ReductionMethod::BranchAndBound;
        options.watch = &watch;
        std::vector<std::pair<double, double>> samples;
        const auto result =
            reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m}, options, [&](double) {
                samples.emplace_back(watch.lowerBound.load(), watch.bestFound.load());
            });
        samples.emplace_back(watch.lowerBound.load(), watch.bestFound.load());
        const double tolerance = 1e-9 * optimum;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            EXPECT_LE(samples[i].first, optimum + tolerance) << "sample " << i;
            EXPECT_GE(samples[i].second, optimum - tolerance) << "sample " << i;
            if (i > 0) {
                EXPECT_GE(samples[i].first, samples[i - 1].first) << "sample " << i;
                EXPECT_LE(samples[i].second, samples[i - 1].second) << "sample " << i;
            }
        }
        EXPECT_TRUE(result.best().optimal);
        EXPECT_EQ(watch.bestFound.load(), result.best().cost);
        EXPECT_EQ(watch.lowerBound.load(), result.best().cost);
    }
}

TEST(BranchAndBound, AStopRequestKeepsTheBestGroupingsWithTheirBounds) {
    // The editor's Cancel on a large set: the flag set while the search runs (with a progress
    // callback) ends it with valid groupings and certificates for every p, not an exception.
    std::mt19937 rng(23);
    const auto inst = test::randomInstance(rng, 34, 30);
    std::atomic<bool> stop{false};
    BoundWatch watch(10);
    ReductionOptions options;
    options.method = ReductionMethod::BranchAndBound;
    options.timeLimitSeconds = 120;
    options.cancelled = &stop;
    options.watch = &watch;
    int calls = 0;
    const auto result =
        reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 10}, options, [&](double) {
            if (++calls == 4) stop = true;
        });
    EXPECT_TRUE(test::isValidGrouping(result.best().groups, 34, 10));
    for (const auto& g : result.curve) expectCertificate(g);
    EXPECT_EQ(watch.bestFound.load(), result.best().cost);
    EXPECT_LE(watch.lowerBound.load(), result.best().cost);
}

TEST(BranchAndBound, AWorkBudgetStopsTheSearchNearItWithValidBounds) {
    // Auto's share is counted in groups tried (each open group and a new one per node): the searches
    // sharing the counter stop once it passes the budget (each thread adds its count every 1024 groups,
    // so it overshoots by at most that per thread), and a stopped search's bounds stay valid against
    // the DP, in both models.
    std::mt19937 rng(12);
    const int n = 18, m = 8;
    const auto inst = test::randomInstance(rng, n, 20);
    const GroupCostModel keyed = makeGroupCostModel(centredGram(inst.shapes, inst.frequencies, inst.weights),
                                                    inst.frequencies, constraintUnits({}, n));
    const GroupCostModel restFree = *test::restFreeModel(inst, {}, 0, inst.shapes.front());
    constexpr std::uint64_t kBudget = 20'000;
    const auto threads = static_cast<std::uint64_t>(std::max(1u, std::thread::hardware_concurrency()));
    for (const GroupCostModel* model : {&keyed, &restFree}) {
        const UnitCurve exact = solveSubsetDp(*model, m);
        int stopped = 0;
        for (int p = 2; p <= m; ++p) {
            std::atomic<std::uint64_t> work{0};
            SearchLimits limits;
            limits.work = &work;
            limits.workBudget = kBudget;
            const UnitPartition found = branchAndBound(*model, p, {}, limits);
            const double optimum = exact[static_cast<std::size_t>(p - 1)].cost;
            EXPECT_LE(work.load(), kBudget + threads * (1024 + kMaxReductionVisemes + 1)) << "p = " << p;
            EXPECT_GE(found.cost, optimum * (1 - 1e-9)) << "p = " << p;
            EXPECT_LE(found.lowerBound, optimum * (1 + 1e-9)) << "p = " << p;
            if (!found.optimal)
                ++stopped;
            else
                EXPECT_NEAR(found.cost, optimum, 1e-9 * optimum) << "p = " << p;
        }
        EXPECT_GT(stopped, 0) << "the budget never stopped a search: the test proves nothing";
    }
}
