#pragma once
// What a solver returns for one number of groups p: the best partition of the units it found and
// what it proved about the optimum.
#include "core/reduce/GroupCostModel.h"

#include <limits>
#include <vector>

namespace vl {

struct UnitPartition {
    std::vector<UnitMask> groups;                          // p groups of units; empty when none was found
    double cost = std::numeric_limits<double>::infinity(); // cost of `groups`
    double lowerBound = std::numeric_limits<double>::infinity(); // no feasible partition costs less
    bool optimal = false; // `groups` is proven optimal (or proven infeasible when empty)
};

// Per p = 1..m (entry p-1).
using UnitCurve = std::vector<UnitPartition>;

} // namespace vl
