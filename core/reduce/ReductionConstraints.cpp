#include "core/reduce/ReductionConstraints.h"

#include "core/common/Error.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace vl {

namespace {

constexpr int kMaxConstraintUnits = 64;

std::string describe(std::span<const std::string> names, int i) {
    if (i >= 0 && static_cast<std::size_t>(i) < names.size())
        return "'" + names[static_cast<std::size_t>(i)] + "'";
    return "viseme " + std::to_string(i);
}

int findRoot(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        parent[static_cast<std::size_t>(i)] =
            parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
        i = parent[static_cast<std::size_t>(i)];
    }
    return i;
}

// Exact chromatic number of the conflict graph by backtracking in DSatur order (most constrained
// unit first), bounded by a greedy colouring from above and a greedy clique from below. The search
// stops after `budget` steps and then returns the clique bound: the solvers still decide every
// number of groups exactly, this only skips numbers that are certainly infeasible.
class Colouring {
  public:
    explicit Colouring(std::span<const std::uint64_t> conflicts) : conflicts_(conflicts) {}

    int chromaticNumber() {
        const int n = static_cast<int>(conflicts_.size());
        if (n == 0) return 0;
        best_ = greedyColours();
        const int clique = greedyClique();
        if (clique < best_) {
            std::vector<std::uint64_t> classes;
            std::uint64_t coloured = 0;
            search(coloured, classes);
        }
        return budget_ < 0 ? clique : best_;
    }

  private:
    int greedyColours() const {
        std::vector<std::uint64_t> classes;
        for (std::size_t u = 0; u < conflicts_.size(); ++u) {
            const std::uint64_t bit = std::uint64_t{1} << u;
            auto it = std::find_if(classes.begin(), classes.end(),
                                   [&](std::uint64_t c) { return (c & conflicts_[u]) == 0; });
            if (it == classes.end())
                classes.push_back(bit);
            else
                *it |= bit;
        }
        return static_cast<int>(classes.size());
    }

    int greedyClique() const {
        int best = 1;
        for (std::size_t start = 0; start < conflicts_.size(); ++start) {
            std::uint64_t candidates = conflicts_[start];
            int size = 1;
            while (candidates) {
                // Take the candidate with the most neighbours among the remaining candidates.
                int pick = -1, pickDegree = -1;
                for (std::uint64_t bits = candidates; bits; bits &= bits - 1) {
                    const int v = std::countr_zero(bits);
                    const int degree = std::popcount(conflicts_[static_cast<std::size_t>(v)] & candidates);
                    if (degree > pickDegree) pick = v, pickDegree = degree;
                }
                ++size;
                candidates &= conflicts_[static_cast<std::size_t>(pick)];
            }
            best = std::max(best, size);
        }
        return best;
    }

    void search(std::uint64_t coloured, std::vector<std::uint64_t>& classes) {
        if (--budget_ < 0) return;
        const int n = static_cast<int>(conflicts_.size());
        if (std::popcount(coloured) == n) {
            best_ = std::min(best_, static_cast<int>(classes.size()));
            return;
        }
        // DSatur: the uncoloured unit adjacent to the most colour classes.
        int pick = -1, pickSaturation = -1;
        for (int u = 0; u < n; ++u) {
            if (coloured >> u & 1) continue;
            int saturation = 0;
            for (const std::uint64_t c : classes)
                saturation += (c & conflicts_[static_cast<std::size_t>(u)]) != 0;
            if (saturation > pickSaturation) pick = u, pickSaturation = saturation;
        }
        const std::uint64_t bit = std::uint64_t{1} << pick;
        for (auto& c : classes) {
            if (c & conflicts_[static_cast<std::size_t>(pick)]) continue;
            c |= bit;
            search(coloured | bit, classes);
            c &= ~bit;
            if (budget_ < 0) return;
        }
        if (static_cast<int>(classes.size()) + 1 < best_) {
            classes.push_back(bit);
            search(coloured | bit, classes);
            classes.pop_back();
        }
    }

    std::span<const std::uint64_t> conflicts_;
    int best_ = 0;
    long budget_ = 2'000'000;
};

} // namespace

ReductionConstraints resolveConstraints(const ConstraintNames& names,
                                        std::span<const std::string> visemeNames, std::string_view where) {
    auto indexOf = [&](const std::string& name) {
        const auto it = std::find(visemeNames.begin(), visemeNames.end(), name);
        if (it == visemeNames.end()) {
            std::string known;
            for (const auto& v : visemeNames) known += (known.empty() ? "" : ", ") + v;
            throwInputError(where, "unknown viseme '" + name + "' (the visemes are: " + known + ")");
        }
        return static_cast<int>(it - visemeNames.begin());
    };
    auto pairOf = [&](const std::pair<std::string, std::string>& pair) {
        if (pair.first == pair.second) throwInputError(where, "'" + pair.first + "' is paired with itself");
        return std::pair{indexOf(pair.first), indexOf(pair.second)};
    };
    ReductionConstraints constraints;
    for (const auto& name : names.pinned) constraints.pinned.push_back(indexOf(name));
    for (const auto& pair : names.apart) constraints.apart.push_back(pairOf(pair));
    for (const auto& pair : names.together) constraints.together.push_back(pairOf(pair));
    return constraints;
}

