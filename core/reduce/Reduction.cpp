// Exact viseme reduction by a subset dynamic programme.
//
// Cost of one group S (merged into its frequency-weighted mean B_S):
//   c(S) = sum_{i in S} f_i rho(A_i, B_S) = D(S) - Q(S) / F(S), with
//   F(S) = sum f_i,  D(S) = sum f_i G_ii,  Q(S) = sum_{i,j in S} f_i f_j G_ij,
// where G_ij = sum_k w_k <a_ik, a_jk> is the weighted Gram matrix of the shapes. G is built once
// in O(n^2 |V|); every c(S) then follows from S minus its highest element in O(n), so all 2^n group
// costs take O(n 2^n) instead of the paper's O(n 2^n |V|). The shapes are centred on their
// frequency-weighted mean first: costs are translation-invariant per vertex, and centring keeps
// D and Q/F small so their difference does not lose precision to cancellation.
//
// Partition DP (the paper's eq. 23): best[p][T] = min over V subset of T of c(V) + best[p-1][T\V].
// Fixing the lowest element of T inside V enumerates every partition exactly once (halving the
// work); every state below the top one then excludes element 0, so layers are indexed by subsets
// of {1..n-1} (2^(n-1) entries). States with |T| < p are infeasible (+inf) and pruned.
// Time O(m 3^(n-1)) (~32M steps for n = 16, m = 10), memory O(m 2^(n-1)). Layers run in parallel
// over T with TBB; the result does not depend on the thread count (each state is computed alone,
// with a fixed enumeration order and strict '<', so ties always go the same way).
#include "core/reduce/Reduction.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace vl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void validate(const ReductionProblem& problem) {
    const std::size_t n = problem.shapes.size();
    if (n == 0) throwInputError("reduction", "no visemes to reduce");
    if (n > static_cast<std::size_t>(kMaxExactVisemes))
        throwInputError("reduction", std::to_string(n) + " visemes: the exact reduction supports at most " +
                                         std::to_string(kMaxExactVisemes) + " (2^n subsets)");
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
}

// G_ij = sum_k w_k <a_ik - c_k, a_jk - c_k>, c = frequency-weighted mean shape. O(n^2 |V|).
std::vector<double> centredGram(const ReductionProblem& problem) {
    const std::size_t n = problem.shapes.size();
    const std::size_t vertices = problem.weights.size();
    double total = 0;
    for (const double f : problem.frequencies) total += f;
    std::vector<double> gram(n * n, 0.0);
    std::vector<Vec3> d(n);
    for (std::size_t k = 0; k < vertices; ++k) {
        Vec3 centre(0, 0, 0);
        for (std::size_t i = 0; i < n; ++i) centre += problem.frequencies[i] * problem.shapes[i][k];
        centre /= total;
        for (std::size_t i = 0; i < n; ++i) d[i] = problem.shapes[i][k] - centre;
        const double w = problem.weights[k];
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j) gram[i * n + j] += w * OpenMesh::dot(d[i], d[j]);
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < i; ++j) gram[i * n + j] = gram[j * n + i];
    return gram;
}

// c(S) for every subset S of the n visemes, incrementally from S minus its highest element.
std::vector<double> allGroupCosts(const std::vector<double>& gram, std::span<const double> f) {
    const std::size_t n = f.size();
    const std::size_t count = std::size_t{1} << n;
    std::vector<double> F(count, 0.0), D(count, 0.0), Q(count, 0.0), cost(count, 0.0);
    for (std::size_t s = 1; s < count; ++s) {
        const int j = std::bit_width(s) - 1;
        const std::size_t rest = s ^ (std::size_t{1} << j);
        const double* row = &gram[static_cast<std::size_t>(j) * n];
        double cross = 0; // sum_{i in rest} f_i G_ij
        for (std::size_t bits = rest; bits; bits &= bits - 1) {
            const int i = std::countr_zero(bits);
            cross += f[i] * row[i];
        }
        const double fj = f[j];
        F[s] = F[rest] + fj;
        D[s] = D[rest] + fj * row[j];
        Q[s] = Q[rest] + fj * (2 * cross + fj * row[j]);
        // A group of zero total frequency costs nothing; rounding may push D - Q/F slightly below 0.
        cost[s] = F[s] > 0 ? std::max(0.0, D[s] - Q[s] / F[s]) : 0.0;
    }
    return cost;
}

struct Split {
    double cost = kInf;
    std::uint32_t rest = 0; // the remainder R = T \ V handed to the layer below
};

// The best split of state T: V = T \ R with R a subset of `others` (= T minus its lowest element)
// and |R| >= minRest (the layer below needs at least that many elements; smaller R are +inf there).
// Two enumerations of the same candidates: all submasks of `others` (cheapest when most are
// feasible), or depth-first over the elements moved into V, |others \ R| <= |others| - minRest
// (cheapest when minRest is large and most submasks would be infeasible). Ties keep the first found.
Split bestSplit(std::uint32_t T, std::uint32_t others, int minRest, const std::vector<double>& cost,
                const std::vector<double>& below) {
    Split best;
    auto consider = [&](std::uint32_t r) {
        const double c = cost[T ^ r] + below[r >> 1];
        if (c < best.cost) best = {c, r};
    };
    const int k = std::popcount(others);
    const int maxMoved = k - minRest; // at most this many elements of `others` join V
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
    // Iterative DFS: moved[d] is the set moved into V at depth d, next[d] the next element index to try.
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

std::vector<int> membersOf(std::uint32_t mask) {
    std::vector<int> members;
    for (std::uint32_t bits = mask; bits; bits &= bits - 1) members.push_back(std::countr_zero(bits));
    return members;
}

} // namespace

