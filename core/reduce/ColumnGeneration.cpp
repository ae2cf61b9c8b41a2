// Column generation for the set-partitioning LP of ColumnGeneration.h.
//
// Master: min sum_S c(S) x_S  s.t.  sum_{S ni a} x_S = 1 for every unit a,  sum_S x_S = p,  x >= 0,
// over the columns generated so far, solved by CLP (COIN-OR, loaded on first use: ClpLibrary.h) and re-solved
// warm after each round. Pricing (GroupPricing.h): a local search from the basis's columns while it finds
// negative reduced costs, then the exact search, whose minimum gives the round's bound. It stops when no
// group has a negative reduced cost: the master's optimum is then the LP's over all 2^n columns.
//
// Branch and price: when that optimum is fractional and its bound below the best partition, Ryan &
// Foster's branching (PairRules.h) splits on a pair of units, depth first, "together" first. A node's
// columns that break its rules get an upper bound of 0; its pricing runs on the units merged into atoms
// with the apart pairs as conflicts, so its bound is the LP bound of the node. Artificial columns (one
// per row, at a cost far above any partition's) keep every node's master feasible.
#include "core/reduce/ColumnGeneration.h"

#include "core/reduce/ClpLibrary.h"
#include "core/reduce/GroupPricing.h"
#include "core/reduce/PairRules.h"

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
// The artificial columns' cost, in units of the start partition's cost (the master's scale).
constexpr double kArtificialCost = 1e3;

// The master LP in CLP, its columns and their pending additions. Columns 0..n are artificial: one per
// unit row, and one per sign on the count row (mask 0).
class Master {
  public:
    Master(const GroupCostModel& model, int p, double unit)
        : clp_(clpLibrary()), lp_(clp_.newModel(), clp_.deleteModel), model_(model), n_(model.size()),
          unit_(unit) {
        clp_.setLogLevel(lp_.get(), 0);
        clp_.setPrimalTolerance(lp_.get(), 1e-10);
        clp_.setDualTolerance(lp_.get(), 1e-10);
        clp_.resize(lp_.get(), n_ + 1, 0);
        std::vector<double> rowBounds(static_cast<std::size_t>(n_) + 1, 1.0);
        rowBounds[static_cast<std::size_t>(n_)] = p;
        clp_.chgRowLower(lp_.get(), rowBounds.data());
        clp_.chgRowUpper(lp_.get(), rowBounds.data());
        for (int row = 0; row <= n_ + 1; ++row)
            queue(0, {std::min(row, n_)}, row == n_ + 1 ? -1.0 : 1.0, kArtificialCost);
    }

    void add(UnitMask group) {
        if (!known_.insert(group).second || !model_.allowed(group)) return;
        std::vector<int> rows;
        for (UnitMask bits = group; bits; bits &= bits - 1) rows.push_back(std::countr_zero(bits));
        rows.push_back(n_);
        queue(group, rows, 1.0, model_.cost(group) / unit_);
    }

    // Columns that break the node's rules are fixed at 0.
    void apply(const PairRules& rules) {
        flush();
        std::vector<double> upper(columns_.size(), std::numeric_limits<double>::max());
        for (std::size_t j = 0; j < columns_.size(); ++j)
            if (columns_[j] && !rules.admits(columns_[j])) upper[j] = 0;
        clp_.chgColumnUpper(lp_.get(), upper.data());
    }

    bool solve() {
        flush();
        clp_.primal(lp_.get(), 0); // from the last basis
        return clp_.isProvenOptimal(lp_.get());
    }
    const double* duals() const { return clp_.dualRowSolution(lp_.get()); }
    const double* values() const { return clp_.primalColumnSolution(lp_.get()); }
    const std::vector<UnitMask>& columns() const { return columns_; }

  private:
    void queue(UnitMask group, const std::vector<int>& rows, double coefficient, double cost) {
        for (const int r : rows) rows_.push_back(r), elements_.push_back(coefficient);
        starts_.push_back(static_cast<CoinBigIndex>(rows_.size()));
        lower_.push_back(0);
        upper_.push_back(std::numeric_limits<double>::max());
        objective_.push_back(cost);
        columns_.push_back(group);
    }
    // One call for all queued columns: one at a time copies the matrix each time, quadratic in the
    // thousands of columns a pool holds.
    void flush() {
        if (objective_.empty()) return;
        clp_.addColumns(lp_.get(), static_cast<int>(objective_.size()), lower_.data(), upper_.data(),
                        objective_.data(), starts_.data(), rows_.data(), elements_.data());
        rows_.clear(), elements_.clear(), lower_.clear(), upper_.clear(), objective_.clear();
        starts_.assign(1, 0);
    }

