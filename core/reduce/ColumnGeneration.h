#pragma once
// Exact reduction by the set-partitioning LP (Aloise, Hansen & Liberti 2012): a partition into p
// groups is a choice of p columns (groups) covering every unit once, and the LP relaxation over all
// 2^n groups is solved by column generation. On viseme sets, structured or not, its optimum is
// usually integral, which proves the partition optimal. Pricing enumerates every group, so the
// reduced costs are exact and the bound holds whatever the LP solver's tolerances:
//   LB = sum_a pi_a + p mu + p min(0, min_S (c(S) - pi(S) - mu))
// for any duals (pi, mu), since every partition is p columns of reduced cost >= that minimum.
#include "core/reduce/BranchAndBound.h"
#include "core/reduce/UnitPartition.h"

#include <span>
#include <vector>

namespace vl {

// Largest number of units it accepts: pricing scans all 2^n group costs (512 MB at 26 units).
constexpr int kMaxColumnGenerationUnits = 26;

// The optimal partition of all units into p groups when the LP proves it (optimal = true, lowerBound =
// cost); otherwise the best partition seen (the LP's integral rounding or `start`) with lowerBound the
// LP bound of the last round. `groupCosts` holds c(S) for all 2^n sets (+inf for a conflicting one:
// allSubsetCosts in SubsetDp.h); `start` is a feasible partition into p groups (the LP's first
// columns; required). Stops at the limits' deadline or cancellation with the bound reached so far.
UnitPartition solveByColumnGeneration(const GroupCostModel& model, std::span<const double> groupCosts, int p,
                                      std::span<const UnitMask> start, const SearchLimits& limits);

} // namespace vl