ConstraintNames combineConstraints(const ConstraintNames& a, const ConstraintNames& b) {
    ConstraintNames c = a;
    c.pinned.insert(c.pinned.end(), b.pinned.begin(), b.pinned.end());
    c.apart.insert(c.apart.end(), b.apart.begin(), b.apart.end());
    c.together.insert(c.together.end(), b.together.begin(), b.together.end());
    return c;
}

ConstraintUnits constraintUnits(const ReductionConstraints& constraints, int n,
                                std::span<const std::string> visemeNames, std::string_view where) {
    auto checkIndex = [&](int i) {
        if (i < 0 || i >= n)
            throwInputError(where,
                            "viseme index " + std::to_string(i) + " is outside 0.." + std::to_string(n - 1));
    };
    auto checkPair = [&](const std::pair<int, int>& pair) {
        checkIndex(pair.first);
        checkIndex(pair.second);
        if (pair.first == pair.second)
            throwInputError(where, describe(visemeNames, pair.first) + " is paired with itself");
    };
    for (const int i : constraints.pinned) checkIndex(i);
    for (const auto& pair : constraints.apart) checkPair(pair);
    for (const auto& pair : constraints.together) checkPair(pair);

    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& [a, b] : constraints.together) {
        const int ra = findRoot(parent, a), rb = findRoot(parent, b);
        parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    ConstraintUnits units;
    units.unitOf.assign(static_cast<std::size_t>(n), -1);
    std::vector<int> unitOfRoot(static_cast<std::size_t>(n), -1);
    for (int i = 0; i < n; ++i) { // roots are the smallest member: units come out ordered by it
        const int root = findRoot(parent, i);
        int& unit = unitOfRoot[static_cast<std::size_t>(root)];
        if (unit < 0) {
            unit = static_cast<int>(units.members.size());
            units.members.emplace_back();
        }
        units.unitOf[static_cast<std::size_t>(i)] = unit;
        units.members[static_cast<std::size_t>(unit)].push_back(i);
    }
    const int count = static_cast<int>(units.members.size());
    if (count > kMaxConstraintUnits)
        throwInputError(where, std::to_string(count) + " visemes (after 'together' constraints): at most " +
                                   std::to_string(kMaxConstraintUnits) + " are supported");

    auto partnerOf = [&](int i) {
        for (const int j : units.members[static_cast<std::size_t>(units.unitOf[static_cast<std::size_t>(i)])])
            if (j != i) return j;
        return i;
    };
    units.conflicts.assign(static_cast<std::size_t>(count), 0);
    const std::uint64_t all = count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
    for (const int i : constraints.pinned) {
        const int unit = units.unitOf[static_cast<std::size_t>(i)];
        if (units.members[static_cast<std::size_t>(unit)].size() > 1)
            throwInputError(where, describe(visemeNames, i) +
                                       " is pinned as its own key but kept together with " +
                                       describe(visemeNames, partnerOf(i)) + ": the constraints contradict");
        const std::uint64_t bit = std::uint64_t{1} << unit;
        units.conflicts[static_cast<std::size_t>(unit)] = all & ~bit;
        for (auto& c : units.conflicts) c |= bit;
        units.conflicts[static_cast<std::size_t>(unit)] &= ~bit;
    }
    for (const auto& [a, b] : constraints.apart) {
        const int ua = units.unitOf[static_cast<std::size_t>(a)],
                  ub = units.unitOf[static_cast<std::size_t>(b)];
        if (ua == ub)
            throwInputError(where, describe(visemeNames, a) + " and " + describe(visemeNames, b) +
                                       " are kept apart but also together (through 'together' constraints): "
                                       "the constraints contradict");
        units.conflicts[static_cast<std::size_t>(ua)] |= std::uint64_t{1} << ub;
        units.conflicts[static_cast<std::size_t>(ub)] |= std::uint64_t{1} << ua;
    }
    units.maxGroups = count;
    units.minGroups = Colouring(units.conflicts).chromaticNumber();
    return units;
}

void throwInfeasibleTarget(const ConstraintUnits& units, int groups, std::string_view where) {
    const std::string none =
        "no grouping into " + std::to_string(groups) + " groups satisfies the constraints: ";
    if (groups > units.maxGroups)
        throwInputError(where, none + "the 'together' constraints leave " + std::to_string(units.maxGroups) +
                                   " separable units (choose m <= " + std::to_string(units.maxGroups) + ")");
    if (groups < units.minGroups)
        throwInputError(where, none + "pinned visemes and 'apart' pairs need at least " +
                                   std::to_string(units.minGroups) +
                                   " groups (choose m >= " + std::to_string(units.minGroups) + ")");
    throwInputError(where, none + "pinned visemes and 'apart' pairs need more groups");
}

} // namespace vl
