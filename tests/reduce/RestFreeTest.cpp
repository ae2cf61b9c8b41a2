// The rest-free model (issue 29): every solver against the brute force over all assignments of the
// visemes to keys or the rest, with and without a rest viseme, with constraints; the keyed model
// unchanged when the rest is not free.
#include "BruteForce.h"
#include "RandomShapes.h"
#include "TestModels.h"

#include "core/common/Error.h"
#include "core/reduce/BranchAndBound.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/SubsetDp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <numeric>

using namespace vl;

namespace {

// A neutral near the shapes (random instances share a base mesh), so that resting is sometimes best.
std::vector<Vec3> neutralNear(const test::RandomInstance& inst, std::mt19937& rng) {
    std::uniform_real_distribution<double> jitter(-0.5, 0.5);
    std::vector<Vec3> neutral = inst.shapes.front();
    for (auto& v : neutral) v += Vec3(jitter(rng), jitter(rng), jitter(rng));
    return neutral;
}

// The optimum over every partition of the model's units into exactly p allowed groups (+inf: none).
double bruteForceModel(const GroupCostModel& model, int p) {
    const int n = model.size();
    std::vector<UnitMask> groups(static_cast<std::size_t>(p), 0);
    double best = std::numeric_limits<double>::infinity();
    std::function<void(int, int)> recurse = [&](int a, int used) {
        if (n - a < p - used) return;
        if (a == n) {
            if (std::all_of(groups.begin(), groups.end(), [&](UnitMask g) { return model.allowed(g); }))
                best = std::min(best, partitionCost(model, groups));
            return;
        }
        for (int g = 0; g <= used && g < p; ++g) {
            groups[static_cast<std::size_t>(g)] |= UnitMask{1} << a;
            recurse(a + 1, std::max(used, g + 1));
            groups[static_cast<std::size_t>(g)] &= ~(UnitMask{1} << a);
        }
    };
    recurse(0, 0);
    return best;
}

// Random instances with zero frequencies (units of weight 0), random constraints and a rest viseme whose
// own rest cost is not 0 (the neutral is another shape), or is 0 (it is the neutral).
struct ModelCase {
    test::RandomInstance inst;
    GroupCostModel model;
};
std::vector<ModelCase> randomRestFreeModels(std::mt19937& rng, int minN, int maxN, int trials) {
    std::vector<ModelCase> cases;
    for (int n = minN; n <= maxN; ++n)
        for (int trial = 0; trial < trials; ++trial) {
            auto inst = trial % 2 ? test::rigInstance(rng, n, 12, 4) : test::randomInstance(rng, n, 8, true);
            if (trial % 3 == 2) inst.frequencies[static_cast<std::size_t>(n - 1)] = 0;
            const int restViseme = static_cast<int>(rng() % static_cast<unsigned>(n));
            const std::vector<Vec3> neutral =
                trial % 4 == 3 ? inst.shapes[static_cast<std::size_t>(restViseme)] : neutralNear(inst, rng);
            const ReductionConstraints c =
                trial % 4 == 0 ? ReductionConstraints{} : test::randomConstraints(rng, n);
            if (auto model = test::restFreeModel(inst, c, restViseme, neutral))
                cases.push_back({inst, *model});
        }
    return cases;
}

ReductionResult solveRestFree(const test::RandomInstance& inst, int m, ReductionMethod method, RestPose rest,
                              const ReductionConstraints& constraints = {}) {
    rest.free = true;
    ReductionOptions options;
    options.method = method;
    return reduceVisemes({inst.shapes, inst.frequencies, inst.weights, m, constraints, rest}, options);
}

// `g` assigns every viseme to a key or the rest, with exactly p keys, the rest viseme resting.
void expectRestFreeGrouping(const Grouping& g, int n, int p, int restViseme) {
    ASSERT_EQ(static_cast<int>(g.groups.size()), p);
    const std::vector<int> groupOf = g.groupOf();
    ASSERT_EQ(static_cast<int>(groupOf.size()), n);
    for (const auto& group : g.groups) EXPECT_FALSE(group.empty());
    EXPECT_TRUE(std::is_sorted(g.rest.begin(), g.rest.end()));
    for (const int i : g.rest) EXPECT_EQ(groupOf[static_cast<std::size_t>(i)], kRestGroup);
    if (restViseme >= 0) {
        EXPECT_EQ(groupOf[static_cast<std::size_t>(restViseme)], kRestGroup);
    }
}

constexpr ReductionMethod kRestFreeMethods[] = {ReductionMethod::SubsetDp, ReductionMethod::BranchAndBound,
                                                ReductionMethod::ColumnGeneration, ReductionMethod::Auto};

// Every method and every p against the brute force on one instance.
void expectAgreement(const test::RandomInstance& inst, const RestPose& rest, std::span<const Vec3> neutral,
                     const ReductionConstraints& constraints = {}) {
    const int n = static_cast<int>(inst.shapes.size());
    const int keysPossible = n - (rest.viseme >= 0 ? 1 : 0);
    std::vector<std::optional<double>> reference;
    for (int p = 1; p <= keysPossible; ++p)
        reference.push_back(test::bruteForceRestFree(inst, p, rest.viseme, neutral, constraints));
    int m = keysPossible;
    while (m > 0 && !reference[static_cast<std::size_t>(m - 1)]) --m;
    if (m == 0) return; // the constraints allow no key count
    for (const ReductionMethod method : kRestFreeMethods) {
        SCOPED_TRACE(std::string("method ") + toString(method));
        const ReductionResult result = solveRestFree(inst, m, method, rest, constraints);
        EXPECT_TRUE(result.restFree);
        for (int p = 1; p <= m; ++p) {
            SCOPED_TRACE("p=" + std::to_string(p));
            const Grouping& g = result.curve[static_cast<std::size_t>(p - 1)];
            const auto& expected = reference[static_cast<std::size_t>(p - 1)];
            if (!expected) {
                EXPECT_FALSE(g.feasible());
                continue;
            }
            const double tolerance = 1e-9 * std::max(1.0, *expected);
            expectRestFreeGrouping(g, n, p, rest.viseme);
            EXPECT_TRUE(g.optimal);
            EXPECT_NEAR(g.cost, *expected, tolerance);
            EXPECT_NEAR(
                restFreeGroupingCost(inst.shapes, inst.frequencies, inst.weights, g.groups, g.rest, neutral),
                g.cost, tolerance);
            std::vector<int> block(static_cast<std::size_t>(n));
            const std::vector<int> groupOf = g.groupOf();
            for (int i = 0; i < n; ++i) // the rest as label p
                block[static_cast<std::size_t>(i)] = groupOf[static_cast<std::size_t>(i)] == kRestGroup
                                                         ? p
                                                         : groupOf[static_cast<std::size_t>(i)];
            EXPECT_TRUE(test::satisfies(block, constraints));
        }
    }
}

} // namespace

