// Column generation for the set-partitioning LP of ColumnGeneration.h.
//
// Master: min sum_S c(S) x_S  s.t.  sum_{S ni a} x_S = 1 for every unit a,  sum_S x_S = p,  x >= 0,
// over the columns generated so far, solved by CLP (COIN-OR, loaded on first use: ClpLibrary.h) and re-solved
// warm after each round. Pricing: the reduced cost c(S) - pi(S) - mu of every one of the 2^n sets, with pi(S)
// from two tables (low and high bits of S), in parallel; the most negative sets become columns. It stops when
// no set has a negative reduced cost: the master's optimum is then the LP's over all 2^n columns.
#include "core/reduce/ColumnGeneration.h"

#include "core/reduce/ClpLibrary.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>

namespace vl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxRounds = 2000;

struct Candidate {
    double reduced;
    UnitMask set;
};

// The sets of negative reduced cost worth adding (at most `keep`, the most negative) and the exact
// minimum reduced cost over all sets but the empty one.
struct Pricing {
    std::vector<Candidate> columns;
    double minimum = kInf;
};

Pricing price(std::span<const double> groupCosts, int n, std::span<const double> pi, double mu,
              double threshold, std::size_t keep) {
    const int lowBits = std::min(n, 12);
    const std::size_t lowCount = std::size_t{1} << lowBits, highCount = std::size_t{1} << (n - lowBits);
    auto subsetSums = [&](int from, int bits) { // sums[s] = sum of pi over the bits of s, shifted by `from`
        std::vector<double> sums(std::size_t{1} << bits, 0.0);
        for (int b = 0; b < bits; ++b)
            for (std::size_t s = 0; s < (std::size_t{1} << b); ++s)
                sums[s | (std::size_t{1} << b)] = sums[s] + pi[static_cast<std::size_t>(from + b)];
        return sums;
    };
    const std::vector<double> low = subsetSums(0, lowBits), high = subsetSums(lowBits, n - lowBits);
    tbb::combinable<Pricing> local;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, highCount, 1), [&](const auto& range) {
        Pricing& mine = local.local();
        for (std::size_t h = range.begin(); h != range.end(); ++h) {
            const double* costs = groupCosts.data() + (h << lowBits);
            const double offset = high[h] + mu;
            double blockMin = kInf;
            for (std::size_t l = 0; l < lowCount; ++l)
                blockMin = std::min(blockMin, costs[l] - (low[l] + offset));
            if (h == 0) { // the empty set is not a column
                blockMin = kInf;
                for (std::size_t l = 1; l < lowCount; ++l)
                    blockMin = std::min(blockMin, costs[l] - (low[l] + offset));
            }
            mine.minimum = std::min(mine.minimum, blockMin);
            if (!(blockMin < threshold)) continue;
            for (std::size_t l = h == 0 ? 1 : 0; l < lowCount; ++l)
                if (const double r = costs[l] - (low[l] + offset); r < threshold)
                    mine.columns.push_back({r, static_cast<UnitMask>((h << lowBits) | l)});
            if (mine.columns.size() > 8 * keep) { // keep memory bounded on the first rounds
                std::nth_element(
                    mine.columns.begin(), mine.columns.begin() + static_cast<std::ptrdiff_t>(keep),
                    mine.columns.end(),
                    [](const Candidate& a, const Candidate& b) { return a.reduced < b.reduced; });
                mine.columns.resize(keep);
            }
        }
    });
    Pricing all;
    local.combine_each([&](const Pricing& part) {
        all.minimum = std::min(all.minimum, part.minimum);
        all.columns.insert(all.columns.end(), part.columns.begin(), part.columns.end());
    });
    // A fixed order (reduced cost, then set), so the run does not depend on the thread count.
    std::sort(all.columns.begin(), all.columns.end(), [](const Candidate& a, const Candidate& b) {
        return a.reduced != b.reduced ? a.reduced < b.reduced : a.set < b.set;
    });
    if (all.columns.size() > keep) all.columns.resize(keep);
    return all;
}

} // namespace

