#pragma once
// Optimal viseme reduction (Danihelka, Kencl, Zara: "Reduction of Animated Models for Embedded
// Devices"): partition n interpolable shapes into p groups minimising
//   rho_f = sum_i f_i * rho(A_i, B_group(i)),  rho(A,B) = sum_k w_k |a_k - b_k|^2,
// where B of a group is the frequency-weighted mean of its members (the paper's eq. 19), optionally
// under designer constraints (ReductionConstraints.h).
//
// Two exact solvers share one cost model (GroupCostModel.h): the paper's subset DP (SubsetDp.h),
// fastest up to ~16 visemes, and repetitive branch and bound (BranchAndBound.h) for larger sets, up
// to 64. Every result carries its certificate: `optimal` only with a proof, otherwise the best grouping
// found with a proven lower bound and the relative gap.
#include "core/common/EnumNames.h"
#include "core/mesh/Mesh.h"
#include "core/reduce/ReductionConstraints.h"
#include "core/reduce/ShapeView.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace vl {

// Largest number of visemes a reduction accepts (units after 'together' constraints fit in 64 bits).
constexpr int kMaxReductionVisemes = 64;
// Largest set the editor reduces in the background today (its panel follows with issue 10's editor
// part); the core has no such limit.
constexpr int kMaxExactVisemes = 20;

enum class ReductionMethod {
    Auto,             // the subset DP for small sets, then the LP, then branch and bound
    SubsetDp,         // the paper's DP (at most 22 units)
    BranchAndBound,   // repetitive branch and bound
    ColumnGeneration, // the set-partitioning LP by column generation
};

template <> struct EnumNames<ReductionMethod> {
    static constexpr const char* what = "method";
    static constexpr EnumName<ReductionMethod> names[] = {{ReductionMethod::Auto, "auto"},
                                                          {ReductionMethod::SubsetDp, "dp"},
                                                          {ReductionMethod::BranchAndBound, "bnb"},
                                                          {ReductionMethod::ColumnGeneration, "lp"}};
};

// The rest-free model (issue 29): in a morph-target runtime the rest pose (all weights 0) is free, so
// the neutral is an extra key at zero displacement that costs nothing. Each viseme joins one of the m
// keys (the frequency-weighted mean, eq. 19) or rests, at cost f_i rho(A_i, neutral); the rest viseme
// of a set (sil) rests by definition. Off: today's keyed model, where the rest is a key like any other.
struct RestPose {
    bool free = false;
    int viseme = -1;                 // the set's rest viseme, -1: none
    std::span<const Vec3> neutral{}; // the neutral shape; empty: the rest viseme's shape
};

struct ReductionProblem {
    ShapeView shapes;                    // n shapes, same vertex count
    std::span<const double> frequencies; // n values >= 0, not all zero
    std::span<const double> weights;     // one per vertex, >= 0
    int target = 1; // m in 1..n (keys: the rest-free model needs a non-resting viseme per key)
    ReductionConstraints constraints{};
    RestPose rest{};
};

// What a running branch and bound has proven so far about one number of groups: a lower bound that
// only rises and the cost of the best grouping found, which only falls (the editor's progress bar of
// the bound). Written by the search, read from any thread.
struct BoundWatch {
    explicit BoundWatch(int watchedGroups) : groups(watchedGroups) {}
    const int groups; // the p watched
    std::atomic<double> lowerBound{0.0};
    std::atomic<double> bestFound{std::numeric_limits<double>::infinity()};
};

struct ReductionOptions {
    ReductionMethod method = ReductionMethod::Auto;
    double timeLimitSeconds = 0; // branch and bound stops after this; 0 = no limit
    // Set from another thread to stop early: branch and bound then returns its best groupings with
    // their bounds, as at the time limit (with or without a progress callback).
    const std::atomic<bool>* cancelled = nullptr;
    BoundWatch* watch = nullptr; // optional: kept up to date by branch and bound and the LP
};

// groupOf() of a resting viseme (rest-free model): it has no key, all its weights stay 0.
constexpr int kRestGroup = -1;