TEST(RestFree, AllSolversAgreeWithBruteForceWithARestViseme) {
    std::mt19937 rng(2929);
    for (int n = 2; n <= 9; ++n)
        for (int trial = 0; trial < 3; ++trial) {
            SCOPED_TRACE("n=" + std::to_string(n) + " trial=" + std::to_string(trial));
            auto inst =
                trial == 1 ? test::rigInstance(rng, n, 12, 4) : test::randomInstance(rng, n, 8, trial == 2);
            const int restViseme = static_cast<int>(rng() % static_cast<unsigned>(n));
            // The rest viseme is the neutral (no neutral given): it rests at cost 0.
            expectAgreement(inst, {false, restViseme, {}}, inst.shapes[static_cast<std::size_t>(restViseme)]);
        }
}

TEST(RestFree, AllSolversAgreeWithBruteForceWithAVirtualRest) {
    std::mt19937 rng(2930);
    for (int n = 1; n <= 9; ++n)
        for (int trial = 0; trial < 3; ++trial) {
            SCOPED_TRACE("n=" + std::to_string(n) + " trial=" + std::to_string(trial));
            auto inst =
                trial == 1 ? test::rigInstance(rng, n, 12, 4) : test::randomInstance(rng, n, 8, trial == 2);
            const std::vector<Vec3> neutral = neutralNear(inst, rng);
            expectAgreement(inst, {false, -1, neutral}, neutral);
        }
}

