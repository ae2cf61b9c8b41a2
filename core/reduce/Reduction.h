#pragma once
// Exact optimal viseme reduction (Danihelka, Kencl, Zara: "Reduction of Animated Models for
// Embedded Devices"): partition n interpolable shapes into p groups minimising
//   rho_f = sum_i f_i * rho(A_i, B_group(i)),  rho(A,B) = sum_k w_k |a_k - b_k|^2,
// where B of a group is the frequency-weighted mean of its members (the paper's eq. 19).
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace vl {

constexpr int kMaxExactVisemes = 20;

struct ReductionProblem {
    std::span<const std::vector<Vec3>> shapes; // n shapes, same vertex count
    std::span<const double> frequencies;       // n values >= 0, not all zero
    std::span<const double> weights;           // one per vertex, >= 0
    int target = 1;                            // m in 1..n
};

struct Grouping {
    double cost = 0.0;                    // optimal rho_f for this number of groups
    std::vector<std::vector<int>> groups; // member indices, each ascending; groups ordered by first member
    bool operator==(const Grouping&) const = default;
};

struct ReductionResult {
    std::vector<Grouping> curve; // curve[p-1]: optimal grouping into p groups, p = 1..m
    const Grouping& best() const { return curve.back(); }
    // groupOf[i]: index of the group viseme i belongs to in best().
    std::vector<int> groupOf() const;
    bool operator==(const ReductionResult&) const = default;
};

// Progress in [0,1]; called from the calling thread only.
using ProgressCallback = std::function<void(double)>;

// Exact optimum by the subset dynamic programme. Throws InputError when n > kMaxExactVisemes,
// m is outside 1..n, sizes disagree, or frequencies/weights are invalid.
ReductionResult reduceVisemes(const ReductionProblem& problem, const ProgressCallback& progress = {});

// The frequency-weighted mean of the members (eq. 19). A group whose frequencies are all zero
// contributes nothing to the cost; its merged shape is the plain mean.
std::vector<Vec3> mergeGroup(std::span<const std::vector<Vec3>> shapes, std::span<const double> frequencies,
                             std::span<const int> members);

// rho(A,B) with per-vertex weights.
double dissimilarity(std::span<const Vec3> a, std::span<const Vec3> b, std::span<const double> weights);

// rho_f of a grouping evaluated directly from the meshes (O(n|V|)): the slow, obvious reference.
double groupingCost(std::span<const std::vector<Vec3>> shapes, std::span<const double> frequencies,
                    std::span<const double> weights, const std::vector<std::vector<int>>& groups);

} // namespace vl