UnitPartition solveByColumnGeneration(const GroupCostModel& model, std::span<const double> groupCosts, int p,
                                      std::span<const UnitMask> start, const SearchLimits& limits) {
    const int n = model.size();
    UnitPartition result;
    result.groups.assign(start.begin(), start.end());
    result.cost = partitionCost(model, result.groups);
    result.lowerBound = 0;
    if (p == 1 || p == n) { // one group, or every unit alone: nothing to choose
        result.lowerBound = result.cost;
        result.optimal = true;
        return result;
    }

    // The master works on costs scaled so that the start partition costs 1: CLP's tolerances are
    // absolute, and viseme costs range from 1e-6 to 1e3 with the units of the meshes.
    const double unit = result.cost > 0 ? result.cost : 1.0;
    const ClpLibrary& clp = clpLibrary();
    const std::unique_ptr<Clp_Simplex, decltype(clp.deleteModel)> lp(clp.newModel(), clp.deleteModel);
    clp.setLogLevel(lp.get(), 0);
    clp.setPrimalTolerance(lp.get(), 1e-10);
    clp.setDualTolerance(lp.get(), 1e-10);
    clp.resize(lp.get(), n + 1, 0);
    std::vector<double> rowBounds(static_cast<std::size_t>(n) + 1, 1.0);
    rowBounds[static_cast<std::size_t>(n)] = p;
    clp.chgRowLower(lp.get(), rowBounds.data());
    clp.chgRowUpper(lp.get(), rowBounds.data());
    std::vector<UnitMask> columns;
    std::vector<int> rows;
    std::vector<double> ones;
    auto addColumn = [&](UnitMask set) {
        rows.clear();
        for (UnitMask bits = set; bits; bits &= bits - 1) rows.push_back(std::countr_zero(bits));
        rows.push_back(n);
        ones.assign(rows.size(), 1.0);
        const double lower = 0, upper = std::numeric_limits<double>::max(),
                     objective = groupCosts[static_cast<std::size_t>(set)] / unit;
        const CoinBigIndex starts[2] = {0, static_cast<CoinBigIndex>(rows.size())};
        clp.addColumns(lp.get(), 1, &lower, &upper, &objective, starts, rows.data(), ones.data());
        columns.push_back(set);
    };
    // First columns: the start partition (a feasible master) and every unit alone.
    for (const UnitMask g : start) addColumn(g);
    for (int a = 0; a < n; ++a)
        if (std::find(start.begin(), start.end(), UnitMask{1} << a) == start.end())
            addColumn(UnitMask{1} << a);

    const std::size_t keep = static_cast<std::size_t>(std::max(2 * n, 32));
    const double tolerance = model.tolerance();
    std::vector<double> pi(static_cast<std::size_t>(n));
    for (int round = 0; round < kMaxRounds && !limits.expired(0); ++round) {
        clp.primal(lp.get(), 0);                   // from the last round's basis
        if (!clp.isProvenOptimal(lp.get())) break; // numerical trouble: keep the bound reached so far
        const double* duals = clp.dualRowSolution(lp.get());
        for (int a = 0; a < n; ++a) pi[static_cast<std::size_t>(a)] = duals[a] * unit;
        const double mu = duals[n] * unit;
        const Pricing priced = price(groupCosts, n, pi, mu, -tolerance, keep);
        // The bound of these duals, valid whatever the master's accuracy (ColumnGeneration.h).
        double bound = p * mu + p * std::min(0.0, priced.minimum);
        for (const double v : pi) bound += v;
        result.lowerBound = std::max(result.lowerBound, bound);

        // An integral master optimum is a partition: keep it when it beats the best so far.
        const double* x = clp.primalColumnSolution(lp.get());
        std::vector<UnitMask> chosen;
        bool integral = true;
        for (std::size_t j = 0; j < columns.size() && integral; ++j) {
            if (x[j] > 1 - 1e-6)
                chosen.push_back(columns[j]);
            else if (x[j] > 1e-6)
                integral = false;
        }
        if (integral && static_cast<int>(chosen.size()) == p) {
            UnitMask covered = 0;
            bool disjoint = true;
            for (const UnitMask g : chosen) {
                disjoint = disjoint && (covered & g) == 0 && model.allowed(g);
                covered |= g;
            }
            if (disjoint && covered == (UnitMask{1} << n) - 1) {
                const double cost = partitionCost(model, chosen);
                if (cost < result.cost) {
                    std::sort(chosen.begin(), chosen.end(), [](UnitMask a, UnitMask b) {
                        return std::countr_zero(a) < std::countr_zero(b);
                    });
                    result.groups = std::move(chosen);
                    result.cost = cost;
                }
            }
        }
        if (result.cost <= result.lowerBound + tolerance) break; // proved
        if (priced.columns.empty()) break; // the LP is solved; its optimum is fractional
        for (const Candidate& c : priced.columns) addColumn(c.set);
    }

    if (result.cost <= result.lowerBound + tolerance) {
        result.optimal = true;
        result.lowerBound = result.cost;
    }
    result.lowerBound = std::min(result.lowerBound, result.cost);
    return result;
}

} // namespace vl
