#include "core/reduce/ReductionHeuristics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace vl {

namespace {

constexpr double kNoCost = std::numeric_limits<double>::infinity();

GroupSums sumsOf(const GroupCostModel& model, UnitMask group) {
    GroupSums sums;
    for (UnitMask bits = group; bits; bits &= bits - 1) {
        const int a = std::countr_zero(bits);
        double crossSum = 0;
        for (UnitMask before = group & ((UnitMask{1} << a) - 1); before; before &= before - 1)
            crossSum += model.h(a, std::countr_zero(before));
        sums = sums.plus(model, a, crossSum);
    }
    return sums;
}

UnitMask conflictsOf(const GroupCostModel& model, UnitMask group) {
    UnitMask c = 0;
    for (UnitMask bits = group; bits; bits &= bits - 1)
        c |= model.conflicts[static_cast<std::size_t>(std::countr_zero(bits))];
    return c;
}

// Frequency-weighted Ward: repeatedly merge the two groups whose union raises the cost least,
// c(A u B) - c(A) - c(B) = F_A F_B / (F_A + F_B) |mu_A - mu_B|^2, never merging conflicting groups.
// Records the partition at every p <= m it passes through.
void wardHierarchy(const GroupCostModel& model, int m, std::vector<std::vector<UnitMask>>& best,
                   std::vector<double>& bestCost) {
    const int n = model.size();
    std::vector<UnitMask> mask(static_cast<std::size_t>(n));
    std::vector<GroupSums> sums(static_cast<std::size_t>(n));
    std::vector<double> between(model.cross); // sum of H over pairs across groups i and j
    std::vector<bool> alive(static_cast<std::size_t>(n), true);
    for (int a = 0; a < n; ++a) {
        mask[static_cast<std::size_t>(a)] = UnitMask{1} << a;
        sums[static_cast<std::size_t>(a)] = GroupSums{}.plus(model, a, 0.0);
    }
    auto record = [&](int groups) {
        if (groups > m) return;
        std::vector<UnitMask> partition;
        double cost = 0;
        for (int a = 0; a < n; ++a)
            if (alive[static_cast<std::size_t>(a)]) {
                partition.push_back(mask[static_cast<std::size_t>(a)]);
                cost += sums[static_cast<std::size_t>(a)].cost();
            }
        auto& slot = best[static_cast<std::size_t>(groups - 1)];
        if (cost < bestCost[static_cast<std::size_t>(groups - 1)]) {
            slot = std::move(partition);
            bestCost[static_cast<std::size_t>(groups - 1)] = cost;
        }
    };
    record(n);
    for (int groups = n; groups > 1; --groups) {
        double bestDelta = kNoCost;
        int bi = -1, bj = -1;
        for (int i = 0; i < n; ++i) {
            if (!alive[static_cast<std::size_t>(i)]) continue;
            const UnitMask ci = conflictsOf(model, mask[static_cast<std::size_t>(i)]);
            for (int j = i + 1; j < n; ++j) {
                if (!alive[static_cast<std::size_t>(j)] || (ci & mask[static_cast<std::size_t>(j)])) continue;
                const GroupSums& a = sums[static_cast<std::size_t>(i)];
                const GroupSums& b = sums[static_cast<std::size_t>(j)];
                const GroupSums u = a.merged(b, between[static_cast<std::size_t>(i * n + j)]);
                const double delta = u.cost() - a.cost() - b.cost();
                if (delta < bestDelta) bestDelta = delta, bi = i, bj = j;
            }
        }
        if (bi < 0) return; // every remaining pair conflicts
        auto& a = sums[static_cast<std::size_t>(bi)];
        const auto& b = sums[static_cast<std::size_t>(bj)];
        a = a.merged(b, between[static_cast<std::size_t>(bi * n + bj)]);
        mask[static_cast<std::size_t>(bi)] |= mask[static_cast<std::size_t>(bj)];
        alive[static_cast<std::size_t>(bj)] = false;
        for (int k = 0; k < n; ++k) {
            between[static_cast<std::size_t>(bi * n + k)] += between[static_cast<std::size_t>(bj * n + k)];
            between[static_cast<std::size_t>(k * n + bi)] = between[static_cast<std::size_t>(bi * n + k)];
        }
        record(groups - 1);
    }
}

// k-means++ seeding on the units' centroids (weights F_a), then each unit joins the nearest seed
// group it does not conflict with. Empty result when some unit fits nowhere.
std::vector<UnitMask> seededPartition(const GroupCostModel& model, int p, std::mt19937& rng) {
    const int n = model.size();
    // Squared distance between the centroids of two units; units of weight 0 are anywhere (0). The
    // rest unit stands for the neutral: a unit's distance to it is its rest cost per frequency.
    auto distance = [&](int a, int b) {
        if (a == model.restUnit) std::swap(a, b);
        const double fa = model.weight[static_cast<std::size_t>(a)],
                     fb = model.weight[static_cast<std::size_t>(b)];
        if (b == model.restUnit) return fa > 0 ? model.rest[static_cast<std::size_t>(a)] / fa : 0.0;
        if (!(fa > 0) || !(fb > 0)) return 0.0;
        return std::max(0.0, model.h(a, a) / (fa * fa) + model.h(b, b) / (fb * fb) -
                                 2 * model.h(a, b) / (fa * fb));
    };
    std::vector<int> seeds;
    std::vector<double> nearest(static_cast<std::size_t>(n), kNoCost);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    UnitMask seeded = 0;
    for (int s = 0; s < p; ++s) {
        double total = 0;
        for (int a = 0; a < n; ++a)
            if (!(seeded >> a & 1))
                total += model.weight[static_cast<std::size_t>(a)] *
                         std::min(nearest[static_cast<std::size_t>(a)], 1e300);
        int pick = s == 0 ? model.restUnit : -1; // the rest group is in every partition: seed it
        if (pick < 0 && total > 0 && std::isfinite(total)) {
            double r = uniform(rng) * total;
            for (int a = 0; a < n && pick < 0; ++a) {
                if (seeded >> a & 1) continue;
                r -= model.weight[static_cast<std::size_t>(a)] *
                     std::min(nearest[static_cast<std::size_t>(a)], 1e300);
                if (r <= 0) pick = a;
            }
        }
        if (pick < 0) { // no weight left: any unseeded unit
            std::vector<int> free;
            for (int a = 0; a < n; ++a)
                if (!(seeded >> a & 1)) free.push_back(a);
            pick = free[std::uniform_int_distribution<std::size_t>(0, free.size() - 1)(rng)];
        }
        seeds.push_back(pick);
        seeded |= UnitMask{1} << pick;
        for (int a = 0; a < n; ++a)
            nearest[static_cast<std::size_t>(a)] =
                std::min(nearest[static_cast<std::size_t>(a)], distance(a, pick));
    }
    std::vector<UnitMask> groups;
    for (const int s : seeds) groups.push_back(UnitMask{1} << s);
    for (int a = 0; a < n; ++a) {
        if (seeded >> a & 1) continue;
        int bestGroup = -1;
        double bestDistance = kNoCost;
        for (int g = 0; g < p; ++g) {
            if (model.conflicts[static_cast<std::size_t>(a)] & groups[static_cast<std::size_t>(g)]) continue;
            const double d = distance(a, seeds[static_cast<std::size_t>(g)]);
            if (d < bestDistance) bestDistance = d, bestGroup = g;
        }
        if (bestGroup < 0) return {};
        groups[static_cast<std::size_t>(bestGroup)] |= UnitMask{1} << a;
    }
    return groups;
}

} // namespace

