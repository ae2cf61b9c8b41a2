// Pricing for column generation against the brute force over every group: the exact search's minimum
// and negative groups, a stopped search's bound, the local search's groups. Random and
// rig-like shapes, zero frequencies, conflicts, the rest-free model; duals drawn at the cost's scale.
#include "RandomShapes.h"
#include "TestModels.h"

#include "core/reduce/GroupPricing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace vl;

namespace {

struct PricingCase {
    GroupCostModel model;
    std::vector<double> pi;
    double mu = 0;
};

// Every allowed group (the rest unit only in the rest group) with its reduced cost, most negative first.
std::vector<PricedGroup> allGroups(const PricingCase& c) {
    const int n = c.model.size();
    std::vector<PricedGroup> out;
    for (UnitMask s = 1; s < (UnitMask{1} << n); ++s)
        if (c.model.allowed(s)) out.push_back({s, reducedCost(c.model, {c.pi, c.mu}, s)});
    std::sort(out.begin(), out.end(),
              [](const PricedGroup& a, const PricedGroup& b) { return a.reducedCost < b.reducedCost; });
    return out;
}

std::vector<PricingCase> randomCases(std::mt19937& rng, int count) {
    std::vector<PricingCase> cases;
    std::uniform_real_distribution<double> unit(0, 1);
    for (int k = 0; k < count; ++k) {
        const int n = 4 + k % 9;
        const int kind = k % 4;
        test::RandomInstance inst =
            kind == 1 ? test::rigInstance(rng, n, 10, 3) : test::randomInstance(rng, n, 8, kind == 2);
        ReductionConstraints constraints;
        if (kind == 3) constraints.apart = {{0, n - 1}};
        std::optional<GroupCostModel> model;
        if (k % 3 == 0) {
            model = test::restFreeModel(inst, constraints, 0, inst.shapes.front());
        } else {
            model = makeGroupCostModel(centredGram(inst.shapes, inst.frequencies, inst.weights),
                                       inst.frequencies, constraintUnits(constraints, n));
        }
        if (!model) continue;
        PricingCase c{*model, {}, 0};
        // Duals about the size of a unit's share of the cost, so that some groups price negative.
        const double share = model->scale / model->size();
        for (int a = 0; a < model->size(); ++a) c.pi.push_back(share * (2.5 * unit(rng) - 0.5));
        c.mu = -share * unit(rng);
        cases.push_back(std::move(c));
    }
    return cases;
}

TEST(GroupPricing, ExactSearchFindsTheMinimumAndNegativeGroups) {
    std::mt19937 rng(31);
    int withColumns = 0;
    for (const PricingCase& c : randomCases(rng, 160)) {
        const std::vector<PricedGroup> all = allGroups(c);
        const double tol = 1e-9 * c.model.scale + 1e-300;
        PricingLimits limits;
        limits.threshold = 0;
        limits.keep = 5;
        const PricedGroups priced = priceGroupsExactly(c.model, {c.pi, c.mu}, limits);
        ASSERT_TRUE(priced.complete);
        EXPECT_NEAR(priced.minimumBound, std::min(all.front().reducedCost, priced.minimumBound), tol);
        EXPECT_LE(priced.minimumBound, all.front().reducedCost + tol);
        // The most negative group comes first; the others are negative too (groups that a member can
        // leave without raising the reduced cost are skipped, so they need not be the next ranks).
        if (all.front().reducedCost < -tol) {
            ASSERT_FALSE(priced.groups.empty());
            EXPECT_NEAR(priced.groups.front().reducedCost, all.front().reducedCost, tol);
        }
        for (const PricedGroup& g : priced.groups) {
            EXPECT_TRUE(c.model.allowed(g.group));
            EXPECT_LT(g.reducedCost, 0.0);
            EXPECT_NEAR(g.reducedCost, reducedCost(c.model, {c.pi, c.mu}, g.group), tol);
        }
        if (all.front().reducedCost < -tol) {
            ++withColumns;
            EXPECT_NEAR(priced.minimumBound, all.front().reducedCost, tol);
        }
    }
    EXPECT_GT(withColumns, 100); // the duals make most cases price something
}

TEST(GroupPricing, AStoppedSearchKeepsAValidBound) {
    std::mt19937 rng(8);
    int stopped = 0;
    for (const PricingCase& c : randomCases(rng, 60)) {
        PricingLimits limits;
        limits.nodeLimit = 3;
        const PricedGroups priced = priceGroupsExactly(c.model, {c.pi, c.mu}, limits);
        stopped += priced.complete ? 0 : 1;
        EXPECT_LE(priced.minimumBound, allGroups(c).front().reducedCost + 1e-9 * c.model.scale);
    }
    EXPECT_GT(stopped, 10);
}

TEST(GroupPricing, LocalSearchReturnsAllowedNegativeGroups) {
    std::mt19937 rng(12);
    int found = 0, cases = 0;
    for (const PricingCase& c : randomCases(rng, 120)) {
        const std::vector<PricedGroup> all = allGroups(c);
        PricingLimits limits;
        const PricedGroups priced = priceGroupsByLocalSearch(c.model, {c.pi, c.mu}, limits, {});
        for (const PricedGroup& g : priced.groups) {
            EXPECT_TRUE(c.model.allowed(g.group));
            EXPECT_LT(g.reducedCost, 0.0);
            EXPECT_EQ(g.reducedCost, reducedCost(c.model, {c.pi, c.mu}, g.group));
        }
        if (all.front().reducedCost < -1e-9 * c.model.scale) {
            ++cases;
            found += priced.groups.empty() ? 0 : 1;
        }
    }
    // A heuristic: it need not find a column every time, but it must usually.
    EXPECT_GT(found, cases * 9 / 10) << found << " of " << cases;
}

} // namespace
