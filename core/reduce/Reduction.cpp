// The reduction entry point: validates the problem, builds the Gram matrix and the cost model of the
// constraint units once, runs the chosen solver and turns unit partitions back into viseme groups.
#include "core/reduce/Reduction.h"
#include "core/reduce/ColumnGeneration.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/reduce/BranchAndBound.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/GroupCostModel.h"
#include "core/reduce/ReductionHeuristics.h"
#include "core/reduce/SubsetDp.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <thread>

namespace vl {

namespace {

constexpr double kInfiniteCost = std::numeric_limits<double>::infinity();
// Auto picks the DP alone up to this many units (well under a millisecond); above, branch and bound
// gets the first share of the DP's time: on real viseme sets it proves n = 16 about 7x faster than
// the DP (bench_reduce BM_ReduceArpabet), on structureless ones the DP follows.
constexpr int kAutoDpUnits = 12;
// Auto gives branch and bound this share of the DP's predicted time at 16 units first, at the search's
// node rate on 2 cores (1.5 M nodes in 70 ms at n = 16, 160 k in 12 ms at n = 24: bench_reduce), and
// twice as many nodes per further unit while the DP's time triples: real sets need few more nodes per
// unit (ARPAbet meshes: 7 k nodes at n = 16, 15 k at 18, 44 k at 20; a rig's 16 shapes 12 k), and on
// structureless ones the share is then 3 % of the DP's time at n = 20 instead of 15 %.
// The share is work, the groups the search's nodes try (SearchLimits), at 6 per node: a node tries
// 4.5 (ARPAbet n = 16) to 6.4 (n = 32) keyed and up to 7.8 rest free (one group more, searches of
// more groups). Counted in nodes, the rest-free searches at n = 36 spent the same share on nodes of
// 7.7 groups against the keyed ones' 5.4 and took 1.4x their time (issue 29).
constexpr double kBranchAndBoundShare = 0.15;
constexpr int kBranchAndBoundShareUnits = 16;
constexpr double kBranchAndBoundWorkPerSecond = 6 * 2e7;
// Past the DP's range Auto's first branch and bound gets at most this share of the time limit.
constexpr double kLpRangeBranchAndBoundShare = 0.25;
// The heuristics' k-means++ restarts per p. Up to kFewRestartsUnits units an exact search always
// finishes within milliseconds and the starts only seed its upper bound: 8 restarts prove the sample
// (15 units) with the same optimum in 1.6 ms of CPU instead of 2.2 ms (bench_reduce
// BM_SampleReduction). Larger sets keep 24: there a good start decides how much of the search runs,
// and it is the answer when a time limit stops the search.
constexpr int kFewRestartsUnits = 16;
HeuristicOptions heuristicOptionsFor(int units) {
    HeuristicOptions options;
    if (units <= kFewRestartsUnits) options.restarts = 8;
    return options;
}

void validate(const ReductionProblem& problem) {
    const std::size_t n = problem.shapes.size();
    if (n == 0) throwInputError("reduction", "no visemes to reduce");
    if (n > static_cast<std::size_t>(kMaxReductionVisemes))
        throwInputError("reduction", std::to_string(n) + " visemes: at most " +
                                         std::to_string(kMaxReductionVisemes) + " are supported");
    if (problem.target < 1 || static_cast<std::size_t>(problem.target) > n)
        throwInputError("reduction", "target m = " + std::to_string(problem.target) + " is outside 1.." +
                                         std::to_string(n));
    if (problem.frequencies.size() != n)
        throwInputError("reduction", std::to_string(problem.frequencies.size()) + " frequencies for " +
                                         std::to_string(n) + " visemes");
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double f = problem.frequencies[i];
        if (!std::isfinite(f) || f < 0)
            throwInputError("reduction", "frequency of viseme " + std::to_string(i) + " is " +
                                             formatDouble(f) + "; must be finite and >= 0");
        total += f;
    }
    if (!(total > 0)) throwInputError("reduction", "all frequencies are zero");
    const std::size_t vertices = problem.weights.size();
    for (std::size_t i = 0; i < n; ++i)
        if (problem.shapes[i].size() != vertices)
            throwInputError("reduction", "viseme " + std::to_string(i) + " has " +
                                             std::to_string(problem.shapes[i].size()) +
                                             " vertices, expected " + std::to_string(vertices));
    for (std::size_t k = 0; k < vertices; ++k)
        if (!std::isfinite(problem.weights[k]) || problem.weights[k] < 0)
            throwInputError("reduction",
                            "weight of vertex " + std::to_string(k) + " must be finite and >= 0");
    const RestPose& rest = problem.rest;
    if (rest.viseme < -1 || rest.viseme >= static_cast<int>(n))
        throwInputError("reduction", "rest viseme " + std::to_string(rest.viseme) + " is outside 0.." +
                                         std::to_string(n - 1));
    if (!rest.neutral.empty() && rest.neutral.size() != vertices)
        throwInputError("reduction", "the neutral shape has " + std::to_string(rest.neutral.size()) +
                                         " vertices, expected " + std::to_string(vertices));
    if (rest.free && rest.neutral.empty() && rest.viseme < 0)
        throwInputError("reduction", "the rest-free model needs a neutral shape or a rest viseme");
}

// The rest-free model's units: the rest viseme's unit marks the rest group; without one, a virtual
// unit with no visemes does. A pinned viseme is a key of its own, so it conflicts with the virtual
// unit as with every other (it rests only when it is the rest viseme: then alone).
struct RestUnits {
    ConstraintUnits units;
    int restUnit = -1;
};
RestUnits restUnitsOf(const ConstraintUnits& units, const RestPose& rest, std::span<const int> pinned) {
    RestUnits out{units, -1};
    if (rest.viseme >= 0) {
        out.restUnit = units.unitOf[static_cast<std::size_t>(rest.viseme)];
        return out;
    }
    if (units.size() >= static_cast<std::size_t>(kMaxReductionVisemes))
        throwInputError("reduction", "the rest-free model without a rest viseme takes at most " +
                                         std::to_string(kMaxReductionVisemes - 1) + " units");
    out.restUnit = static_cast<int>(units.size());
    const UnitMask virtualBit = UnitMask{1} << out.restUnit;
    UnitMask pinnedUnits = 0;
    for (const int i : pinned) {
        const int unit = units.unitOf[static_cast<std::size_t>(i)];
        pinnedUnits |= UnitMask{1} << unit;
        out.units.conflicts[static_cast<std::size_t>(unit)] |= virtualBit;
    }
    out.units.members.emplace_back();
    out.units.conflicts.push_back(pinnedUnits);
    ++out.units.maxGroups;
    // The virtual unit shares a colour with any unpinned unit; with every unit pinned it needs its own.
    if (std::popcount(pinnedUnits) == static_cast<int>(units.size())) ++out.units.minGroups;
    return out;
}

} // namespace

