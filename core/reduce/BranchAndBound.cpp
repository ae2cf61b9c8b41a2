#include "core/reduce/BranchAndBound.h"

#include "core/reduce/SubsetDp.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <numeric>
#include <vector>

namespace vl {

namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();
constexpr int kMaxSearchUnits = 64;
// Subtrees this close to the root of a suffix problem run as parallel tasks, when the suffix is at
// least kParallelMinUnits long (smaller problems finish faster than tasks start).
constexpr int kParallelDepth = 3;
constexpr int kParallelMinUnits = 14;

// The best complete placement found so far, shared by all tasks of one suffix problem.
class Incumbent {
  public:
    explicit Incumbent(double cost) : cost_(cost) {}
    double cost() const { return cost_.load(std::memory_order_relaxed); }
    void offer(double cost, std::span<const std::int8_t> labels) {
        if (cost >= this->cost()) return;
        std::lock_guard lock(mutex_);
        if (cost >= cost_.load()) return;
        labels_.assign(labels.begin(), labels.end());
        cost_.store(cost);
    }
    const std::vector<std::int8_t>& labels() const { return labels_; }

  private:
    std::atomic<double> cost_;
    std::mutex mutex_;
    std::vector<std::int8_t> labels_; // group per position; empty until a placement was offered
};

// A partial placement: groups 0..k-1 and the group of each placed position.
struct State {
    int k = 0;
    double partial = 0; // sum of the groups' costs
    std::array<GroupSums, kMaxSearchUnits> sums{};
    std::array<UnitMask, kMaxSearchUnits> masks{};
    std::array<std::int8_t, kMaxSearchUnits> labels{};
};

// No default member initialisers: a node's child list stays uninitialised until filled (zeroing a
// list sized for 64 groups at every node was a fifth of the search time).
struct Child {
    double bound;
    double delta;
    double crossSum; // sum of H(unit, member) over the group's members (0 for a new group)
    int group;       // k = open a new group
};

class SuffixSearch {
  public:
    // `restOpen`: a suffix problem of the rest-free model, which starts with the rest group open as
    // group 0 holding the rest unit (at rest cost 0 in `model`, see searchPartition).
    SuffixSearch(const GroupCostModel& model, std::span<const int> order, std::span<const double> suffixBound,
                 int first, int groups, int zeroFrom, bool restOpen, const SearchLimits& limits,
                 Incumbent& incumbent)
        : model_(model), order_(order), suffixBound_(suffixBound), first_(first), q_(groups),
          n_(static_cast<int>(order.size())), zeroFrom_(std::max(zeroFrom, first)), restOpen_(restOpen),
          limits_(limits), incumbent_(incumbent), tolerance_(model.tolerance()) {}

    // Lower bound of the parts of the tree left unexplored (+inf when the search completed).
    double run() {
        State s;
        if (restOpen_) {
            s.k = 1;
            s.masks[0] = UnitMask{1} << model_.restUnit;
            s.sums[0] = GroupSums{}.plus(model_, model_.restUnit, 0.0);
            s.partial = s.sums[0].cost();
        }
        return explore(s, first_);
    }

  private:
    // `groups`: the groups the node tries (the work SearchLimits counts).
    bool expired(unsigned groups) {
        constexpr unsigned kCheckEvery = 1024;
        thread_local unsigned work = 0;
        work += groups;
        if (work < kCheckEvery) return false;
        if (limits_.expired(work)) stopped_.store(true, std::memory_order_relaxed);
        work = 0;
        return stopped_.load(std::memory_order_relaxed);
    }