    const ClpLibrary& clp_;
    std::unique_ptr<Clp_Simplex, decltype(ClpLibrary::deleteModel)> lp_;
    const GroupCostModel& model_;
    const int n_;
    const double unit_;
    std::vector<UnitMask> columns_;
    std::unordered_set<UnitMask> known_;
    std::vector<int> rows_;
    std::vector<double> elements_, lower_, upper_, objective_;
    std::vector<CoinBigIndex> starts_{0};
};

struct NodeResult {
    double bound = 0;       // no partition obeying the node's rules costs less
    bool converged = false; // the node's LP is solved (no column of negative reduced cost)
    bool integral = false;  // ... and its optimum is a partition
    std::vector<double> x;  // the master's values at the end (fractional optimum: the branching pair)
};

// Column generation at one node of branch and price. Updates `best` with every integral partition
// cheaper than it.
NodeResult solveNode(const GroupCostModel& model, Master& master, const PairRules& rules, int p, double unit,
                     const SearchLimits& limits, UnitPartition& best, ColumnGenerationStats& stats) {
    const int n = model.size();
    const AtomModel atoms = atomModel(model, rules);
    NodeResult node;
    if (!atoms.feasible) {
        node.bound = std::numeric_limits<double>::infinity();
        node.converged = true;
        return node;
    }
    master.apply(rules);
    PricingLimits pricing;
    pricing.threshold = -model.tolerance();
    pricing.keep = static_cast<std::size_t>(std::max(2 * n, 32));
    pricing.stop = &limits;
    const double tolerance = model.tolerance();
    const UnitMask all = n == 64 ? ~UnitMask{0} : (UnitMask{1} << n) - 1;
    std::vector<double> pi(static_cast<std::size_t>(n)), atomPi(atoms.members.size());
    std::vector<UnitMask> basis;
    for (int round = 0; round < kMaxRounds && !limits.expired(0); ++round) {
        ++stats.rounds;
        if (!master.solve()) break; // numerical trouble: keep the bound reached so far
        const double* duals = master.duals();
        for (int a = 0; a < n; ++a) pi[static_cast<std::size_t>(a)] = duals[a] * unit;
        const double mu = duals[n] * unit;
        std::fill(atomPi.begin(), atomPi.end(), 0.0);
        for (std::size_t k = 0; k < atoms.members.size(); ++k)
            for (UnitMask bits = atoms.members[k]; bits; bits &= bits - 1)
                atomPi[k] += pi[static_cast<std::size_t>(std::countr_zero(bits))];
        const MasterDuals atomDuals{atomPi, mu};

        // An integral master optimum is a partition: keep it when it beats the best so far.
        const std::vector<UnitMask>& columns = master.columns();
        const double* x = master.values();
        std::vector<UnitMask> chosen;
        bool integral = true;
        basis.clear();
        for (std::size_t j = 0; j < columns.size(); ++j) {
            if (x[j] <= 1e-6) continue;
            if (!columns[j] || x[j] < 1 - 1e-6) integral = false; // artificial, or fractional
            if (columns[j]) {
                basis.push_back(atoms.atomsOf(columns[j]));
                if (x[j] >= 1 - 1e-6) chosen.push_back(columns[j]);
            }
        }
        node.integral = false;
        if (integral && static_cast<int>(chosen.size()) == p) {
            UnitMask covered = 0;
            bool disjoint = true;
            for (const UnitMask g : chosen) {
                disjoint = disjoint && (covered & g) == 0 && model.allowed(g);
                covered |= g;
            }
            node.integral = disjoint && covered == all;
            if (node.integral) {
                const double cost = partitionCost(model, chosen);
                if (cost < best.cost) {
                    std::sort(chosen.begin(), chosen.end(), [](UnitMask a, UnitMask b) {
                        return std::countr_zero(a) < std::countr_zero(b);
                    });
                    best.groups = std::move(chosen);
                    best.cost = cost;
                }
            }
        }
        if (best.cost <= node.bound + tolerance) break; // nothing better below this node

        PricedGroups priced = priceGroupsByLocalSearch(atoms.atoms, atomDuals, pricing, basis);
        const bool periodic = round % kExactPricingEvery == kExactPricingEvery - 1;
        if (priced.groups.empty() || periodic) {
            PricingLimits exactLimits = pricing;
            // A periodic search is only for a recent bound: it must not cost more than the rounds.
            if (!priced.groups.empty()) exactLimits.nodeLimit = kPeriodicPricingNodes;
            PricedGroups exact = priceGroupsExactly(atoms.atoms, atomDuals, exactLimits);
            // The bound of these duals, valid whatever the master's accuracy (ColumnGeneration.h).
            double bound = p * mu + p * std::min(0.0, exact.minimumBound);
            for (const double v : pi) bound += v;
            node.bound = std::max(node.bound, bound);
            if (best.cost <= node.bound + tolerance) break;
            if (exact.complete && exact.groups.empty()) { // the node's LP is solved
                node.converged = true;
                node.x.assign(x, x + columns.size());
                break;
            }
            priced.groups.insert(priced.groups.end(), exact.groups.begin(), exact.groups.end());
        }
        if (priced.groups.empty()) break; // stopped
        for (const PricedGroup& c : priced.groups) master.add(atoms.unitsOf(c.group));
    }
    return node;
}