ConstraintUnits keyUnits(const ReductionConstraints& constraints, int n, const RestPose& rest,
                         std::span<const std::string> visemeNames, std::string_view where) {
    const ConstraintUnits keyed = constraintUnits(constraints, n, visemeNames, where);
    if (!rest.free) return keyed;
    ConstraintUnits units = restUnitsOf(keyed, rest, constraints.pinned).units;
    --units.minGroups;
    --units.maxGroups;
    return units;
}

namespace {

// f_i rho(A_i, neutral) per viseme (in double, from the meshes, not the centred Gram).
std::vector<double> visemeRestCosts(const ReductionProblem& problem) {
    const RestPose& rest = problem.rest;
    const ShapeRow neutral =
        rest.neutral.empty() ? problem.shapes[static_cast<std::size_t>(rest.viseme)] : ShapeRow(rest.neutral);
    std::vector<double> costs;
    for (std::size_t i = 0; i < problem.shapes.size(); ++i)
        costs.push_back(problem.frequencies[i] * dissimilarity(problem.shapes[i], neutral, problem.weights));
    return costs;
}

// The group holding restUnit (if any) becomes the resting visemes.
Grouping toGrouping(const UnitPartition& entry, const ConstraintUnits& units, int restUnit) {
    Grouping g;
    g.cost = entry.cost;
    g.optimal = entry.optimal;
    g.lowerBound = entry.optimal ? entry.cost : entry.lowerBound;
    for (const UnitMask mask : entry.groups) {
        std::vector<int> members;
        for (UnitMask bits = mask; bits; bits &= bits - 1) {
            const auto& unit = units.members[static_cast<std::size_t>(std::countr_zero(bits))];
            members.insert(members.end(), unit.begin(), unit.end());
        }
        std::sort(members.begin(), members.end());
        if (restUnit >= 0 && (mask >> restUnit & 1))
            g.rest = std::move(members);
        else
            g.groups.push_back(std::move(members));
    }
    std::sort(g.groups.begin(), g.groups.end());
    return g;
}

// Branch and bound for every feasible p = 1..m, in parallel, from the heuristics' partitions. Runs
// on its own thread so the calling thread can report progress.
// `restGroups` (1 in the rest-free model, else 0): groups beyond the keys, for the watch (which counts keys).
UnitCurve solveByBranchAndBound(const GroupCostModel& model, const ConstraintUnits& units, int m,
                                const ReductionOptions& options, const ProgressCallback& progress,
                                std::uint64_t workBudget = 0, bool tightenStoppedBound = true,
                                int restGroups = 0) {
    const int watched = options.watch ? options.watch->groups + restGroups : 0;
    const auto starts = heuristicPartitions(model, m, heuristicOptionsFor(model.size()));
    SearchLimits limits;
    std::atomic<std::uint64_t> work{0};
    if (workBudget > 0) {
        limits.work = &work;
        limits.workBudget = workBudget;
    }
    limits.tightenStoppedBound = tightenStoppedBound;
    if (options.timeLimitSeconds > 0)
        limits.deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options.timeLimitSeconds));
    // With a progress callback the searches watch a flag of their own: set when the caller's flag is,
    // and when the callback throws (the editor cancels its task that way), so the searches stop before
    // the exception leaves instead of running on to their time limit while the caller waits.
    std::atomic<bool> stopped{false};
    limits.cancelled = progress ? &stopped : options.cancelled;
    std::vector<std::atomic<double>> done(static_cast<std::size_t>(m));
    UnitCurve curve(static_cast<std::size_t>(m));
    if (BoundWatch* watch = options.watch;
        watch && watched >= 1 && watched <= m &&
        starts[static_cast<std::size_t>(watched - 1)].size() == static_cast<std::size_t>(watched)) {
        // Known before the searches start (the watched one may wait for a thread for seconds).
        const auto& start = starts[static_cast<std::size_t>(watched - 1)];
        watch->bestFound = partitionCost(model, start);
        watch->lowerBound = std::min(blockLowerBound(model, watched), watch->bestFound.load());
    }
    auto solve = [&] {
        tbb::parallel_for(1, m + 1, [&](int p) {
            auto& entry = curve[static_cast<std::size_t>(p - 1)];
            if (!units.feasible(p)) {
                entry.optimal = true; // proven: the constraints rule p out
            } else {
                const auto& start = starts[static_cast<std::size_t>(p - 1)];
                BoundWatch* watch = options.watch && watched == p ? options.watch : nullptr;
                entry = branchAndBound(model, p, start, limits, &done[static_cast<std::size_t>(p - 1)],
                                       watch ? &watch->lowerBound : nullptr);
                if (watch) {
                    watch->bestFound = entry.cost;
                    watch->lowerBound = entry.optimal ? entry.cost : entry.lowerBound;
                }
            }
            done[static_cast<std::size_t>(p - 1)] = 1.0;
        });
    };
    if (!progress) {
        solve();
    } else {
        auto running = std::async(std::launch::async, solve);
        try {
            while (running.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
                if (options.cancelled && options.cancelled->load()) stopped = true;
                double sum = 0;
                for (const auto& d : done) sum += d.load(std::memory_order_relaxed);
                progress(sum / m);
            }
        } catch (...) {
            stopped = true;
            running.wait();
            throw;
        }
        running.get();
    }
    // OPT is non-increasing in p: a bound for p + 1 groups bounds p groups too.
    for (int p = m - 1; p >= 1; --p) {
        auto& entry = curve[static_cast<std::size_t>(p - 1)];
        const auto& next = curve[static_cast<std::size_t>(p)];
        if (!entry.optimal && next.lowerBound < kInfiniteCost)
            entry.lowerBound = std::min(entry.cost, std::max(entry.lowerBound, next.lowerBound));
    }
    return curve;
}