    int children(const State& s, int t, std::array<Child, kMaxSearchUnits + 1>& out) const {
        const int u = order_[static_cast<std::size_t>(t)];
        const int remaining = n_ - t - 1; // units left after this one
        const double rest = suffixBound_[static_cast<std::size_t>(t + 1)];
        int count = 0;
        if (remaining >= q_ - s.k) { // joining keeps enough units to open the missing groups
            for (int g = 0; g < s.k; ++g) {
                const UnitMask members = s.masks[static_cast<std::size_t>(g)];
                if (model_.conflicts[static_cast<std::size_t>(u)] & members) continue;
                const GroupSums& before = s.sums[static_cast<std::size_t>(g)];
                if (before.resting) { // resting costs rest_u whoever rests: no cross terms to sum
                    const double delta = model_.rest[static_cast<std::size_t>(u)];
                    out[static_cast<std::size_t>(count++)] = {s.partial + delta + rest, delta, 0.0, g};
                    continue;
                }
                double crossSum = 0;
                for (UnitMask bits = members; bits; bits &= bits - 1)
                    crossSum += model_.h(u, std::countr_zero(bits));
                const double delta = before.plus(model_, u, crossSum).cost() - before.cost();
                out[static_cast<std::size_t>(count++)] = {s.partial + delta + rest, delta, crossSum, g};
            }
        }
        if (s.k < q_) { // a group of one: c({u}), not 0 for a unit of several visemes or the rest unit
            const double delta = model_.singletonCost(u);
            out[static_cast<std::size_t>(count++)] = {s.partial + delta + rest, delta, 0.0, s.k};
        }
        std::sort(out.begin(), out.begin() + count,
                  [](const Child& a, const Child& b) { return a.bound < b.bound; });
        return count;
    }

    void apply(State& s, int t, int unit, const Child& c) const {
        const auto g = static_cast<std::size_t>(c.group);
        if (c.group == s.k) {
            ++s.k;
            s.sums[g] = GroupSums{};
        }
        s.sums[g] = s.sums[g].plus(model_, unit, c.crossSum);
        s.masks[g] |= UnitMask{1} << unit;
        s.partial += c.delta;
        s.labels[static_cast<std::size_t>(t)] = static_cast<std::int8_t>(c.group);
    }

    static void undo(State& s, int unit, const Child& c, const GroupSums& before) {
        const auto g = static_cast<std::size_t>(c.group);
        s.masks[g] &= ~(UnitMask{1} << unit);
        s.sums[g] = before;
        s.partial -= c.delta;
        if (s.masks[g] == 0) --s.k;
    }

    // Units of weight 0 cost nothing wherever they go: the first placement of the zero-weight tail
    // that respects the conflicts and opens the missing groups completes an optimal leaf.
    bool completeFeasibly(State& s, int t) {
        if (t == n_) return s.k == q_;
        const int u = order_[static_cast<std::size_t>(t)];
        const int remaining = n_ - t - 1;
        for (int g = 0; g <= s.k && g < q_; ++g) {
            const bool opens = g == s.k;
            if (!opens && remaining < q_ - s.k) continue;
            if (model_.conflicts[static_cast<std::size_t>(u)] & s.masks[static_cast<std::size_t>(g)])
                continue;
            if (opens) ++s.k;
            s.masks[static_cast<std::size_t>(g)] |= UnitMask{1} << u;
            s.labels[static_cast<std::size_t>(t)] = static_cast<std::int8_t>(g);
            if (completeFeasibly(s, t + 1)) return true;
            s.masks[static_cast<std::size_t>(g)] &= ~(UnitMask{1} << u);
            if (opens) --s.k;
        }
        return false;
    }

    void leaf(State& s) {
        incumbent_.offer(s.partial,
                         std::span(s.labels.data() + first_, static_cast<std::size_t>(n_ - first_)));
    }