struct Grouping {
    double cost = 0.0;       // rho_f of `groups` and `rest` (+inf when no grouping into p groups exists)
    double lowerBound = 0.0; // proven: no grouping into p groups satisfying the constraints costs less
    bool optimal = false;    // proven minimal (then lowerBound == cost)
    std::vector<std::vector<int>> groups; // member indices, each ascending; groups ordered by first member
    std::vector<int> rest{};              // the resting visemes, ascending (rest-free model only)

    bool feasible() const { return !groups.empty(); }
    // groupOf[i]: the group viseme i is in, kRestGroup when it rests (groups and rest partition the n
    // visemes).
    std::vector<int> groupOf() const;
    // (cost - lowerBound) / cost: 0 when optimal, 1 when nothing is known.
    double gap() const;
    bool operator==(const Grouping&) const = default;
};

struct ReductionResult {
    std::vector<Grouping> curve;                        // curve[p-1]: grouping into p groups, p = 1..m
    ReductionMethod method = ReductionMethod::SubsetDp; // the solver that ran
    bool restFree = false;                              // the rest-free model ran (RestPose)
    const Grouping& best() const { return curve.back(); }
    // groupOf[i]: index of the group viseme i belongs to in best().
    std::vector<int> groupOf() const;
    bool operator==(const ReductionResult&) const = default;
};

// Progress in [0,1]; called from the calling thread only.
using ProgressCallback = std::function<void(double)>;

// The reduction for p = 1..m. Throws InputError when m is outside 1..n, n > kMaxReductionVisemes,
// sizes disagree, frequencies/weights are invalid, the constraints contradict themselves, or no
// grouping into m groups satisfies them (entries p < m that the constraints rule out have no groups).
ReductionResult reduceVisemes(const ReductionProblem& problem, const ReductionOptions& options,
                              const ProgressCallback& progress = {});
ReductionResult reduceVisemes(const ReductionProblem& problem, const ProgressCallback& progress = {});

// The constraint units of n visemes with their group limits counted in keys, as the user gives m:
// under the rest-free model (rest.free) the rest is a group beyond the m keys, which a viseme may join
// unless it is pinned. For feasibility checks and throwInfeasibleTarget before a run.
ConstraintUnits keyUnits(const ReductionConstraints& constraints, int n, const RestPose& rest,
                         std::span<const std::string> visemeNames = {},
                         std::string_view where = "constraints");

// The frequency-weighted mean of the members (eq. 19). A group whose frequencies are all zero
// contributes nothing to the cost; its merged shape is the plain mean.
std::vector<Vec3> mergeGroup(const ShapeView& shapes, std::span<const double> frequencies,
                             std::span<const int> members);

// rho_f of a grouping with resting visemes, directly from the meshes: groupingCost of the keys plus
// f_i rho(A_i, neutral) per resting viseme. The slow reference of the rest-free model.
double restFreeGroupingCost(const ShapeView& shapes, std::span<const double> frequencies,
                            std::span<const double> weights, const std::vector<std::vector<int>>& groups,
                            std::span<const int> resting, std::span<const Vec3> neutral);

// rho(A,B) with per-vertex weights.
double dissimilarity(ShapeRow a, ShapeRow b, std::span<const double> weights);

// rho_f of each grouping through the weighted Gram matrix, with the solvers' summation (one O(n^2 |V|)
// pass, then O(n^2) per grouping): the numbers the solvers report for the same groups, so a given
// grouping (e.g. a standard phoneme -> viseme map) compares exactly with the optimum. Each grouping must
// partition 0..n-1 into non-empty groups; throws InputError otherwise and for invalid inputs (as
// reduceVisemes). With a free rest, the group holding the rest viseme (if any) rests.
std::vector<double> evaluateGroupings(const ShapeView& shapes, std::span<const double> frequencies,
                                      std::span<const double> weights,
                                      std::span<const std::vector<std::vector<int>>> groupings,
                                      const RestPose& rest = {});

// rho_f of a grouping evaluated directly from the meshes (O(n|V|)): the slow, obvious reference.
double groupingCost(const ShapeView& shapes, std::span<const double> frequencies,
                    std::span<const double> weights, const std::vector<std::vector<int>>& groups);

} // namespace vl