// The DP's run time on 2 cores: about 5.5 ms at 16 units and m = 10 (all-layer rows), x3 per further unit.
double estimatedSubsetDpSeconds(int units, int m) {
    return 0.0055 * std::pow(3.0, units - 16) * std::max(1.0, m / 10.0);
}

// Auto's first share for branch and bound (kBranchAndBoundShare), in seconds and in search work.
double branchAndBoundShareSeconds(int units, int m) {
    return kBranchAndBoundShare * estimatedSubsetDpSeconds(kBranchAndBoundShareUnits, m) *
           std::pow(2.0, units - kBranchAndBoundShareUnits);
}
std::uint64_t branchAndBoundShareWork(int units, int m) {
    return static_cast<std::uint64_t>(branchAndBoundShareSeconds(units, m) * kBranchAndBoundWorkPerSecond);
}

// The LP by column generation for every feasible p = 1..m, one p after another (each prices in
// parallel), from the heuristics' partitions; p the heuristics found no partition for stays unproven.
// `restGroups` as in solveByBranchAndBound: the watched p's entry is published to options.watch.
UnitCurve solveByColumnGeneration(const GroupCostModel& model, const ConstraintUnits& units, int m,
                                  const ReductionOptions& options, const ProgressCallback& progress,
                                  const UnitCurve& proven = {}, int restGroups = 0) {
    const int watched = options.watch ? options.watch->groups + restGroups : 0;
    const auto starts = heuristicPartitions(model, m, heuristicOptionsFor(model.size()));
    SearchLimits limits;
    limits.cancelled = options.cancelled;
    if (options.timeLimitSeconds > 0)
        limits.deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options.timeLimitSeconds));
    UnitCurve curve(static_cast<std::size_t>(m));
    ColumnPool pool; // the groups of one p start the next
    // The target m first: the caller asked for it, the smaller p fill the cost curve in the time left.
    for (int p = m; p >= 1; --p) {
        auto& entry = curve[static_cast<std::size_t>(p - 1)];
        const auto& start = starts[static_cast<std::size_t>(p - 1)];
        if (!units.feasible(p))
            entry.optimal = true; // proven: the constraints rule p out
        else if (static_cast<std::size_t>(p) <= proven.size() &&
                 proven[static_cast<std::size_t>(p - 1)].optimal)
            entry = proven[static_cast<std::size_t>(p - 1)]; // an earlier search proved it
        else if (!start.empty() && !limits.expired(0))
            entry = solveByColumnGeneration(model, p, start, limits, &pool);
        else if (!start.empty()) // out of time: the start, bounded below
            entry = {start, partitionCost(model, start), 0.0, false};
        // OPT is non-increasing in p: the bound for p + 1 groups bounds p groups too.
        if (p < m && !entry.optimal && !entry.groups.empty() &&
            curve[static_cast<std::size_t>(p)].lowerBound < kInfiniteCost)
            entry.lowerBound = std::min(
                entry.cost, std::max(entry.lowerBound, curve[static_cast<std::size_t>(p)].lowerBound));
        if (p == watched && !entry.groups.empty()) {
            options.watch->bestFound = entry.cost;
            options.watch->lowerBound = entry.optimal ? entry.cost : entry.lowerBound;
        }
        if (progress) progress(static_cast<double>(m - p + 1) / m);
    }
    return curve;
}