TEST(RestFree, ARestVisemeWithAnotherNeutralRestsAtItsOwnCost) {
    std::mt19937 rng(2931);
    for (int n = 3; n <= 8; ++n) {
        const auto inst = test::randomInstance(rng, n, 8);
        const std::vector<Vec3> neutral = neutralNear(inst, rng);
        expectAgreement(inst, {false, n - 1, neutral}, neutral);
    }
}

TEST(RestFree, ConstraintsHoldAndAgreeWithBruteForce) {
    std::mt19937 rng(2932);
    for (int n = 4; n <= 8; ++n)
        for (int trial = 0; trial < 4; ++trial) {
            SCOPED_TRACE("n=" + std::to_string(n) + " trial=" + std::to_string(trial));
            const auto inst = test::randomInstance(rng, n, 8);
            std::vector<int> order(static_cast<std::size_t>(n));
            std::iota(order.begin(), order.end(), 0);
            std::shuffle(order.begin(), order.end(), rng);
            ReductionConstraints c;
            c.pinned = {order[0]};
            c.apart = {{order[1], order[2]}};
            c.together = {{order[2], order[3]}};
            const int restViseme = trial % 2 ? -1 : order[static_cast<std::size_t>(trial % n)];
            const std::vector<Vec3> neutral =
                restViseme >= 0 ? inst.shapes[static_cast<std::size_t>(restViseme)] : neutralNear(inst, rng);
            expectAgreement(inst, {false, restViseme, restViseme >= 0 ? std::span<const Vec3>{} : neutral},
                            neutral, c);
        }
}

TEST(RestFree, BranchAndBoundWithoutAStartAgreesWithBruteForceOnTheModel) {
    // No heuristic start: the search's own bounds (the rest-free suffix problems with the rest group
    // open) must find and prove every optimum. Zero weights, constraints, rest costs of the rest unit
    // 0 and not 0.
    std::mt19937 rng(2937);
    int checked = 0;
    for (const ModelCase& c : randomRestFreeModels(rng, 2, 9, 6)) {
        const int units = c.model.size();
        for (int p = 1; p <= units; ++p) {
            SCOPED_TRACE("units=" + std::to_string(units) + " p=" + std::to_string(p));
            const double expected = bruteForceModel(c.model, p);
            const UnitPartition found = branchAndBound(c.model, p, {});
            EXPECT_TRUE(found.optimal);
            if (std::isinf(expected)) {
                EXPECT_TRUE(found.groups.empty());
                continue;
            }
            const double tolerance = 1e-9 * std::max(1.0, expected);
            EXPECT_NEAR(found.cost, expected, tolerance);
            EXPECT_NEAR(partitionCost(c.model, found.groups), found.cost, tolerance);
            ++checked;
        }
    }
    EXPECT_GT(checked, 150);
}

TEST(RestFree, BranchAndBoundAgreesWithTheDpOnLargerModels) {
    std::mt19937 rng(2938);
    for (const ModelCase& c : randomRestFreeModels(rng, 11, 15, 3)) {
        const int units = c.model.size();
        const int m = std::min(units, 9);
        const UnitCurve dp = solveSubsetDp(c.model, m);
        for (int p = 1; p <= m; ++p) {
            SCOPED_TRACE("units=" + std::to_string(units) + " p=" + std::to_string(p));
            const UnitPartition& expected = dp[static_cast<std::size_t>(p - 1)];
            const UnitPartition found = branchAndBound(c.model, p, {});
            EXPECT_TRUE(found.optimal);
            EXPECT_EQ(found.groups.empty(), expected.groups.empty());
            if (!expected.groups.empty()) {
                EXPECT_NEAR(found.cost, expected.cost, 1e-9 * std::max(1.0, expected.cost));
            }
        }
    }
}

TEST(RestFree, AStoppedSearchKeepsAValidBound) {
    // Stopped at once, the bound comes from a rest-free suffix problem plus blocks of the units before
    // it: never above the optimum, and the groups found never below it.
    std::mt19937 rng(2939);
    std::atomic<bool> cancelled{true};
    SearchLimits limits;
    limits.cancelled = &cancelled;
    for (const ModelCase& c : randomRestFreeModels(rng, 14, 16, 2)) {
        const int m = std::min(c.model.size(), 9);
        const UnitCurve dp = solveSubsetDp(c.model, m);
        for (int p = 2; p <= m; ++p) {
            SCOPED_TRACE("units=" + std::to_string(c.model.size()) + " p=" + std::to_string(p));
            const UnitPartition& expected = dp[static_cast<std::size_t>(p - 1)];
            if (expected.groups.empty()) continue;
            const UnitPartition stopped = branchAndBound(c.model, p, {}, limits);
            EXPECT_LE(stopped.lowerBound, expected.cost * (1 + 1e-9));
            if (!stopped.groups.empty()) {
                EXPECT_GE(stopped.cost, expected.cost * (1 - 1e-9));
            }
        }
    }
}

