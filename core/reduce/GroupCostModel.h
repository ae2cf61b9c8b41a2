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
//
// Rest-free model (issue 29): the neutral pose is an extra key that costs nothing, fixed at zero
// displacement. One unit, restUnit, marks the rest group R; its members are not keyed but rest:
//   c(R) = sum_{a in R} rest_a,  rest_a = sum_{i in a} f_i rho(A_i, neutral),
// and every other group costs D - Q/F as above. Resting costs at least as much as joining any key
// (the mean minimises the weighted sum of squares, the neutral is one candidate centre), so
// c(S) >= c(S1) + c(S2) for every split of S still holds: the solvers' bounds stay valid with it.
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
    std::vector<double> rest;        // rest_a (zeros in the keyed model)
    int restUnit = -1;               // the unit marking the rest group; -1: the keyed model
    // The cost of all units in one group: the scale for relative tolerances and gaps.
    double scale = 0;

    int size() const { return static_cast<int>(weight.size()); }
    double h(int a, int b) const {
        return cross[static_cast<std::size_t>(a) * weight.size() + static_cast<std::size_t>(b)];
    }
    // c(S) in O(|S|^2) with a fixed summation order, so every solver reports identical costs.
    double cost(UnitMask group) const;
    // c({a}): the spread of a unit's visemes about their mean (0 for one viseme), rest_a for the rest
    // unit alone.
    double singletonCost(int a) const;
    // No two members conflict.
    bool allowed(UnitMask group) const;
    // Absolute tolerance below which two costs are the same optimum (rounding of D - Q/F).
    double tolerance() const { return 1e-11 * scale + 1e-300; }
};

// Running sums of one group, for solvers that grow groups one unit at a time.
struct GroupSums {
    double F = 0, D = 0, Q = 0;
    double R = 0;         // sum of rest_a over the members (rest-free model only)
    bool resting = false; // holds the rest unit: costs R
    double cost() const {
        if (resting) return std::max(0.0, R);
        return F > 0 ? std::max(0.0, D - Q / F) : 0.0;
    }
    // The sums after adding unit a, whose cross term with the current members is crossSum = sum_b H_ab.
    GroupSums plus(const GroupCostModel& model, int a, double crossSum) const {
        const auto i = static_cast<std::size_t>(a);
        GroupSums out{F + model.weight[i], D + model.self[i], Q + 2 * crossSum + model.h(a, a), R, resting};
        if (model.restUnit >= 0) out.R += model.rest[i], out.resting = resting || a == model.restUnit;
        return out;
    }
    // The sums after removing member a, where crossTo = sum_b H_ab over all members b, a included.
    GroupSums minus(const GroupCostModel& model, int a, double crossTo) const {
        const auto i = static_cast<std::size_t>(a);
        GroupSums out{F - model.weight[i], D - model.self[i], Q - 2 * crossTo + model.h(a, a), R, resting};
        if (model.restUnit >= 0) out.R -= model.rest[i], out.resting = resting && a != model.restUnit;
        return out;
    }
    // The sums of the union with a disjoint group, `between` = sum of H_ab across the two.
    GroupSums merged(const GroupSums& other, double between) const {
        return {F + other.F, D + other.D, Q + other.Q + 2 * between, R + other.R, resting || other.resting};
    }
};

// The model of `units` for the Gram matrix `gram` (n x n, row-major) and frequencies f (n values).
GroupCostModel makeGroupCostModel(std::span<const double> gram, std::span<const double> frequencies,
                                  const ConstraintUnits& units);

// The rest-free variant of `model` (see above): restCosts[i] = f_i rho(A_i, neutral) per viseme,
// summed per unit of `units`; restUnit marks the rest group. `units` with one unit more than the
// model (no visemes, restUnit) appends that virtual unit (F = D = H = rest = 0) for a set without a
// rest viseme; the conflicts are those of `units`.
void makeRestFree(GroupCostModel& model, std::span<const double> restCosts, const ConstraintUnits& units,
                  int restUnit);

// Sum of c(S) over the groups of a partition given as unit masks.
double partitionCost(const GroupCostModel& model, std::span<const UnitMask> groups);

} // namespace vl
