#include "core/reduce/MaxErrorSearch.h"

#include "core/common/Error.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace vl {

namespace {

using Mask = std::uint64_t;

Mask bit(int i) {
    return Mask{1} << i;
}

double squaredDistance(const Vec3& a, const Vec3& b) {
    return (a - b).sqrnorm();
}

class Checker {
  public:
    explicit Checker(const MaxErrorProblem& p) : p_(p), limit2_(p.maxError * p.maxError) {
        for (std::size_t v = 0; v < p.weights.size(); ++v)
            if (p.weights[v] > 0) counted_.push_back(v);
    }

    const std::vector<std::size_t>& counted() const { return counted_; }
    double limit2() const { return limit2_; }

    // Every member within X of the key's frequency-weighted mean (a plain mean when the members'
    // frequencies sum to 0, as mergeGroup does), at every counted vertex.
    bool keyAllowed(Mask visemes) {
        if (std::popcount(visemes) <= 1) return true;
        if (const auto it = memo_.find(visemes); it != memo_.end()) return it->second;
        std::vector<int> members;
        for (Mask m = visemes; m; m &= m - 1) members.push_back(std::countr_zero(m));
        double total = 0;
        for (const int i : members) total += p_.frequencies[static_cast<std::size_t>(i)];
        bool allowed = true;
        for (std::size_t k = 0; allowed && k < counted_.size(); ++k) {
            const std::size_t v = counted_[k];
            Vec3 mean(0, 0, 0);
            for (const int i : members) {
                const double w = total > 0 ? p_.frequencies[static_cast<std::size_t>(i)] / total
                                           : 1.0 / static_cast<double>(members.size());
                mean += w * p_.shapes[static_cast<std::size_t>(i)][v];
            }
            for (const int i : members)
                if (squaredDistance(p_.shapes[static_cast<std::size_t>(i)][v], mean) > limit2_) {
                    allowed = false;
                    break;
                }
        }
        memo_.emplace(visemes, allowed);
        return allowed;
    }

    bool restAllowed(int viseme) const {
        if (p_.rest.empty()) return false;
        for (const std::size_t v : counted_)
            if (squaredDistance(p_.shapes[static_cast<std::size_t>(viseme)][v], p_.rest[v]) > limit2_)
                return false;
        return true;
    }

