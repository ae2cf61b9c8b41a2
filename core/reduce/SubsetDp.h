#pragma once
// Exact reduction by the paper's subset dynamic programme (eq. 23) on units, for every p = 1..m in
// one run. Fastest for small n (time O(m 3^(n-1)), memory O(2^n + m 2^(n-1))); BranchAndBound.h
// takes over above that.
#include "core/reduce/UnitPartition.h"

#include <functional>
#include <vector>

namespace vl {

// Largest number of units the DP accepts (memory: every layer is kept, ~200 MB at m = 10).
constexpr int kMaxSubsetDpUnits = 22;

// For each p = 1..m: the optimal partition into p groups respecting the conflicts (optimal = true,
// lowerBound = cost), or no groups when none exists. `progress` gets values in [0,1] from the calling
// thread. Requires model.size() <= kMaxSubsetDpUnits and 1 <= m <= model.size().
// c(S) for all 2^n sets S of units (bit a = unit a), +inf for a set holding a conflicting pair, in
// O(n 2^n). Requires model.size() <= kMaxSubsetDpUnits + 4 (memory: 8 * 2^n bytes).
std::vector<double> allSubsetCosts(const GroupCostModel& model);

UnitCurve solveSubsetDp(const GroupCostModel& model, int m, const std::function<void(double)>& progress = {});

} // namespace vl
