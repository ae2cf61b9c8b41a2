#pragma once
// Good partitions fast, for the upper bounds of the exact solvers: frequency-weighted Ward
// agglomeration (one pass gives every p), then Hartigan moves (move one unit to another group while
// that lowers the exact cost) from Ward's partition and from k-means++ seeded restarts. Everything is
// in the Gram (kernel) form of GroupCostModel and respects its conflicts.
#include "core/reduce/GroupCostModel.h"

#include <cstdint>
#include <vector>

namespace vl {

struct HeuristicOptions {
    int restarts = 24;         // k-means++ restarts per p
    std::uint32_t seed = 2024; // fixed: the result is deterministic
};

// For each p = 1..m (entry p-1): the cheapest partition into exactly p groups found, or no groups
// when none was found (conflicts can make greedy merging fail). Partitions are unit masks.
std::vector<std::vector<UnitMask>> heuristicPartitions(const GroupCostModel& model, int m,
                                                       const HeuristicOptions& options = {});

// Improves `groups` in place by Hartigan moves (and pair swaps when no move helps); returns its cost.
double improveByMoves(const GroupCostModel& model, std::vector<UnitMask>& groups);

} // namespace vl