std::vector<int> ReductionResult::groupOf() const {
    std::size_t n = 0;
    for (const auto& g : best().groups) n += g.size();
    std::vector<int> result(n, -1);
    for (std::size_t g = 0; g < best().groups.size(); ++g)
        for (const int member : best().groups[g])
            result[static_cast<std::size_t>(member)] = static_cast<int>(g);
    return result;
}

ReductionResult reduceVisemes(const ReductionProblem& problem, const ProgressCallback& progress) {
    validate(problem);
    const int n = static_cast<int>(problem.shapes.size());
    const int m = problem.target;
    const std::vector<double> cost = allGroupCosts(centredGram(problem), problem.frequencies);
    if (progress) progress(0.05);

    // Layer q (q = 1..m-1) holds best[q][T] for T a subset of {1..n-1}, indexed by T >> 1.
    const std::uint32_t full = (n == 32) ? ~0u : ((1u << n) - 1u);
    const std::size_t states = std::size_t{1} << (n - 1);
    std::vector<std::vector<double>> best(static_cast<std::size_t>(std::max(m - 1, 1)));
    std::vector<std::vector<std::uint32_t>> rest(best.size()); // remainder T \ V chosen at each state
    best[0].resize(states);
    for (std::size_t t = 0; t < states; ++t) best[0][t] = t ? cost[t << 1] : kInf;

    for (int q = 2; q <= m - 1; ++q) {
        const auto& prev = best[static_cast<std::size_t>(q - 2)];
        auto& cur = best[static_cast<std::size_t>(q - 1)];
        auto& choice = rest[static_cast<std::size_t>(q - 1)];
        cur.assign(states, kInf);
        choice.assign(states, 0);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(1, states, 256), [&](const auto& range) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
                const auto T = static_cast<std::uint32_t>(t << 1);
                if (std::popcount(T) < q) continue;
                const std::uint32_t low = T & (~T + 1);
                const auto [bestCost, bestRest] = bestSplit(T, T ^ low, q - 1, cost, prev);
                cur[t] = bestCost;
                choice[t] = bestRest;
            }
        });
        if (progress) progress(0.05 + 0.9 * (q - 1) / std::max(1, m - 1));
    }

    // Top level: the full set with p groups, p = 1..m; V contains viseme 0.
    ReductionResult result;
    result.curve.resize(static_cast<std::size_t>(m));
    const std::uint32_t others = full ^ 1u;
    for (int p = 1; p <= m; ++p) {
        double bestCost = kInf;
        std::uint32_t bestRest = 0;
        if (p == 1) {
            bestCost = cost[full];
        } else {
            const Split split = bestSplit(full, others, p - 1, cost, best[static_cast<std::size_t>(p - 2)]);
            bestCost = split.cost;
            bestRest = split.rest;
        }
        // Walk the recorded choices down the layers to recover the groups.
        Grouping& grouping = result.curve[static_cast<std::size_t>(p - 1)];
        grouping.cost = bestCost;
        grouping.groups.push_back(membersOf(full ^ bestRest));
        std::uint32_t T = bestRest;
        for (int q = p - 1; q >= 1; --q) {
            const std::uint32_t r = q == 1 ? 0u : rest[static_cast<std::size_t>(q - 1)][T >> 1];
            grouping.groups.push_back(membersOf(T ^ r));
            T = r;
        }
        std::sort(grouping.groups.begin(), grouping.groups.end());
    }
    if (progress) progress(1.0);
    return result;
}

std::vector<Vec3> mergeGroup(std::span<const std::vector<Vec3>> shapes, std::span<const double> frequencies,
                             std::span<const int> members) {
    if (members.empty()) throw std::invalid_argument("mergeGroup: empty group");
    double total = 0;
    for (const int i : members) total += frequencies[static_cast<std::size_t>(i)];
    const std::size_t vertices = shapes[static_cast<std::size_t>(members[0])].size();
    std::vector<Vec3> merged(vertices, Vec3(0, 0, 0));
    for (const int i : members) {
        // Zero-frequency groups fall back to the plain mean: any shape is optimal for them.
        const double w = total > 0 ? frequencies[static_cast<std::size_t>(i)] / total : 1.0 / members.size();
        const auto& shape = shapes[static_cast<std::size_t>(i)];
        for (std::size_t k = 0; k < vertices; ++k) merged[k] += w * shape[k];
    }
    return merged;
}

double dissimilarity(std::span<const Vec3> a, std::span<const Vec3> b, std::span<const double> weights) {
    double sum = 0;
    for (std::size_t k = 0; k < a.size(); ++k) sum += weights[k] * (a[k] - b[k]).sqrnorm();
    return sum;
}

double groupingCost(std::span<const std::vector<Vec3>> shapes, std::span<const double> frequencies,
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

} // namespace vl