TEST(RestFree, LargerSetsAgreeBetweenSolvers) {
    // n = 10..14: no brute force, but the DP, branch and bound and the LP prove the same optimum.
    std::mt19937 rng(2933);
    for (int n = 10; n <= 14; n += 2) {
        const auto inst = test::rigInstance(rng, n, 16, 5);
        const std::vector<Vec3> neutral = neutralNear(inst, rng);
        for (const RestPose rest : {RestPose{false, 0, {}}, RestPose{false, -1, neutral}}) {
            const auto dp = solveRestFree(inst, n - 1, ReductionMethod::SubsetDp, rest);
            const auto bnb = solveRestFree(inst, n - 1, ReductionMethod::BranchAndBound, rest);
            const auto lp = solveRestFree(inst, n - 1, ReductionMethod::ColumnGeneration, rest);
            for (std::size_t e = 0; e < dp.curve.size(); ++e) {
                SCOPED_TRACE("n=" + std::to_string(n) + " p=" + std::to_string(e + 1));
                const double tolerance = 1e-9 * std::max(1.0, dp.curve[e].cost);
                EXPECT_NEAR(bnb.curve[e].cost, dp.curve[e].cost, tolerance);
                EXPECT_TRUE(bnb.curve[e].optimal);
                // The LP proves most p; where its relaxation is fractional its bound still holds.
                EXPECT_LE(lp.curve[e].lowerBound, dp.curve[e].cost + tolerance);
                EXPECT_GE(lp.curve[e].cost, dp.curve[e].cost - tolerance);
                if (lp.curve[e].optimal) {
                    EXPECT_NEAR(lp.curve[e].cost, dp.curve[e].cost, tolerance);
                }
            }
        }
    }
}

TEST(RestFree, NeverCostsMoreThanTheKeyedModelWithOneKeyMore) {
    // The keyed optimum with p + 1 groups is at most the rest-free one with p keys: the same groups
    // with the rest group keyed at its mean instead of the neutral cost no more.
    std::mt19937 rng(2934);
    const auto inst = test::randomInstance(rng, 8, 8);
    const auto free = solveRestFree(inst, 6, ReductionMethod::SubsetDp, {false, 0, {}});
    const auto keyed = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 7});
    for (std::size_t e = 0; e < free.curve.size(); ++e)
        EXPECT_LE(keyed.curve[e + 1].cost, free.curve[e].cost * (1 + 1e-12));
}

TEST(RestFree, TheKeyedModelIgnoresTheRestViseme) {
    std::mt19937 rng(2935);
    const auto inst = test::randomInstance(rng, 7, 8);
    const ReductionResult plain = reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 5});
    const ReductionResult marked =
        reduceVisemes({inst.shapes, inst.frequencies, inst.weights, 5, {}, RestPose{false, 2, {}}});
    EXPECT_EQ(plain, marked);
    EXPECT_FALSE(marked.restFree);
    for (const Grouping& g : marked.curve) EXPECT_TRUE(g.rest.empty());
}

TEST(RestFree, RejectsTooManyKeysAndAMissingNeutral) {
    std::mt19937 rng(2936);
    const auto inst = test::randomInstance(rng, 4, 6);
    // With a rest viseme, at most n - 1 visemes can hold keys.
    EXPECT_THROW(solveRestFree(inst, 4, ReductionMethod::Auto, {false, 0, {}}), InputError);
    EXPECT_THROW(solveRestFree(inst, 2, ReductionMethod::Auto, {false, -1, {}}), InputError);
    const std::vector<Vec3> shortNeutral(3);
    EXPECT_THROW(solveRestFree(inst, 2, ReductionMethod::Auto, {false, -1, shortNeutral}), InputError);
}