  private:
    const MaxErrorProblem& p_;
    double limit2_;
    std::vector<std::size_t> counted_;
    std::unordered_map<Mask, bool> memo_;
};

void checkProblem(const MaxErrorProblem& p) {
    if (!std::isfinite(p.maxError) || p.maxError < 0)
        throwInputError("--max-error-mm", "the bound must be a finite distance >= 0");
    const std::size_t n = p.shapes.size();
    if (n == 0 || n > 64 || p.frequencies.size() != n || p.units.unitOf.size() != n)
        throwInputError("max error", "sizes disagree");
    for (std::size_t i = 0; i < n; ++i)
        if (p.shapes[i].size() != p.weights.size()) throwInputError("max error", "vertex counts disagree");
    if (!p.rest.empty() && p.rest.size() != p.weights.size())
        throwInputError("max error", "rest vertex count");
}

// Placement search over units for one number of keys.
class Search {
  public:
    Search(const MaxErrorProblem& p, Checker& checker) : p_(p), checker_(checker) {
        const int units = static_cast<int>(p.units.size());
        std::vector<Mask> visemeMask(static_cast<std::size_t>(units), 0);
        for (int u = 0; u < units; ++u)
            for (const int i : p.units.members[static_cast<std::size_t>(u)])
                visemeMask[static_cast<std::size_t>(u)] |= bit(i);
        // Necessary pairwise condition: members of one key are within 2X of each other everywhere.
        const std::size_t n = p.shapes.size();
        std::vector<Mask> close(n, 0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j) {
                bool ok = true;
                for (const std::size_t v : checker.counted())
                    if (squaredDistance(p.shapes[i][v], p.shapes[j][v]) > 4 * checker.limit2()) {
                        ok = false;
                        break;
                    }
                if (ok) {
                    close[i] |= bit(static_cast<int>(j));
                    close[j] |= bit(static_cast<int>(i));
                }
            }
        Mask mustRest = 0, mustKey = 0;
        for (const int i : p.mustRest) mustRest |= bit(p.units.unitOf[static_cast<std::size_t>(i)]);
        for (const int i : p.mustKey) mustKey |= bit(p.units.unitOf[static_cast<std::size_t>(i)]);
        units_.resize(static_cast<std::size_t>(units));
        for (int u = 0; u < units; ++u) {
            Unit& unit = units_[static_cast<std::size_t>(u)];
            unit.visemes = visemeMask[static_cast<std::size_t>(u)];
            unit.mustRest = (mustRest & bit(u)) != 0;
            unit.restAllowed = !(mustKey & bit(u));
            for (Mask m = unit.visemes; m && unit.restAllowed; m &= m - 1)
                unit.restAllowed = checker.restAllowed(std::countr_zero(m));
            if (unit.mustRest && !unit.restAllowed)
                throwInputError("--max-error-mm",
                                "the rest viseme moves more than the bound: nothing can meet it");
            for (int w = 0; w < units; ++w) {
                bool compatible = w != u && !(p.units.conflicts[static_cast<std::size_t>(u)] & bit(w));
                for (Mask m = unit.visemes; m && compatible; m &= m - 1)
                    compatible = (visemeMask[static_cast<std::size_t>(w)] &
                                  ~close[static_cast<std::size_t>(std::countr_zero(m))]) == 0;
                if (compatible) unit.compatible |= bit(w);
            }
        }
        // Most constrained first: forced rests, then units compatible with the fewest others.
        order_.resize(static_cast<std::size_t>(units));
        std::iota(order_.begin(), order_.end(), 0);
        std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
            const Unit &x = units_[static_cast<std::size_t>(a)], &y = units_[static_cast<std::size_t>(b)];
            if (x.mustRest != y.mustRest) return x.mustRest;
            return std::popcount(x.compatible) < std::popcount(y.compatible);
        });
    }

    // A lower bound on the keys: units that cannot rest and are pairwise incompatible need one each
    // (a greedy clique in the incompatibility graph).
    int lowerBound() const {
        Mask clique = 0;
        int size = 0;
        for (const int u : order_) {
            const Unit& unit = units_[static_cast<std::size_t>(u)];
            if (unit.restAllowed) continue;
            if ((clique & unit.compatible) == 0) {
                clique |= bit(u);
                ++size;
            }
        }
        return std::max(size, 1);
    }

    // Outcome of the search for at most `keys` keys.
    enum class Outcome { Found, Refuted, Stopped };
    Outcome run(int keys, std::uint64_t budget, std::vector<int>& groupOf) {
        keys_ = keys;
        budgetLeft_ = budget;
        stopped_ = false;
        groups_.clear();
        restUnits_ = 0;
        if (place(0)) {
            groupOf.assign(p_.shapes.size(), -1);
            for (std::size_t g = 0; g < groups_.size(); ++g)
                for (Mask m = groups_[g]; m; m &= m - 1)
                    for (const int i : p_.units.members[static_cast<std::size_t>(std::countr_zero(m))])
                        groupOf[static_cast<std::size_t>(i)] = static_cast<int>(g);
            return Outcome::Found;
        }
        return stopped_ ? Outcome::Stopped : Outcome::Refuted;
    }
    std::uint64_t visited() const { return visited_; }

  private:
    struct Unit {
        Mask visemes = 0, compatible = 0;
        bool mustRest = false, restAllowed = false;
    };

    Mask visemesOf(Mask units) const {
        Mask v = 0;
        for (Mask m = units; m; m &= m - 1)
            v |= units_[static_cast<std::size_t>(std::countr_zero(m))].visemes;
        return v;
    }

    // A key no remaining unit can join is final: check it exactly now.
    bool closedKeysAllowed(std::size_t next) {
        Mask remaining = 0;
        for (std::size_t k = next; k < order_.size(); ++k) remaining |= bit(order_[k]);
        for (const Mask g : groups_) {
            Mask joinable = remaining;
            for (Mask m = g; m && joinable; m &= m - 1)
                joinable &= units_[static_cast<std::size_t>(std::countr_zero(m))].compatible;
            if (joinable == 0 && !checker_.keyAllowed(visemesOf(g))) return false;
        }
        return true;
    }

    bool place(std::size_t next) {
        ++visited_;
        if (budgetLeft_ == 0) {
            stopped_ = true;
            return false;
        }
        --budgetLeft_;
        if (!closedKeysAllowed(next)) return false;
        if (next == order_.size()) return true; // every key was closed and checked
        const int u = order_[next];
        const Unit& unit = units_[static_cast<std::size_t>(u)];
        if (unit.restAllowed) {
            restUnits_ |= bit(u);
            if (place(next + 1)) return true;
            restUnits_ &= ~bit(u);
            if (unit.mustRest || stopped_) return false;
        }
        for (std::size_t g = 0; g < groups_.size(); ++g) {
            if ((groups_[g] & ~unit.compatible) != 0) continue;
            groups_[g] |= bit(u);
            if (place(next + 1)) return true;
            groups_[g] &= ~bit(u);
            if (stopped_) return false;
        }
        // A key is only checked once closed: the condition is not hereditary (a member added later
        // moves the mean), so a key that fails now may still pass.
        if (static_cast<int>(groups_.size()) < keys_) {
            groups_.push_back(bit(u));
            if (place(next + 1)) return true;
            groups_.pop_back();
        }
        return false;
    }

    const MaxErrorProblem& p_;
    Checker& checker_;
    std::vector<Unit> units_;
    std::vector<int> order_;
    std::vector<Mask> groups_;
    Mask restUnits_ = 0;
    int keys_ = 0;
    std::uint64_t budgetLeft_ = 0, visited_ = 0;
    bool stopped_ = false;
};

} // namespace

