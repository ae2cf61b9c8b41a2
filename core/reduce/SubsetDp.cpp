// Cost of every group: c(S) for all 2^n sets of units, each from S minus its highest unit j in
// O(n): Q(S) = Q(S\j) + 2 sum_{i in S\j} H_ij + H_jj, with F and D summed over the same bits. A set
// holding a conflicting pair costs +inf, so no solver step ever picks it.
//
// Partition DP (the paper's eq. 23): best[q][T] = min over V subset of T of c(V) + best[q-1][T\V].
// Fixing the lowest unit of T inside V enumerates every partition exactly once (halving the work);
// every state below the top one then excludes unit 0, so layers are indexed by subsets of
// {1..n-1} (2^(n-1) entries). States with |T| < q are infeasible and skipped. Layers run in parallel
// over T with TBB; the result does not depend on the thread count (each state is computed alone,
// with a fixed enumeration order and strict '<', so ties always go the same way).
#include "core/reduce/SubsetDp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace vl {

namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

std::vector<double> allGroupCosts(const GroupCostModel& model) {
    const int n = model.size();
    const std::size_t count = std::size_t{1} << n;
    std::vector<double> cost(count, 0.0), Q(count, 0.0);
    // Parallel over blocks of the high bits: each block only reads sets with a smaller highest unit,
    // which earlier blocks (sequential in the outer loop over j) have finished.
    for (int j = 0; j < n; ++j) {
        const std::size_t lo = std::size_t{1} << j;
        const double* row = &model.cross[static_cast<std::size_t>(j) * static_cast<std::size_t>(n)];
        const double fj = model.weight[static_cast<std::size_t>(j)],
                     dj = model.self[static_cast<std::size_t>(j)];
        const UnitMask conflictsJ = model.conflicts[static_cast<std::size_t>(j)];
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, lo, 4096), [&](const auto& range) {
            for (std::size_t rest = range.begin(); rest != range.end(); ++rest) {
                const std::size_t s = rest | lo;
                double cross = 0, F = fj, D = dj;
                for (std::size_t bits = rest; bits; bits &= bits - 1) {
                    const int i = std::countr_zero(bits);
                    cross += row[i];
                    F += model.weight[static_cast<std::size_t>(i)];
                    D += model.self[static_cast<std::size_t>(i)];
                }
                Q[s] = Q[rest] + 2 * cross + row[j];
                const bool conflict = std::isinf(cost[rest]) || (rest & conflictsJ) != 0;
                // Rounding may push D - Q/F slightly below 0.
                cost[s] = conflict ? kUnreached : (F > 0 ? std::max(0.0, D - Q[s] / F) : 0.0);
            }
        });
    }
    return cost;
}

struct Split {
    double cost = kUnreached;
    std::uint32_t rest = 0; // the remainder R = T \ V handed to the layer below
};

// The best split of state T: V = T \ R with R a subset of `others` (= T minus its lowest unit)
// and |R| >= minRest (the layer below needs at least that many units; smaller R are +inf there).
// Two enumerations of the same candidates: all submasks of `others` (cheapest when most are
// feasible), or depth-first over the units moved into V, |others \ R| <= |others| - minRest
// (cheapest when minRest is large and most submasks would be infeasible). Ties keep the first found.
Split bestSplit(std::uint32_t T, std::uint32_t others, int minRest, const std::vector<double>& cost,
                const std::vector<double>& below) {
    Split best;
    auto consider = [&](std::uint32_t r) {
        const double c = cost[T ^ r] + below[r >> 1];
        if (c < best.cost) best = {c, r};
    };
    const int k = std::popcount(others);
    const int maxMoved = k - minRest; // at most this many units of `others` join V
    if (maxMoved < 0) return best;
    if (2 * maxMoved >= k) {
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            consider(r);
            if (r == 0) break;
        }
        return best;
    }
    std::uint32_t bits[32]; // the single-bit masks of `others`, lowest first
    for (std::uint32_t x = others, i = 0; x; x &= x - 1) bits[i++] = x & (~x + 1);
    // Iterative DFS: moved[d] is the set moved into V at depth d, next[d] the next unit index to try.
    std::uint32_t moved[33];
    int next[33];
    int depth = 0;
    moved[0] = 0;
    next[0] = 0;
    consider(others);
    while (depth >= 0) {
        const int i = next[depth];
        if (i < k && depth < maxMoved) {
            next[depth] = i + 1;
            moved[depth + 1] = moved[depth] | bits[i];
            consider(others ^ moved[depth + 1]);
            ++depth;
            next[depth] = i + 1;
        } else {
            --depth;
        }
    }
    return best;
}

} // namespace

UnitCurve solveSubsetDp(const GroupCostModel& model, int m, const std::function<void(double)>& progress) {
    const int n = model.size();
    const std::vector<double> cost = allGroupCosts(model);
    if (progress) progress(0.05);

    const std::uint32_t full = (1u << n) - 1u;
    const std::uint32_t others = full ^ 1u;
    const std::size_t states = std::size_t{1} << (n - 1);
    // Layer q (q = 1..m-1) is best[q][T] for T a subset of {1..n-1}, indexed by T >> 1; only the
    // layer below is kept, plus the remainder chosen at every state of every layer (for the groups).
    std::vector<double> below(states), current(states);
    std::vector<std::vector<std::uint32_t>> rest(static_cast<std::size_t>(std::max(m - 1, 1)));
    for (std::size_t t = 0; t < states; ++t) below[t] = t ? cost[t << 1] : kUnreached;

    UnitCurve curve(static_cast<std::size_t>(m));
    auto finish = [&](int p, const Split& split) {
        UnitPartition& entry = curve[static_cast<std::size_t>(p - 1)];
        entry.optimal = true;
        if (!(split.cost < kUnreached)) return; // no partition into p groups respects the conflicts
        entry.groups.push_back(full ^ split.rest);
        std::uint32_t T = split.rest;
        for (int q = p - 1; q >= 1; --q) {
            const std::uint32_t r = q == 1 ? 0u : rest[static_cast<std::size_t>(q - 1)][T >> 1];
            entry.groups.push_back(T ^ r);
            T = r;
        }
        std::sort(entry.groups.begin(), entry.groups.end(),
                  [](UnitMask a, UnitMask b) { return std::countr_zero(a) < std::countr_zero(b); });
        entry.cost = partitionCost(model, entry.groups);
        entry.lowerBound = entry.cost;
    };
    finish(1, {cost[full], 0});
    if (m >= 2) finish(2, bestSplit(full, others, 1, cost, below));

    for (int q = 2; q <= m - 1; ++q) {
        auto& choice = rest[static_cast<std::size_t>(q - 1)];
        choice.assign(states, 0);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(1, states, 256), [&](const auto& range) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
                const auto T = static_cast<std::uint32_t>(t << 1);
                if (std::popcount(T) < q) {
                    current[t] = kUnreached;
                    continue;
                }
                const std::uint32_t low = T & (~T + 1);
                const Split split = bestSplit(T, T ^ low, q - 1, cost, below);
                current[t] = split.cost;
                choice[t] = split.rest;
            }
        });
        current[0] = kUnreached;
        std::swap(below, current);
        finish(q + 1, bestSplit(full, others, q, cost, below));
        if (progress) progress(0.05 + 0.95 * q / (m - 1));
    }
    if (progress) progress(1.0);
    return curve;
}

} // namespace vl