// The pair of units whose shared value in the fractional optimum x is nearest 1/2 (Ryan & Foster).
std::pair<int, int> branchingPair(const std::vector<UnitMask>& columns, const std::vector<double>& x, int n) {
    std::vector<double> together(static_cast<std::size_t>(n * n), 0.0);
    for (std::size_t j = 0; j < x.size(); ++j) {
        if (x[j] <= 1e-9 || !columns[j]) continue;
        for (UnitMask a = columns[j]; a; a &= a - 1)
            for (UnitMask b = a & (a - 1); b; b &= b - 1)
                together[static_cast<std::size_t>(std::countr_zero(a) * n + std::countr_zero(b))] += x[j];
    }
    std::pair<int, int> pair{-1, -1};
    double nearest = 0.5 - 1e-6; // only a pair strictly inside (0, 1)
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            if (const double d = std::abs(together[static_cast<std::size_t>(a * n + b)] - 0.5); d < nearest)
                nearest = d, pair = {a, b};
    return pair;
}

} // namespace

UnitPartition solveByColumnGeneration(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                                      const SearchLimits& limits, ColumnPool* pool,
                                      ColumnGenerationStats* stats) {
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
    Master master(model, p, unit);
    // First columns: the start partition, every unit alone, the pool's.
    for (const UnitMask g : start) master.add(g);
    for (int a = 0; a < n; ++a) master.add(UnitMask{1} << a);
    if (pool)
        for (const UnitMask g : *pool) master.add(g);

    // Depth first; each open node carries its parent's bound, valid for all of its partitions.
    struct Open {
        PairRules rules;
        double bound;
    };
    std::vector<Open> open{{PairRules{}, 0.0}};
    ColumnGenerationStats counts;
    const double tolerance = model.tolerance();
    bool root = true;
    double stoppedBound = std::numeric_limits<double>::infinity(); // of a node left unfinished
    while (!open.empty()) {
        Open node = std::move(open.back());
        open.pop_back();
        if (node.bound >= result.cost - tolerance) continue;
        if (limits.expired(0)) {
            stoppedBound = std::min(stoppedBound, node.bound);
            break;
        }
        ++counts.nodes;
        const NodeResult solved = solveNode(model, master, node.rules, p, unit, limits, result, counts);
        const double bound = std::max(node.bound, solved.bound);
        if (root) result.lowerBound = std::min(bound, result.cost);
        root = false;
        if (bound >= result.cost - tolerance || (solved.converged && solved.integral)) continue;
        if (!solved.converged) { // stopped by the limits
            stoppedBound = std::min(stoppedBound, bound);
            break;
        }
        const auto [a, b] = branchingPair(master.columns(), solved.x, n);
        if (a < 0) { // no pair to branch on (numerical): keep the bound
            stoppedBound = std::min(stoppedBound, bound);
            break;
        }
        Open apart{node.rules, bound}, together{node.rules, bound};
        apart.rules.apart.emplace_back(a, b);
        together.rules.together.emplace_back(a, b);
        open.push_back(std::move(apart));
        open.push_back(std::move(together)); // explored first
    }
    if (stats) *stats = counts;
    if (pool) {
        pool->clear();
        for (const UnitMask g : master.columns())
            if (g) pool->push_back(g);
    }
    // Every partition lies below a node pruned by the best cost, or an open or unfinished one.
    double openBound = stoppedBound;
    for (const Open& node : open) openBound = std::min(openBound, node.bound);
    result.lowerBound = std::max(result.lowerBound, std::min(openBound, result.cost));
    if (result.cost <= result.lowerBound + tolerance) {
        result.optimal = true;
        result.lowerBound = result.cost;
    }
    result.lowerBound = std::min(result.lowerBound, result.cost);
    return result;
}

} // namespace vl