double improveByMoves(const GroupCostModel& model, std::vector<UnitMask>& groups) {
    const int n = model.size();
    const int p = static_cast<int>(groups.size());
    std::vector<int> groupOf(static_cast<std::size_t>(n), -1);
    std::vector<GroupSums> sums(static_cast<std::size_t>(p));
    // crossTo[g * n + a] = sum over members b of group g of H_ab.
    std::vector<double> crossTo(static_cast<std::size_t>(p * n), 0.0);
    for (int g = 0; g < p; ++g) {
        sums[static_cast<std::size_t>(g)] = sumsOf(model, groups[static_cast<std::size_t>(g)]);
        for (UnitMask bits = groups[static_cast<std::size_t>(g)]; bits; bits &= bits - 1) {
            const int b = std::countr_zero(bits);
            groupOf[static_cast<std::size_t>(b)] = g;
            for (int a = 0; a < n; ++a) crossTo[static_cast<std::size_t>(g * n + a)] += model.h(a, b);
        }
    }
    const double tolerance = model.tolerance();
    auto without = [&](int g, int a) {
        return sums[static_cast<std::size_t>(g)].minus(model, a,
                                                       crossTo[static_cast<std::size_t>(g * n + a)]);
    };
    auto with = [&](int g, int a) {
        return sums[static_cast<std::size_t>(g)].plus(model, a, crossTo[static_cast<std::size_t>(g * n + a)]);
    };
    auto move = [&](int a, int to) {
        const int from = groupOf[static_cast<std::size_t>(a)];
        sums[static_cast<std::size_t>(from)] = without(from, a);
        sums[static_cast<std::size_t>(to)] = with(to, a);
        groups[static_cast<std::size_t>(from)] &= ~(UnitMask{1} << a);
        groups[static_cast<std::size_t>(to)] |= UnitMask{1} << a;
        groupOf[static_cast<std::size_t>(a)] = to;
        for (int b = 0; b < n; ++b) {
            crossTo[static_cast<std::size_t>(from * n + b)] -= model.h(a, b);
            crossTo[static_cast<std::size_t>(to * n + b)] += model.h(a, b);
        }
    };
    for (bool improved = true; improved;) {
        improved = false;
        for (int a = 0; a < n; ++a) {
            const int from = groupOf[static_cast<std::size_t>(a)];
            if (std::popcount(groups[static_cast<std::size_t>(from)]) == 1) continue;
            const double leave = without(from, a).cost() - sums[static_cast<std::size_t>(from)].cost();
            double bestDelta = -tolerance;
            int bestTo = -1;
            for (int g = 0; g < p; ++g) {
                if (g == from ||
                    (model.conflicts[static_cast<std::size_t>(a)] & groups[static_cast<std::size_t>(g)]))
                    continue;
                const double delta = leave + with(g, a).cost() - sums[static_cast<std::size_t>(g)].cost();
                if (delta < bestDelta) bestDelta = delta, bestTo = g;
            }
            if (bestTo >= 0) {
                move(a, bestTo);
                improved = true;
            }
        }
        if (improved) continue;
        // No single move helps: try exchanging two units of different groups.
        for (int a = 0; a < n && !improved; ++a) {
            for (int b = a + 1; b < n && !improved; ++b) {
                const int ga = groupOf[static_cast<std::size_t>(a)],
                          gb = groupOf[static_cast<std::size_t>(b)];
                if (ga == gb) continue;
                const UnitMask restA = groups[static_cast<std::size_t>(ga)] & ~(UnitMask{1} << a);
                const UnitMask restB = groups[static_cast<std::size_t>(gb)] & ~(UnitMask{1} << b);
                if ((model.conflicts[static_cast<std::size_t>(b)] & restA) ||
                    (model.conflicts[static_cast<std::size_t>(a)] & restB))
                    continue;
                const double hab = model.h(a, b);
                const GroupSums sa = without(ga, a), sb = without(gb, b);
                const GroupSums na = sa.plus(model, b, crossTo[static_cast<std::size_t>(ga * n + b)] - hab);
                const GroupSums nb = sb.plus(model, a, crossTo[static_cast<std::size_t>(gb * n + a)] - hab);
                const double delta = na.cost() + nb.cost() - sums[static_cast<std::size_t>(ga)].cost() -
                                     sums[static_cast<std::size_t>(gb)].cost();
                if (delta < -tolerance) {
                    move(a, gb);
                    move(b, ga);
                    improved = true;
                }
            }
        }
    }
    return partitionCost(model, groups);
}

