#pragma once
// Pricing for column generation on the set-partitioning LP (ColumnGeneration.h): the groups S of most
// negative reduced cost  r(S) = c(S) - pi(S) - mu  for the master's duals (pi per unit, mu for the
// count row), found without listing the 2^n groups, so that column generation takes every n up to 64.
//
// Exact pricing is a branch and bound over groups. A group S = I + J grown from members I (weighted
// mean m_I, weight F_I) costs, in the centre form of c = D - Q/F (GroupCostModel.h),
//   c(S) = c(I) + min_z [ F_I |z - m_I|^2 + sum_{u in J} (c_u + F_u |m_u - z|^2) ],
// m_u the mean of unit u and c_u its own spread. With r = |z - m_I| and |m_u - z| >= (d_u - r)+,
// d_u = |m_u - m_I|, every group grown from I by undecided units has reduced cost at least
//   c(I) - pi(I) - mu + min_r>=0 [ F_I r^2 + sum_u min(0, c_u - pi_u + F_u (d_u - r)+^2) ],
// a minimum over one variable, taken exactly (the sum is piecewise quadratic in r). It ignores how
// far the added units are from each other; a second bound counts those pairs (each at least as far as
// its units' nearest linked units, GroupPricing.cpp), and the larger of the two prunes. Groups grow only
// by units whose "balls" intersect those of every member (GroupPricing.cpp): in high dimensions, where
// the bound above is weak, that graph is sparse. The rest group of
// the rest-free model costs sum rest_a, linear: its bound is the sum of the negative rest_u - pi_u.
#include "core/reduce/BranchAndBound.h"
#include "core/reduce/GroupCostModel.h"

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace vl {

struct PricedGroup {
    UnitMask group = 0;
    double reducedCost = 0;
};

struct MasterDuals {
    std::span<const double> pi; // one per unit of the model
    double mu = 0;              // the row sum x_S = p
};

struct PricingLimits {
    double threshold = 0;               // groups with a reduced cost below this are returned
    std::size_t keep = 64;              // at most this many, the most negative
    std::uint64_t nodeLimit = 0;        // search nodes before stopping (0: none); the bound stays valid
    const SearchLimits* stop = nullptr; // its deadline and cancellation also stop the exact search
};

struct PricedGroups {
    // Reduced cost < threshold, most negative first (the minimum first when the search completes).
    // Groups that a member could leave without raising the reduced cost may be left out.
    std::vector<PricedGroup> groups;
    // No allowed group has a reduced cost below this; the exact minimum when `complete`.
    double minimumBound = -std::numeric_limits<double>::infinity();
    bool complete = false; // the search was not stopped by a limit
    std::uint64_t nodes = 0;
};

// r(S) for one group (GroupCostModel::cost, so it matches the master's column cost).
double reducedCost(const GroupCostModel& model, const MasterDuals& duals, UnitMask group);

// Exact pricing over every allowed group (no conflicting pair; the rest group only with restUnit).
PricedGroups priceGroupsExactly(const GroupCostModel& model, const MasterDuals& duals,
                                const PricingLimits& limits);

// Heuristic pricing: from every unit alone and from each of `seeds`, add or drop the unit that lowers
// the reduced cost most until none does. Milliseconds at 64 units; finds no proof (minimumBound unset).
PricedGroups priceGroupsByLocalSearch(const GroupCostModel& model, const MasterDuals& duals,
                                      const PricingLimits& limits, std::span<const UnitMask> seeds);

} // namespace vl
