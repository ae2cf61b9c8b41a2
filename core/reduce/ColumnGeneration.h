#pragma once
// Exact reduction by the set-partitioning LP (Aloise, Hansen & Liberti 2012): a partition into p
// groups is a choice of p columns (groups) covering every unit once, and the LP relaxation over all
// 2^n groups is solved by column generation. On viseme sets, structured or not, its optimum is
// usually integral, which proves the partition optimal; when it is not, branch and price (Ryan &
// Foster's pair branching, PairRules.h) closes the gap. Pricing (GroupPricing.h) finds columns by a
// local search and, when that finds none, by an exact branch and bound over groups whose minimum
// gives a bound that holds whatever the LP solver's tolerances:
//   LB = sum_a pi_a + p mu + p min(0, min_S (c(S) - pi(S) - mu))
// for any duals (pi, mu), since every partition is p columns of reduced cost >= that minimum.
#include "core/reduce/BranchAndBound.h"
#include "core/reduce/UnitPartition.h"

#include <span>
#include <vector>

namespace vl {

// Columns worth keeping from one p to the next (a partition into p groups shares most of its groups
// with the optimum for p + 1).
using ColumnPool = std::vector<UnitMask>;

// The optimal partition of all units into p groups when the LP proves it (optimal = true, lowerBound =
// cost); otherwise the best partition seen (the LP's integral rounding or `start`) with lowerBound the
// best LP bound proven. `start` is a feasible partition into p groups (the LP's first columns;
// required). `pool` (optional) adds its columns to the first ones and receives the columns generated.
// Stops at the limits' deadline or cancellation with the bound reached so far.
// What a run did (optional): nodes of branch and price (1: the root LP was enough) and LP rounds.
struct ColumnGenerationStats {
    int nodes = 0;
    int rounds = 0;
};

UnitPartition solveByColumnGeneration(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                                      const SearchLimits& limits, ColumnPool* pool = nullptr,
                                      ColumnGenerationStats* stats = nullptr);

} // namespace vl