std::vector<std::vector<UnitMask>> heuristicPartitions(const GroupCostModel& model, int m,
                                                       const HeuristicOptions& options) {
    const int n = model.size();
    m = std::min(m, n);
    std::vector<std::vector<UnitMask>> best(static_cast<std::size_t>(m));
    std::vector<double> bestCost(static_cast<std::size_t>(m), kNoCost);
    wardHierarchy(model, m, best, bestCost);
    tbb::parallel_for(1, m + 1, [&](int p) {
        auto& slot = best[static_cast<std::size_t>(p - 1)];
        double& slotCost = bestCost[static_cast<std::size_t>(p - 1)];
        if (!slot.empty()) slotCost = improveByMoves(model, slot);
        if (p == 1 || p == n) return; // a single partition exists (if any)
        std::mt19937 rng(options.seed + static_cast<std::uint32_t>(p));
        for (int r = 0; r < options.restarts; ++r) {
            auto groups = seededPartition(model, p, rng);
            if (groups.empty()) continue;
            const double cost = improveByMoves(model, groups);
            if (cost < slotCost - model.tolerance()) slot = std::move(groups), slotCost = cost;
        }
    });
    for (auto& partition : best)
        std::sort(partition.begin(), partition.end(),
                  [](UnitMask a, UnitMask b) { return std::countr_zero(a) < std::countr_zero(b); });
    return best;
}

} // namespace vl