MaxErrorResult smallestKeysWithin(const MaxErrorProblem& problem) {
    checkProblem(problem);
    Checker checker(problem);
    Search search(problem, checker);
    MaxErrorResult result;
    const int units = static_cast<int>(problem.units.size());
    int p = search.lowerBound();
    result.provenLowerBound = p;
    bool refutedBelow = true;
    for (; p <= units; ++p) {
        std::uint64_t left =
            problem.nodeBudget > search.visited() ? problem.nodeBudget - search.visited() : 0;
        const auto outcome = search.run(p, left, result.groupOf);
        if (outcome == Search::Outcome::Found) break;
        if (outcome == Search::Outcome::Stopped) {
            // No proof for p: try the next p with the rest of the budget, or fall back to one key each.
            refutedBelow = false;
            continue;
        }
        if (refutedBelow) result.provenLowerBound = p + 1;
    }
    if (p > units) {
        // Nothing found: either proven impossible (visemes kept together differ too much), or the
        // budget ran out and one key per unit is the fallback when it meets the bound.
        std::vector<int> own(problem.units.unitOf.begin(), problem.units.unitOf.end());
        if (refutedBelow || !withinMaxError(problem, own))
            throwInputError("--max-error-mm", "no grouping keeps every viseme within the bound (visemes kept "
                                              "together differ by more)");
        p = units;
        result.groupOf = std::move(own);
        refutedBelow = false;
    }
    result.keys = p;
    result.certified = refutedBelow;
    result.provenLowerBound = std::min(result.provenLowerBound, p);
    result.nodes = search.visited();
    return result;
}

bool withinMaxError(const MaxErrorProblem& problem, const std::vector<int>& groupOf) {
    checkProblem(problem);
    Checker checker(problem);
    std::vector<Mask> keys;
    for (std::size_t i = 0; i < groupOf.size(); ++i) {
        const int g = groupOf[i];
        if (g < 0) {
            if (!checker.restAllowed(static_cast<int>(i))) return false;
            continue;
        }
        if (keys.size() <= static_cast<std::size_t>(g)) keys.resize(static_cast<std::size_t>(g) + 1, 0);
        keys[static_cast<std::size_t>(g)] |= bit(static_cast<int>(i));
    }
    return std::all_of(keys.begin(), keys.end(), [&](Mask k) { return checker.keyAllowed(k); });
}

std::vector<std::pair<int, int>> maxErrorApartPairs(const MaxErrorProblem& problem) {
    checkProblem(problem);
    Checker checker(problem);
    std::vector<std::pair<int, int>> pairs;
    const std::size_t n = problem.shapes.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (const std::size_t v : checker.counted())
                if (squaredDistance(problem.shapes[i][v], problem.shapes[j][v]) > 4 * checker.limit2()) {
                    pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
                    break;
                }
    return pairs;
}

} // namespace vl
