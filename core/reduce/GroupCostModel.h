#pragma once
// The reduction objective on units (visemes, or visemes the constraints keep together), shared by
// every solver.
//
// With B of a group its frequency-weighted mean (the paper's eq. 19), the cost of a group S in eq. (4)
//   c(S) = sum_{i in S} f_i rho(A_i, B_S) = D(S) - Q(S) / F(S),
//   F(S) = sum f_i,  D(S) = sum f_i G_ii,  Q(S) = sum_{i,j in S} f_i f_j G_ij,
// needs the shapes only through the weighted Gram matrix G_ij = sum_k w_k <a_ik, a_jk>: the problem is
// weighted minimum-sum-of-squares clustering of n points. A unit a of several visemes is summarised by
// F_a, D_a and H_ab = sum_{i in a, j in b} f_i f_j G_ij, so c(S) for a set of units has the same form.
// A group of total frequency 0 costs nothing.
#include "core/reduce/ReductionConstraints.h"

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

namespace vl {

using UnitMask = std::uint64_t; // a set of units, bit a = unit a

struct GroupCostModel {
    std::vector<double> weight;      // F_a
    std::vector<double> self;        // D_a
    std::vector<double> cross;       // H_ab, size x size, row-major
    std::vector<UnitMask> conflicts; // bit b of conflicts[a]: a and b may never share a group
    // The cost of all units in one group: the scale for relative tolerances and gaps.
    double scale = 0;

    int size() const { return static_cast<int>(weight.size()); }
    double h(int a, int b) const {
        return cross[static_cast<std::size_t>(a) * weight.size() + static_cast<std::size_t>(b)];
    }
    // c(S) in O(|S|^2) with a fixed summation order, so every solver reports identical costs.
    double cost(UnitMask group) const;
    // No two members conflict.
    bool allowed(UnitMask group) const;
    // Absolute tolerance below which two costs are the same optimum (rounding of D - Q/F).
    double tolerance() const { return 1e-11 * scale + 1e-300; }
};

// Running sums of one group, for solvers that grow groups one unit at a time.
struct GroupSums {
    double F = 0, D = 0, Q = 0;
    double cost() const { return F > 0 ? std::max(0.0, D - Q / F) : 0.0; }
    // The sums after adding unit a, whose cross term with the current members is crossSum = sum_b H_ab.
    GroupSums plus(const GroupCostModel& model, int a, double crossSum) const {
        return {F + model.weight[static_cast<std::size_t>(a)], D + model.self[static_cast<std::size_t>(a)],
                Q + 2 * crossSum + model.h(a, a)};
    }
};

// The model of `units` for the Gram matrix `gram` (n x n, row-major) and frequencies f (n values).
GroupCostModel makeGroupCostModel(std::span<const double> gram, std::span<const double> frequencies,
                                  const ConstraintUnits& units);

// Sum of c(S) over the groups of a partition given as unit masks.
double partitionCost(const GroupCostModel& model, std::span<const UnitMask> groups);

} // namespace vl
