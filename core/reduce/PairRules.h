#pragma once
// Ryan & Foster's branching rules for branch and price on the set-partitioning LP (ColumnGeneration.h):
// at a node, some pairs of units must share a group and some must not. A fractional LP optimum always
// has a pair (a, b) whose groups' values sum strictly between 0 and 1; branching on "together" or
// "apart" cuts it off in both children, and every partition satisfies one of the two.
#include "core/reduce/GroupCostModel.h"

#include <utility>
#include <vector>

namespace vl {

struct PairRules {
    std::vector<std::pair<int, int>> together, apart;

    // The group obeys every rule of the node.
    bool admits(UnitMask group) const;
};

// The pricing model of a node: units that must share a group merged into atoms (their sums added,
// GroupCostModel.h), apart pairs added to the atoms' conflicts.
struct AtomModel {
    GroupCostModel atoms;
    std::vector<UnitMask> members; // the units of each atom
    bool feasible = true;          // false: a rule joins two conflicting units, no group obeys the node

    UnitMask unitsOf(UnitMask atomGroup) const;
    UnitMask atomsOf(UnitMask unitGroup) const; // for a group the rules admit
};

AtomModel atomModel(const GroupCostModel& model, const PairRules& rules);

} // namespace vl
