// Column generation for the set-partitioning LP of ColumnGeneration.h.
//
// Master: min sum_S c(S) x_S  s.t.  sum_{S ni a} x_S = 1 for every unit a,  sum_S x_S = p,  x >= 0,
// over the columns generated so far, solved by CLP (COIN-OR, loaded on first use: ClpLibrary.h) and re-solved
// warm after each round. Pricing (GroupPricing.h): a local search from the basis's columns while it finds
// negative reduced costs, then the exact search, whose minimum gives the round's bound. It stops when no
// group has a negative reduced cost: the master's optimum is then the LP's over all 2^n columns.
#include "core/reduce/ColumnGeneration.h"

#include "core/reduce/ClpLibrary.h"
#include "core/reduce/GroupPricing.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_set>

namespace vl {

namespace {

constexpr int kMaxRounds = 5000;
// Rounds between exact pricings while the local search still finds columns: each exact pricing gives
// a bound, so a time limit leaves one that is not too old.
constexpr int kExactPricingEvery = 25;
constexpr std::uint64_t kPeriodicPricingNodes = 100000;

} // namespace

UnitPartition solveByColumnGeneration(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                                      const SearchLimits& limits, ColumnPool* pool) {
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
    std::unordered_set<UnitMask> known;
    // Columns are queued and handed to CLP together: one call per round (adding them one by one
    // copies the matrix each time, quadratic in the thousands of columns a pool holds).
    std::vector<int> rows;
    std::vector<double> lower, upper, objective;
    std::vector<CoinBigIndex> starts{0};
    auto addColumn = [&](UnitMask set) {
        if (!known.insert(set).second || !model.allowed(set)) return;
        for (UnitMask bits = set; bits; bits &= bits - 1) rows.push_back(std::countr_zero(bits));
        rows.push_back(n);
        starts.push_back(static_cast<CoinBigIndex>(rows.size()));
        lower.push_back(0);
        upper.push_back(std::numeric_limits<double>::max());
        objective.push_back(model.cost(set) / unit);
        columns.push_back(set);
    };
    auto flushColumns = [&] {
        if (objective.empty()) return;
        const std::vector<double> ones(rows.size(), 1.0);
        clp.addColumns(lp.get(), static_cast<int>(objective.size()), lower.data(), upper.data(),
                       objective.data(), starts.data(), rows.data(), ones.data());
        rows.clear(), lower.clear(), upper.clear(), objective.clear();
        starts.assign(1, 0);
    };
    // First columns: the start partition (a feasible master), every unit alone, the pool's.
    for (const UnitMask g : start) addColumn(g);
    for (int a = 0; a < n; ++a) addColumn(UnitMask{1} << a);
    if (pool)
        for (const UnitMask g : *pool) addColumn(g);

    PricingLimits pricing;
    pricing.threshold = -model.tolerance();
    pricing.keep = static_cast<std::size_t>(std::max(2 * n, 32));
    pricing.stop = &limits;
    const double tolerance = model.tolerance();
    std::vector<double> pi(static_cast<std::size_t>(n));
    std::vector<UnitMask> basis;
    for (int round = 0; round < kMaxRounds && !limits.expired(0); ++round) {
        flushColumns();
        clp.primal(lp.get(), 0);                   // from the last round's basis
        if (!clp.isProvenOptimal(lp.get())) break; // numerical trouble: keep the bound reached so far
        const double* duals = clp.dualRowSolution(lp.get());
        for (int a = 0; a < n; ++a) pi[static_cast<std::size_t>(a)] = duals[a] * unit;
        const MasterDuals master{pi, duals[n] * unit};

        // An integral master optimum is a partition: keep it when it beats the best so far.
        const double* x = clp.primalColumnSolution(lp.get());
        std::vector<UnitMask> chosen;
        bool integral = true;
        basis.clear();
        for (std::size_t j = 0; j < columns.size(); ++j) {
            if (x[j] > 1e-6) basis.push_back(columns[j]);
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
            if (disjoint && covered == (n == 64 ? ~UnitMask{0} : (UnitMask{1} << n) - 1)) {
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

        PricedGroups priced = priceGroupsByLocalSearch(model, master, pricing, basis);
        const bool periodic = round % kExactPricingEvery == kExactPricingEvery - 1;
        if (priced.groups.empty() || periodic) {
            PricingLimits exactLimits = pricing;
            // A periodic search is only for a recent bound: it must not cost more than the rounds.
            if (!priced.groups.empty()) exactLimits.nodeLimit = kPeriodicPricingNodes;
            PricedGroups exact = priceGroupsExactly(model, master, exactLimits);
            // The bound of these duals, valid whatever the master's accuracy (ColumnGeneration.h).
            double bound = p * master.mu + p * std::min(0.0, exact.minimumBound);
            for (const double v : pi) bound += v;
            result.lowerBound = std::max(result.lowerBound, bound);
            if (result.cost <= result.lowerBound + tolerance) break; // proved
            if (exact.complete && exact.groups.empty()) break; // the LP is solved; its optimum is fractional
            priced.groups.insert(priced.groups.end(), exact.groups.begin(), exact.groups.end());
        }
        if (priced.groups.empty()) break; // stopped
        for (const PricedGroup& c : priced.groups) addColumn(c.group);
    }
    if (pool) *pool = columns;

    if (result.cost <= result.lowerBound + tolerance) {
        result.optimal = true;
        result.lowerBound = result.cost;
    }
    result.lowerBound = std::min(result.lowerBound, result.cost);
    return result;
}

} // namespace vl