// Per p, the better of two runs' results: a proof from either, the cheaper grouping, the higher bound.
UnitCurve betterOf(UnitCurve first, const UnitCurve& second) {
    for (std::size_t i = 0; i < first.size(); ++i) {
        UnitPartition& a = first[i];
        const UnitPartition& b = second[i];
        if (a.optimal) continue;
        if (b.optimal) {
            a = b;
            continue;
        }
        const double bound = std::max(a.lowerBound, b.lowerBound);
        if (!b.groups.empty() && (a.groups.empty() || b.cost < a.cost)) a = b;
        a.lowerBound = std::min(bound, a.cost);
    }
    return first;
}

} // namespace

double Grouping::gap() const {
    if (optimal) return 0.0;
    if (!(cost < kInfiniteCost) || cost <= 0) return cost <= 0 ? 0.0 : 1.0;
    return std::clamp((cost - lowerBound) / cost, 0.0, 1.0);
}

std::vector<int> Grouping::groupOf() const {
    std::size_t n = rest.size();
    for (const auto& g : groups) n += g.size();
    std::vector<int> result(n, kRestGroup);
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (const int member : groups[g]) result[static_cast<std::size_t>(member)] = static_cast<int>(g);
    return result;
}

std::vector<int> ReductionResult::groupOf() const {
    return best().groupOf();
}

