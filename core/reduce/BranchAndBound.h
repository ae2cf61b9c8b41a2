#pragma once
// Certified optimum of the reduction for any n (up to 64 units) by repetitive branch and bound
// (Brusco 2006, "A repetitive branch-and-bound procedure for minimum within-cluster sums of squares
// partitioning"), on the Gram form of the objective (GroupCostModel).
//
// Units are placed one at a time in a fixed order into an existing group or a new one (a unit opens
// group k only after groups 0..k-1 exist: each partition is enumerated once). A partial placement of
// the first t units is pruned when
//   c(groups so far) + OPT(units t..n-1)  >=  best cost found,
// which is valid because the cost is superadditive: splitting a group never raises the cost, so the
// groups restricted to the last units cost at least their own optimum. The optima of the suffixes
// t..n-1 come from solving the suffix problems first, smallest to largest, each with the bounds of
// the smaller ones (the "repetitive" part). When the search is stopped early, the smallest bound of
// the unexplored subtrees is a valid lower bound on the optimum.
#include "core/reduce/UnitPartition.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <span>

namespace vl {

struct SearchLimits {
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    const std::atomic<bool>* cancelled = nullptr; // set by another thread to stop early
    // A work limit that, unlike the deadline, gives the same answer on a slow or loaded machine:
    // the searches sharing `work` stop once they have tried about `workBudget` groups together (a
    // node tries each open group and a new one: its time is about proportional to that count, where
    // a node count would charge a node of 11 open groups as one of 3).
    std::atomic<std::uint64_t>* work = nullptr;
    std::uint64_t workBudget = 0;
    // A stopped search's lower bound adds the exact optima of blocks of the units before its suffix
    // (subset DPs: milliseconds per p). Off when the caller discards a stopped search's bound anyway
    // (Auto's portfolio runs the DP next); the bound reported is then the suffix's alone, still valid.
    bool tightenStoppedBound = true;
    // Called once per `done` groups tried by one search.
    bool expired(std::uint64_t done) const {
        if (work && work->fetch_add(done, std::memory_order_relaxed) + done > workBudget) return true;
        return (cancelled && cancelled->load(std::memory_order_relaxed)) ||
               std::chrono::steady_clock::now() >= deadline;
    }
};

// The optimal partition of all units into exactly p groups with no conflicting pair in a group.
// `start` is a feasible partition into p groups (an upper bound) or empty. `done` (optional) is raised
// towards 1 as the suffix problems complete. Without a proof before the limits expire, the result has
// optimal = false, the best partition found and a valid lower bound. p must be in 1..model.size().
// `provenBound` (optional) is raised to a valid lower bound of this problem each time a suffix
// problem is solved (the suffix's optimum plus the block bound of the units before it).
UnitPartition branchAndBound(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                             const SearchLimits& limits = {}, std::atomic<double>* done = nullptr,
                             std::atomic<double>* provenBound = nullptr);

// The lower bound branchAndBound starts from, known before any search: the units in its placement
// order cut into small blocks, each solved exactly into p groups with the conflicts dropped.
double blockLowerBound(const GroupCostModel& model, int p);

} // namespace vl