    double explore(State& s, int t) {
        if (t == zeroFrom_) {
            if (s.partial < incumbent_.cost()) {
                State copy = s;
                if (completeFeasibly(copy, t)) leaf(copy);
            }
            return kNoBound;
        }
        if (expired(static_cast<unsigned>(s.k + (s.k < q_ ? 1 : 0))))
            return s.partial + suffixBound_[static_cast<std::size_t>(t)];
        std::array<Child, kMaxSearchUnits + 1> list;
        const int count = children(s, t, list);
        const int u = order_[static_cast<std::size_t>(t)];
        if (t - first_ < kParallelDepth && n_ - first_ >= kParallelMinUnits && count > 1) {
            std::array<double, kMaxSearchUnits + 1> unexplored;
            tbb::parallel_for(0, count, [&](int i) {
                const Child& c = list[static_cast<std::size_t>(i)];
                unexplored[static_cast<std::size_t>(i)] = kNoBound;
                if (c.bound >= incumbent_.cost() - tolerance_) return;
                if (stopped_.load(std::memory_order_relaxed)) {
                    unexplored[static_cast<std::size_t>(i)] = c.bound;
                    return;
                }
                State copy = s;
                apply(copy, t, u, c);
                unexplored[static_cast<std::size_t>(i)] = explore(copy, t + 1);
            });
            return *std::min_element(unexplored.begin(), unexplored.begin() + count);
        }
        double unexplored = kNoBound;
        for (int i = 0; i < count; ++i) {
            const Child& c = list[static_cast<std::size_t>(i)];
            if (c.bound >= incumbent_.cost() - tolerance_) break; // sorted: the rest is pruned too
            if (stopped_.load(std::memory_order_relaxed)) return std::min(unexplored, c.bound);
            const GroupSums before = s.sums[static_cast<std::size_t>(c.group)];
            apply(s, t, u, c);
            if (t + 1 == n_)
                leaf(s);
            else
                unexplored = std::min(unexplored, explore(s, t + 1));
            undo(s, u, c, before);
        }
        return unexplored;
    }