ReductionResult reduceVisemes(const ReductionProblem& problem, const ProgressCallback& progress) {
    return reduceVisemes(problem, ReductionOptions{}, progress);
}

ReductionResult reduceVisemes(const ReductionProblem& problem, const ReductionOptions& options,
                              const ProgressCallback& progress) {
    validate(problem);
    const int n = static_cast<int>(problem.shapes.size());
    const int m = problem.target;
    const ConstraintUnits keyedUnits = constraintUnits(problem.constraints, n, {}, "reduction constraints");
    // The rest-free model partitions the units into m + 1 groups, one of them marked by the rest unit.
    const bool restFree = problem.rest.free;
    const int restGroups = restFree ? 1 : 0;
    const RestUnits restUnits = restFree ? restUnitsOf(keyedUnits, problem.rest, problem.constraints.pinned)
                                         : RestUnits{keyedUnits, -1};
    const ConstraintUnits& units = restUnits.units;
    const int groupsWanted = m + restGroups;
    if (!units.feasible(groupsWanted))
        throwInfeasibleTarget(keyUnits(problem.constraints, n, problem.rest), m, "reduction constraints");
    GroupCostModel model = makeGroupCostModel(
        centredGram(problem.shapes, problem.frequencies, problem.weights), problem.frequencies, keyedUnits);
    if (restFree) makeRestFree(model, visemeRestCosts(problem), units, restUnits.restUnit);
    const int count = model.size();
    const int solvable = std::min(groupsWanted, count);

    ReductionResult result;
    result.method = options.method;
    result.restFree = restFree;
    if (result.method == ReductionMethod::SubsetDp && count > kMaxSubsetDpUnits)
        throwInputError("reduction", "the subset DP takes at most " + std::to_string(kMaxSubsetDpUnits) +
                                         " visemes (2^n subsets), the problem has " + std::to_string(count) +
                                         "; use branch and bound");
    UnitCurve curve;
    if (result.method == ReductionMethod::Auto && count > kAutoDpUnits && count <= kMaxSubsetDpUnits) {
        // A portfolio: branch and bound proves structured sets in a fraction of the DP's time, the DP
        // wins on structureless ones (all shapes about equally far apart). Branch and bound gets a
        // share of the DP's predictable time; the DP runs only when that was not enough.
        const double dpSeconds = estimatedSubsetDpSeconds(count, solvable);
        // The share is counted in search work (groups tried), not seconds, so that the solver chosen
        // (and the project file recording it) is the same on a slow, loaded or instrumented machine.
        const double shareSeconds = branchAndBoundShareSeconds(count, solvable);
        const std::uint64_t budget = branchAndBoundShareWork(count, solvable);
        const bool dpFits =
            options.timeLimitSeconds <= 0 || options.timeLimitSeconds >= shareSeconds + dpSeconds;
        // When the DP follows an unproven search, that search's bounds are discarded: skip them.
        curve = solveByBranchAndBound(model, units, solvable, options, progress, budget, !dpFits, restGroups);
        result.method = ReductionMethod::BranchAndBound;
        const bool proven =
            std::all_of(curve.begin(), curve.end(), [](const UnitPartition& e) { return e.optimal; });
        if (!proven && dpFits && !(options.cancelled && options.cancelled->load())) {
            curve = solveSubsetDp(model, solvable, progress);
            result.method = ReductionMethod::SubsetDp;
        }
    } else if ((result.method == ReductionMethod::Auto && count > kMaxSubsetDpUnits) ||
               result.method == ReductionMethod::ColumnGeneration) {
        // Above the DP's limit: with Auto, branch and bound first gets the same share as in the DP's
        // range (structured sets are proved in milliseconds), then the LP, which proves most sets,
        // structured or not, for the p left; branch and bound again, in the time left, for any p the
        // LP did not prove.
        const auto started = std::chrono::steady_clock::now();
        const bool automatic = result.method == ReductionMethod::Auto;
        auto allProven = [](const UnitCurve& c) {
            return std::all_of(c.begin(), c.end(), [](const UnitPartition& e) { return e.optimal; });
        };
        if (automatic) {
            // Past the DP's range the share stops growing: the LP proves real sets faster than branch
            // and bound (ARPAbet 40, m = 10: 0.5 s instead of 2.4 s; rest-free 1.7 s instead of 7.5 s).
            std::uint64_t share = branchAndBoundShareWork(kMaxSubsetDpUnits, solvable);
            if (options.timeLimitSeconds > 0)
                share = std::min(
                    share, static_cast<std::uint64_t>(kLpRangeBranchAndBoundShare * options.timeLimitSeconds *
                                                      kBranchAndBoundWorkPerSecond));
            curve =
                solveByBranchAndBound(model, units, solvable, options, progress, share, false, restGroups);
            result.method = ReductionMethod::BranchAndBound;
        }
        if (!automatic || !allProven(curve)) {
            ReductionOptions left = options; // the LP's deadline counts from the start, as the limit does
            if (left.timeLimitSeconds > 0)
                left.timeLimitSeconds = std::max(
                    1e-3,
                    left.timeLimitSeconds -
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
            UnitCurve lp = solveByColumnGeneration(model, units, solvable, left, progress, curve, restGroups);
            curve = automatic ? betterOf(std::move(lp), curve) : std::move(lp);
            result.method = ReductionMethod::ColumnGeneration;
            const double spent =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            const bool timeLeft = options.timeLimitSeconds <= 0 || spent < options.timeLimitSeconds;
            if (automatic && !allProven(curve) && timeLeft &&
                !(options.cancelled && options.cancelled->load())) {
                ReductionOptions rest = options;
                if (rest.timeLimitSeconds > 0) rest.timeLimitSeconds -= spent;
                curve = betterOf(std::move(curve), solveByBranchAndBound(model, units, solvable, rest,
                                                                         progress, 0, true, restGroups));
                result.method = ReductionMethod::BranchAndBound;
            }
        }
    } else {
        if (result.method == ReductionMethod::Auto)
            result.method =
                count <= kAutoDpUnits ? ReductionMethod::SubsetDp : ReductionMethod::BranchAndBound;
        curve = result.method == ReductionMethod::SubsetDp
                    ? solveSubsetDp(model, solvable, progress)
                    : solveByBranchAndBound(model, units, solvable, options, progress, 0, true, restGroups);
    }
    // Rest-free: entry 0 (everything rests, no key) is not on the curve of p = 1..m keys.
    for (std::size_t e = static_cast<std::size_t>(restGroups); e < curve.size(); ++e)
        result.curve.push_back(toGrouping(curve[e], units, restUnits.restUnit));
    // More groups than units: nothing can be split further (the target check above excludes m).
    result.curve.resize(static_cast<std::size_t>(m), Grouping{kInfiniteCost, kInfiniteCost, true, {}, {}});
    if (!result.best().feasible())
        throwInfeasibleTarget(keyUnits(problem.constraints, n, problem.rest), m, "reduction constraints");
    if (progress) progress(1.0);
    return result;
}

std::vector<Vec3> mergeGroup(const ShapeView& shapes, std::span<const double> frequencies,
                             std::span<const int> members) {
    if (members.empty()) throw std::invalid_argument("mergeGroup: empty group");
    double total = 0;
    for (const int i : members) total += frequencies[static_cast<std::size_t>(i)];
    const std::size_t vertices = shapes[static_cast<std::size_t>(members[0])].size();
    std::vector<Vec3> merged(vertices, Vec3(0, 0, 0));
    for (const int i : members) {
        // Zero-frequency groups fall back to the plain mean: any shape is optimal for them.
        const double w = total > 0 ? frequencies[static_cast<std::size_t>(i)] / total : 1.0 / members.size();
        const auto shape = shapes[static_cast<std::size_t>(i)];
        for (std::size_t k = 0; k < vertices; ++k) merged[k] += w * shape[k];
    }
    return merged;
}

double dissimilarity(ShapeRow a, ShapeRow b, std::span<const double> weights) {
    double sum = 0;
    for (std::size_t k = 0; k < a.size(); ++k) sum += weights[k] * (a[k] - b[k]).sqrnorm();
    return sum;
}

std::vector<double> evaluateGroupings(const ShapeView& shapes, std::span<const double> frequencies,
                                      std::span<const double> weights,
                                      std::span<const std::vector<std::vector<int>>> groupings,
                                      const RestPose& rest) {
    const ReductionProblem problem{shapes, frequencies, weights, 1, {}, rest};
    validate(problem);
    const int n = static_cast<int>(shapes.size());
    const ConstraintUnits units = constraintUnits({}, n); // every viseme its own unit
    GroupCostModel model = makeGroupCostModel(centredGram(shapes, frequencies, weights), frequencies, units);
    // Only a rest viseme marks a group as resting here: a virtual unit would be in no given group.
    if (rest.free && rest.viseme >= 0) makeRestFree(model, visemeRestCosts(problem), units, rest.viseme);
    std::vector<double> costs;
    for (std::size_t k = 0; k < groupings.size(); ++k) {
        const std::string where = "grouping " + std::to_string(k + 1);
        UnitMask seen = 0;
        std::vector<UnitMask> masks;
        for (const auto& group : groupings[k]) {
            if (group.empty()) throwInputError(where, "has an empty group");
            UnitMask mask = 0;
            for (const int i : group) {
                if (i < 0 || i >= n)
                    throwInputError(where, "viseme index " + std::to_string(i) + " is outside 0.." +
                                               std::to_string(n - 1));
                const UnitMask bit = UnitMask{1} << i;
                if ((seen | mask) & bit)
                    throwInputError(where, "viseme " + std::to_string(i) + " is in two groups");
                mask |= bit;
            }
            seen |= mask;
            masks.push_back(mask);
        }
        if (std::popcount(seen) != n)
            throwInputError(where, "leaves out viseme " + std::to_string(std::countr_one(seen)));
        costs.push_back(partitionCost(model, masks));
    }
    return costs;
}

double groupingCost(const ShapeView& shapes, std::span<const double> frequencies,
                    std::span<const double> weights, const std::vector<std::vector<int>>& groups) {
    double total = 0;
    for (const auto& group : groups) {
        const auto merged = mergeGroup(shapes, frequencies, group);
        for (const int i : group)
            total += frequencies[static_cast<std::size_t>(i)] *
                     dissimilarity(shapes[static_cast<std::size_t>(i)], merged, weights);
    }
    return total;
}

double restFreeGroupingCost(const ShapeView& shapes, std::span<const double> frequencies,
                            std::span<const double> weights, const std::vector<std::vector<int>>& groups,
                            std::span<const int> resting, std::span<const Vec3> neutral) {
    double total = groupingCost(shapes, frequencies, weights, groups);
    for (const int i : resting)
        total += frequencies[static_cast<std::size_t>(i)] *
                 dissimilarity(shapes[static_cast<std::size_t>(i)], neutral, weights);
    return total;
}

} // namespace vl
