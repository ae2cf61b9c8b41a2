#pragma once
// The smallest number of keys for which every viseme stays within a distance X of its own shape
// (`reduce --max-error-mm`): a grouping is allowed only when, for every viseme i and every vertex v
// that counts (weight > 0), |a_i(v) - B(v)| <= X, where B is the shape i is shown with: its key (the
// frequency-weighted mean of the key's members, the paper's eq. 19) or, in the rest-free model, the
// rest pose when i rests.
//
// The condition on a key is not pairwise (the mean moves with every member), so the search is exact
// by enumeration: visemes (units, after the designer's constraints) are placed one at a time into a
// key, the rest, or a new key, pruned by necessary pairwise conditions — two visemes within X of one
// mean are within 2X of each other at every vertex, and a viseme rests only when it moves no vertex
// more than X — and each key of a complete placement is checked exactly (memoised per key). The
// first p (from a lower bound up) with an allowed placement is the answer; it is certified when every
// smaller p was refuted by a complete search (not stopped by `nodeBudget`).
#include "core/reduce/ReductionConstraints.h"
#include "core/reduce/ShapeView.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl {

struct MaxErrorProblem {
    ShapeView shapes;                    // n shapes
    std::span<const Vec3> rest;          // the rest pose (neutral); empty: no viseme may rest
    std::span<const double> frequencies; // n values >= 0
    std::span<const double> weights;     // per vertex; only vertices with weight > 0 count
    double maxError = 0;                 // X, in model units, >= 0
    ConstraintUnits units;               // the designer's constraints (constraintUnits)
    std::vector<int> mustRest;           // visemes that rest by definition (the rest viseme)
    std::vector<int> mustKey;            // visemes that may not rest (pinned as their own key)
    std::uint64_t nodeBudget = 50'000'000;
};

struct MaxErrorResult {
    int keys = 0;             // the smallest p >= 1 found such that an allowed grouping has at most p keys
    std::vector<int> groupOf; // per viseme: its key 0..keys-1, or -1 when it rests
    bool certified = false;   // no grouping with fewer keys is allowed (proven)
    int provenLowerBound = 0; // every grouping with fewer keys was refuted
    std::uint64_t nodes = 0;  // placements visited
};

// Throws InputError when X is negative or not finite, sizes disagree, or a viseme that must rest
// moves more than X (nothing can satisfy the bound).
MaxErrorResult smallestKeysWithin(const MaxErrorProblem& problem);

// Whether the grouping keeps every viseme within X (groupOf as in MaxErrorResult): the exact check.
bool withinMaxError(const MaxErrorProblem& problem, const std::vector<int>& groupOf);

// Pairs of visemes that can never share a key under the bound (|a_i - a_j| > 2X at some vertex),
// for the reduction's 'apart' constraints: a relaxation of the bound the solvers honour exactly.
std::vector<std::pair<int, int>> maxErrorApartPairs(const MaxErrorProblem& problem);

} // namespace vl