    const GroupCostModel& model_;
    std::span<const int> order_;
    std::span<const double> suffixBound_;
    const int first_, q_, n_, zeroFrom_;
    const bool restOpen_;
    const SearchLimits& limits_;
    Incumbent& incumbent_;
    const double tolerance_;
    std::atomic<bool> stopped_{false};
};

// The order units are placed in. Units of weight 0 go last (they cost nothing, see completeFeasibly).
// The others farthest first: the heaviest unit, then again and again the unit whose cheapest pair with
// the units already ordered costs most (a pair {a, b} costs F_a F_b / (F_a + F_b) |x_a - x_b|^2). Every
// suffix is then a spread-out sample of the set, units no few groups hold cheaply, so its optimum is a
// large share of the whole optimum and the bounds prune early; and the units placed first are those
// whose groups decide the most. On the 40 ARPAbet meshes (area weights) this proves p = 9 in 1.1 s
// where interleaving the groups of the heuristics' partition (the order before) took 53 s.
// Units of weight 0 cost nothing in any group, except the rest unit.
bool placedBySearch(const GroupCostModel& model, int a) {
    return model.weight[static_cast<std::size_t>(a)] > 0 || a == model.restUnit;
}

// Moves the heaviest unit of order[from..] to order[from].
void heaviestTo(const GroupCostModel& model, std::vector<int>& order, std::size_t from) {
    const auto begin = order.begin() + static_cast<std::ptrdiff_t>(from);
    std::swap(*begin, *std::max_element(begin, order.end(), [&](int a, int b) {
        return model.weight[static_cast<std::size_t>(a)] < model.weight[static_cast<std::size_t>(b)];
    }));
}

// The farthest-first order of the keyed model (see above).
std::vector<int> farthestFirst(const GroupCostModel& model) {
    const int n = model.size();
    std::vector<int> order, zero;
    for (int a = 0; a < n; ++a) (placedBySearch(model, a) ? order : zero).push_back(a);
    if (!order.empty()) {
        heaviestTo(model, order, 0);
        // nearest[a]: the cost of a's cheapest pair with an ordered unit; order[0..k) is ordered.
        std::vector<double> nearest(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
        for (std::size_t k = 1; k < order.size(); ++k) {
            const int last = order[k - 1];
            std::size_t farthest = k;
            for (std::size_t i = k; i < order.size(); ++i) {
                const int a = order[i];
                double& d = nearest[static_cast<std::size_t>(a)];
                d = std::min(d, model.cost(UnitMask{1} << a | UnitMask{1} << last));
                if (d > nearest[static_cast<std::size_t>(order[farthest])]) farthest = i;
            }
            std::swap(order[k], order[farthest]);
        }
    }
    order.insert(order.end(), zero.begin(), zero.end());
    return order;
}

// Rest-free: the rest unit goes first, so the rest group's cost is exact from the root on; the others
// keep their places in the keyed model's order, where the rest viseme is an ordinary point (its shape,
// its frequency) that joins the spread-out sample at its turn (a virtual rest unit has weight 0: the
// others' order is the keyed one). Search nodes for p = 1..11 on the ARPAbet meshes (m = 10 keys),
// against farthest first among the other units from the heaviest on: n = 24: 50 k (+12 %), 28: -12 %,
// 32: 706 k (-13 %), 36: 1.96 M (-39 %). Seeding the choice with the resting costs (the rest as a
// point of infinite weight, ordered first), or letting the rest unit enter at its turn by its resting
// costs, did worse at n = 32 (+14 % each).
std::vector<int> placementOrder(const GroupCostModel& model) {
    if (model.restUnit < 0) return farthestFirst(model);
    GroupCostModel keyed = model;
    keyed.restUnit = -1;
    std::vector<int> order = farthestFirst(keyed);
    order.erase(std::find(order.begin(), order.end(), model.restUnit));
    order.insert(order.begin(), model.restUnit);
    return order;
}

// The model of `units` alone: unit i of the result is units[i], with its conflicts among them.
GroupCostModel restrictedModel(const GroupCostModel& model, std::span<const int> units) {
    GroupCostModel sub;
    sub.scale = model.scale;
    for (const int a : units) {
        if (a == model.restUnit) sub.restUnit = static_cast<int>(sub.weight.size());
        sub.weight.push_back(model.weight[static_cast<std::size_t>(a)]);
        sub.self.push_back(model.self[static_cast<std::size_t>(a)]);
        sub.rest.push_back(model.rest[static_cast<std::size_t>(a)]);
        UnitMask conflicts = 0;
        for (std::size_t i = 0; i < units.size(); ++i) {
            sub.cross.push_back(model.h(a, units[i]));
            if (model.conflicts[static_cast<std::size_t>(a)] >> units[i] & 1) conflicts |= UnitMask{1} << i;
        }
        sub.conflicts.push_back(conflicts);
    }
    return sub;
}

// A lower bound for placing `units` in at most p groups: they are cut into blocks of at most
// kBlockUnits consecutive units, each block solved exactly by the subset DP into min(p, |block|) groups
// with the conflicts dropped (a relaxation), and the optima summed. Valid because the cost of a group
// is at least the sum of the costs of its parts, each part about its own mean (the mean minimises a
// part's weighted sum of squares), and more groups never cost more. Also in the rest-free model: the
// rest group's parts cost their rest costs, or less as keyed parts (GroupCostModel.h).
constexpr int kBlockUnits = 14;
double blockBound(const GroupCostModel& model, std::span<const int> units, int p) {
    double total = 0;
    for (std::size_t from = 0; from < units.size(); from += kBlockUnits) {
        const auto block = units.subspan(from, std::min<std::size_t>(kBlockUnits, units.size() - from));
        const int size = static_cast<int>(block.size());
        if (size <= p) continue; // every unit alone: 0 is a bound (the rest unit alone costs rest_a >= 0)
        GroupCostModel sub = restrictedModel(model, block);
        sub.conflicts.assign(block.size(), 0);
        sub.scale = sub.cost((UnitMask{1} << size) - 1);
        const UnitCurve curve = solveSubsetDp(sub, p);
        total += std::max(0.0, curve.back().cost);
    }
    return total;
}

// Units in conflict with every other unit (pinned visemes) are groups of their own in any feasible
// partition, and a group of one costs nothing (the rest unit alone costs its fixed rest_a: the
// search without it is the keyed problem of the others, and canonicalise adds rest_a back).
UnitMask isolatedUnits(const GroupCostModel& model) {
    const int n = model.size();
    const UnitMask all = n == kMaxSearchUnits ? ~UnitMask{0} : (UnitMask{1} << n) - 1;
    UnitMask isolated = 0;
    for (int a = 0; a < n; ++a)
        if ((model.conflicts[static_cast<std::size_t>(a)] | UnitMask{1} << a) == all)
            isolated |= UnitMask{1} << a;
    return isolated;
}

// Groups in canonical order (by lowest unit), the cost recomputed the one shared way, and the bound
// kept at or below it.
void canonicalise(UnitPartition& result, const GroupCostModel& model) {
    if (!result.groups.empty()) {
        std::sort(result.groups.begin(), result.groups.end(),
                  [](UnitMask a, UnitMask b) { return std::countr_zero(a) < std::countr_zero(b); });
        result.cost = partitionCost(model, result.groups);
        if (result.optimal) result.lowerBound = result.cost;
        result.lowerBound = std::min(result.lowerBound, result.cost);
    } else {
        result.cost = kNoBound;
        if (result.optimal) result.lowerBound = kNoBound; // proven: no partition into p groups exists
    }
}

// A placement of the units order[first..n-1]: labels[i] is the group of order[first + i].
struct Placement {
    double cost = kNoBound;
    std::vector<std::int8_t> labels;
};

// The groups of `placement` of order[first..]; `openRest` (the rest unit, or -1) is in group 0 too.
std::vector<UnitMask> groupsOf(const Placement& placement, std::span<const int> order, int first, int groups,
                               int openRest) {
    std::vector<UnitMask> masks(static_cast<std::size_t>(groups), 0);
    if (openRest >= 0) masks[0] |= UnitMask{1} << openRest;
    for (std::size_t i = 0; i < placement.labels.size(); ++i)
        masks[static_cast<std::size_t>(placement.labels[i])] |= UnitMask{1}
                                                                << order[static_cast<std::size_t>(first) + i];
    return masks;
}

// Every unit of order[first..] in a group of its own, after the open rest group (group 0) if any.
Placement eachAlone(const GroupCostModel& model, std::span<const int> order, int first, bool restOpen) {
    Placement out{0, {}};
    for (std::size_t t = static_cast<std::size_t>(first); t < order.size(); ++t) {
        out.cost += model.singletonCost(order[t]);
        out.labels.push_back(
            static_cast<std::int8_t>(t - static_cast<std::size_t>(first) + (restOpen ? 1 : 0)));
    }
    return out;
}

// `previous`, the best placement of order[first + 1..], with unit order[first] added to the group
// where it costs least. `openRest` as in groupsOf; when it is order[first] itself, it is in group 0
// already.
Placement extended(const GroupCostModel& model, std::span<const int> order, int first, int groups,
                   const Placement& previous, int openRest) {
    const int u = order[static_cast<std::size_t>(first)];
    const std::vector<UnitMask> masks = groupsOf(previous, order, first + 1, groups, openRest);
    const double base = partitionCost(model, masks);
    Placement out;
    for (int g = 0; g < groups; ++g) {
        const UnitMask members = masks[static_cast<std::size_t>(g)];
        const bool holds = members >> u & 1;
        if ((model.conflicts[static_cast<std::size_t>(u)] & members) || (u == openRest && !holds)) continue;
        const double cost =
            holds ? base : base - model.cost(members) + model.cost(members | UnitMask{1} << u);
        if (cost < out.cost) {
            out.cost = cost;
            out.labels.assign(1, static_cast<std::int8_t>(g));
            out.labels.insert(out.labels.end(), previous.labels.begin(), previous.labels.end());
        }
    }
    return out;
}

// The caller's partition `start` of all units, as a placement of order[first..] costed in `model`.
// `openRest` as in groupsOf: its group becomes group 0, the open rest group of the suffix problem.
Placement givenPlacement(const GroupCostModel& model, std::span<const int> order, int first,
                         std::span<const UnitMask> start, int openRest) {
    std::vector<UnitMask> groups(start.begin(), start.end());
    if (openRest >= 0)
        std::stable_partition(groups.begin(), groups.end(), [&](UnitMask g) { return g >> openRest & 1; });
    Placement out{partitionCost(model, groups), {}};
    for (std::size_t t = static_cast<std::size_t>(first); t < order.size(); ++t)
        for (std::size_t g = 0; g < groups.size(); ++g)
            if (groups[g] >> order[t] & 1) out.labels.push_back(static_cast<std::int8_t>(g));
    return out;
}

// The model of the rest-free suffix problems: the rest unit's own rest cost left out, as the whole
// problem's placement of the rest unit (order[0]) pays it.
GroupCostModel withoutOwnRest(const GroupCostModel& model) {
    GroupCostModel out = model;
    out.rest[static_cast<std::size_t>(model.restUnit)] = 0;
    return out;
}

UnitPartition searchPartition(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                              const SearchLimits& limits, std::atomic<double>* done,
                              std::atomic<double>* provenBound) {
    const int n = model.size();
    const std::vector<int> order = placementOrder(model);
    int zeroFrom = n;
    while (zeroFrom > 0 && !placedBySearch(model, order[static_cast<std::size_t>(zeroFrom - 1)])) --zeroFrom;
    // Rest-free (order[0] is then the rest unit): the suffix problems of order[first..], first >= 1, are
    // rest-free too, with the rest group open from the start (group 0: the rest unit, at rest cost 0).
    // Their optima bound the suffix of any placement of order[0..first): the rest group's cost
    // sum_{a in R} rest_a (GroupCostModel.h) splits exactly into its parts before and from first, a key
    // group's cost (eq. 4) is at least the sum of its two parts' costs (each part about its own mean,
    // eq. 19), and the parts from first on are a placement of the suffix with the rest group open into
    // at most p groups, which costs at least the optimum with min(p, units) groups (splitting a group
    // never costs more). Keyed suffix problems (the rest group as one more key) bounded the resting
    // units' costs by their keyed costs only, and branch and bound explored about 1.5x the nodes.
    const bool restFree = model.restUnit >= 0;
    const GroupCostModel suffixModel = restFree ? withoutOwnRest(model) : GroupCostModel{};
    const int openRest = restFree ? model.restUnit : -1;

    // suffixBound[t]: lower bound (the optimum once proven) of units order[t..n-1] in min(p, n - t) groups
    // (rest-free, t >= 1: with the open rest group, in min(p, n - t + 1) groups).
    std::vector<double> suffixBound(static_cast<std::size_t>(n + 1), 0.0);
    Placement previous; // best placement of the last suffix solved
    UnitPartition result;
    for (int first = n - 1; first >= 0; --first) {
        const bool restOpen = restFree && first > 0;
        const GroupCostModel& problem = restOpen ? suffixModel : model;
        const int size = n - first + (restOpen ? 1 : 0); // units of the suffix problem
        const int groups = std::min(p, size);
        // Starting bound: the previous suffix's best placement with unit order[first] added.
        Placement initial;
        if (groups == size)
            initial = eachAlone(problem, order, first, restOpen);
        else if (!previous.labels.empty())
            initial = extended(problem, order, first, groups, previous, openRest);
        // The caller's partition of all units: for the whole problem, and in the rest-free model for
        // the suffix of all units but the rest unit (order[0]), which is the whole problem but for
        // the rest unit's own fixed rest cost, and the largest search of the rest-free model.
        if (first <= (restFree ? 1 : 0) && static_cast<int>(start.size()) == p) {
            Placement given = givenPlacement(problem, order, first, start, restOpen ? openRest : -1);
            if (given.cost < initial.cost) initial = std::move(given);
        }
        Incumbent incumbent(initial.cost);
        double unexplored = kNoBound;
        if (groups < size) {
            SuffixSearch search(problem, order, suffixBound, first, groups, zeroFrom, restOpen, limits,
                                incumbent);
            unexplored = search.run();
        }
        const double best = incumbent.cost();
        previous = {best, incumbent.labels().empty() ? std::move(initial.labels) : incumbent.labels()};
        const std::vector<std::int8_t>& labels = previous.labels;
        suffixBound[static_cast<std::size_t>(first)] = std::min(best, unexplored);
        if (done) done->store(static_cast<double>(n - first) / n, std::memory_order_relaxed);
        if (provenBound && unexplored == kNoBound && first > 0) {
            // Same argument as the stopped case below: the solved suffix plus blocks of the rest.
            const double bound =
                std::max(suffixBound[static_cast<std::size_t>(first)] +
                             blockBound(model, std::span(order.data(), static_cast<std::size_t>(first)), p),
                         provenBound->load(std::memory_order_relaxed));
            provenBound->store(bound, std::memory_order_relaxed);
        }
        if (unexplored < kNoBound || first == 0) {
            // Stopped (or finished): report the whole problem. A stopped search proved a bound for
            // the suffix only; the units before it add the optima of small blocks of them (blockBound),
            // or, when larger, all units in blocks.
            result.lowerBound = std::max(0.0, std::min(best, unexplored));
            if (first > 0 && unexplored < kNoBound && limits.tightenStoppedBound)
                result.lowerBound = std::max(
                    result.lowerBound +
                        blockBound(model, std::span(order.data(), static_cast<std::size_t>(first)), p),
                    blockBound(model, order, p));
            result.optimal = unexplored == kNoBound && first == 0;
            if (first == 0 && !labels.empty()) {
                result.groups.assign(static_cast<std::size_t>(p), 0);
                for (int t = 0; t < n; ++t)
                    result.groups[static_cast<std::size_t>(labels[static_cast<std::size_t>(t)])] |=
                        UnitMask{1} << order[static_cast<std::size_t>(t)];
            } else if (static_cast<int>(start.size()) == p) {
                result.groups.assign(start.begin(), start.end());
            }
            break;
        }
    }
    canonicalise(result, model);
    return result;
}

} // namespace

double blockLowerBound(const GroupCostModel& model, int p) {
    return blockBound(model, placementOrder(model), p);
}

UnitPartition branchAndBound(const GroupCostModel& model, int p, std::span<const UnitMask> start,
                             const SearchLimits& limits, std::atomic<double>* done,
                             std::atomic<double>* provenBound) {
    // Isolated units leave the search: the others are placed into p - k groups, and the k groups of one
    // are added back. Exact (they are singletons in every feasible partition, at cost 0), and the
    // search no longer spends a group's worth of branching and weaker suffix bounds on them.
    const int n = model.size();
    const UnitMask isolated = isolatedUnits(model);
    const int k = std::popcount(isolated);
    if (k == 0 || k == n || k >= p) // nothing to take out, or no group left for the others
        return searchPartition(model, p, start, limits, done, provenBound);
    std::vector<int> rest; // original unit of each unit of the smaller problem
    for (int a = 0; a < n; ++a)
        if (!(isolated >> a & 1)) rest.push_back(a);
    const auto restMask = [&](UnitMask original) {
        UnitMask mask = 0;
        for (std::size_t i = 0; i < rest.size(); ++i)
            if (original >> rest[i] & 1) mask |= UnitMask{1} << i;
        return mask;
    };
    const GroupCostModel sub = restrictedModel(model, rest); // the whole problem's scale and tolerances
    std::vector<UnitMask> subStart;
    for (const UnitMask g : start)
        if (!(g & isolated)) subStart.push_back(restMask(g));
    if (static_cast<int>(subStart.size()) != p - k) subStart.clear(); // not of that shape: no start
    UnitPartition result = searchPartition(sub, p - k, subStart, limits, done, provenBound);
    if (result.groups.empty()) return result;
    std::vector<UnitMask> groups;
    for (const UnitMask g : result.groups) {
        UnitMask original = 0;
        for (UnitMask bits = g; bits; bits &= bits - 1)
            original |= UnitMask{1} << rest[static_cast<std::size_t>(std::countr_zero(bits))];
        groups.push_back(original);
    }
    for (UnitMask bits = isolated; bits; bits &= bits - 1) groups.push_back(bits & -bits);
    result.groups = std::move(groups);
    canonicalise(result, model);
    return result;
}

} // namespace vl
