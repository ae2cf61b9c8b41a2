// Exact and heuristic pricing of groups (GroupPricing.h).
#include "core/reduce/GroupPricing.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <set>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace vl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::array<double, 64> filledWith(double value) {
    std::array<double, 64> out;
    out.fill(value);
    return out;
}

UnitMask bitOf(int a) {
    return UnitMask{1} << a;
}

// The groups below the threshold, most negative first: a bounded max-heap on the reduced cost.
class BestGroups {
  public:
    BestGroups(double threshold, std::size_t keep)
        : threshold_(threshold), keep_(std::max<std::size_t>(keep, 1)) {}
    void offer(UnitMask group, double reduced) {
        minimum_ = std::min(minimum_, reduced);
        if (!(reduced < cutoff())) return;
        if (seen_.count(group)) return;
        heap_.push_back({group, reduced});
        seen_.insert(group);
        std::push_heap(heap_.begin(), heap_.end(), worse);
        if (heap_.size() > keep_) {
            std::pop_heap(heap_.begin(), heap_.end(), worse);
            seen_.erase(heap_.back().group);
            heap_.pop_back();
        }
    }
    // A group must beat this to enter.
    double cutoff() const { return heap_.size() < keep_ ? threshold_ : heap_.front().reducedCost; }
    double minimum() const { return minimum_; }
    void noteMinimum(double value) { minimum_ = std::min(minimum_, value); }
    std::vector<PricedGroup> sorted() && {
        std::sort(heap_.begin(), heap_.end(), [](const PricedGroup& a, const PricedGroup& b) {
            return a.reducedCost != b.reducedCost ? a.reducedCost < b.reducedCost : a.group < b.group;
        });
        return std::move(heap_);
    }

  private:
    static bool worse(const PricedGroup& a, const PricedGroup& b) {
        return a.reducedCost != b.reducedCost ? a.reducedCost < b.reducedCost : a.group < b.group;
    }
    double threshold_;
    std::size_t keep_;
    double minimum_ = kInf;
    std::vector<PricedGroup> heap_;
    std::set<UnitMask> seen_;
};

// A group being grown: its sums and, per unit u, x_u = sum over members a of H_ua.
struct Partial {
    UnitMask members = 0;
    double F = 0, D = 0, Q = 0, pi = 0;
    std::array<double, 64> cross{};
};

class ExactSearch {
  public:
    ExactSearch(const GroupCostModel& model, const MasterDuals& duals, const PricingLimits& limits)
        : model_(model), duals_(duals), limits_(limits), best_(limits.threshold, limits.keep) {
        const int n = model.size();
        for (int u = 0; u < n; ++u) {
            const auto i = static_cast<std::size_t>(u);
            const double f = model.weight[i];
            spread_[i] = model.restUnit == u ? 0.0 : std::max(0.0, model.singletonCost(u));
            meanNorm2_[i] = f > 0 ? model.h(u, u) / (f * f) : 0.0;
            keyable_ |= u == model.restUnit ? 0 : bitOf(u);
        }
        linkIntersectingBalls();
    }

    // The rest groups (cheap: a linear cost).
    void searchRest() {
        if (model_.restUnit >= 0) searchRestGroups();
    }

    struct Seed {
        int unit;
        UnitMask undecided;
    };
    // Seeds: the first member of a group in an order from the most promising unit alone, each with
    // the units that may join it.
    std::vector<Seed> seeds() const {
        const int n = model_.size();
        std::vector<int> order;
        for (int u = 0; u < n; ++u)
            if (keyable_ & bitOf(u)) order.push_back(u);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return alone(a) < alone(b); });
        UnitMask later = 0;
        for (const int u : order) later |= bitOf(u);
        std::vector<Seed> out;
        for (const int seed : order) {
            later &= ~bitOf(seed);
            const auto i = static_cast<std::size_t>(seed);
            // A unit with a non-negative term only ever prices as a group of its own (GroupPricing.h).
            out.push_back({seed, (balls_ & bitOf(seed)) ? later & linked_[i] & ~model_.conflicts[i] : 0});
        }
        return out;
    }

    // Every group whose first member is seed.unit.
    void searchSeed(const Seed& seed) {
        Partial start;
        include(start, Partial{}, seed.unit);
        if (stopped_)
            foldUnexplored(start, seed.undecided);
        else
            explore(start, seed.undecided);
    }

    // The groups and bounds of a search over other seeds.
    void absorb(ExactSearch&& other) {
        const double minimum = other.best_.minimum();
        for (const PricedGroup& g : std::move(other.best_).sorted()) best_.offer(g.group, g.reducedCost);
        best_.noteMinimum(minimum);
        stopped_ = stopped_ || other.stopped_;
        nodes_ += other.nodes_;
        unexploredMinimum_ = std::min(unexploredMinimum_, other.unexploredMinimum_);
    }

    PricedGroups finish() {
        PricedGroups out;
        out.complete = !stopped_;
        out.nodes = nodes_;
        out.minimumBound = std::min(best_.minimum(), unexploredMinimum_);
        out.groups = std::move(best_).sorted();
        // The master prices a column by GroupCostModel::cost: report exactly that value.
        for (PricedGroup& g : out.groups) g.reducedCost = reducedCost(model_, duals_, g.group);
        return out;
    }

  private:
    double pi(int u) const { return duals_.pi[static_cast<std::size_t>(u)]; }
    double alone(int u) const { return spread_[static_cast<std::size_t>(u)] - pi(u); }

    // The sums of `from` plus unit u.
    void include(Partial& to, const Partial& from, int u) const {
        const auto i = static_cast<std::size_t>(u);
        to.members = from.members | bitOf(u);
        to.F = from.F + model_.weight[i];
        to.D = from.D + model_.self[i];
        to.Q = from.Q + 2 * from.cross[i] + model_.h(u, u);
        to.pi = from.pi + pi(u);
        const int n = model_.size();
        for (int v = 0; v < n; ++v)
            to.cross[static_cast<std::size_t>(v)] = from.cross[static_cast<std::size_t>(v)] + model_.h(v, u);
    }
    double value(const Partial& g) const {
        const double cost = g.F > 0 ? std::max(0.0, g.D - g.Q / g.F) : 0.0;
        return cost - g.pi - duals_.mu;
    }

    // The lower bound of GroupPricing.h over all groups grown from g by units of `undecided`, and the
    // undecided unit that looks best at the bound's centre distance (-1 when none can lower it).
    double bound(const Partial& g, UnitMask undecided, int& branch) const {
        branch = -1;
        const double base = value(g);
        double constant = 0;     // units whose term does not depend on r
        double bestAtCentre = 0; // for the branching choice
        if (!(g.F > 0)) {        // no centre yet (zero-frequency members): every unit at its best
            for (UnitMask bits = undecided; bits; bits &= bits - 1) {
                const int u = std::countr_zero(bits);
                const double e = alone(u);
                if (e < bestAtCentre) bestAtCentre = e, branch = u;
                constant += std::min(0.0, e);
            }
            if (branch < 0 && undecided) branch = std::countr_zero(undecided);
            return base + constant;
        }
        struct Event {
            double at;
            int unit;
            bool ends;
        };
        std::array<Event, 128> events;
        std::size_t count = 0;
        double A = g.F, B = 0, C = 0; // phi(r) = A r^2 + B r + C on the current interval
        std::array<double, 64> distance{};
        for (UnitMask bits = undecided; bits; bits &= bits - 1) {
            const int u = std::countr_zero(bits);
            const auto i = static_cast<std::size_t>(u);
            const double e = alone(u), f = model_.weight[i];
            if (!(e < 0)) continue; // never below zero: the unit is left out at every r
            if (!(f > 0)) {
                constant += e;
                if (e < bestAtCentre) bestAtCentre = e, branch = u;
                continue;
            }
            const double d2 = meanNorm2_[i] - 2 * g.cross[i] / (f * g.F) + g.Q / (g.F * g.F);
            const double d = std::sqrt(std::max(0.0, d2));
            distance[i] = d;
            const double start = d - std::sqrt(-e / f);
            if (start <= 0) {
                A += f, B -= 2 * f * d, C += f * d * d + e;
            } else {
                events[count++] = {start, u, false};
            }
            events[count++] = {d, u, true};
        }
        std::sort(events.begin(), events.begin() + static_cast<std::ptrdiff_t>(count),
                  [](const Event& a, const Event& b) { return a.at < b.at; });
        double minimum = kInf, argmin = 0, from = 0;
        for (std::size_t k = 0; k <= count; ++k) {
            const double to = k < count ? events[k].at : kInf;
            double r = std::clamp(-B / (2 * A), from, to);
            if (!std::isfinite(r)) r = from;
            if (const double phi = (A * r + B) * r + C; phi < minimum) minimum = phi, argmin = r;
            if (k == count) break;
            const Event& ev = events[k];
            const auto i = static_cast<std::size_t>(ev.unit);
            const double f = model_.weight[i], d = distance[i], e = alone(ev.unit);
            if (ev.ends) { // past m_u: the term stays at its minimum e
                A -= f, B += 2 * f * d, C -= f * d * d;
            } else {
                A += f, B -= 2 * f * d, C += f * d * d + e;
            }
            from = ev.at;
        }
        // Branch on the unit whose term is lowest at the bound's centre distance.
        for (UnitMask bits = undecided; bits; bits &= bits - 1) {
            const int u = std::countr_zero(bits);
            const auto i = static_cast<std::size_t>(u);
            const double f = model_.weight[i], e = alone(u);
            if (!(e < 0) || !(f > 0)) continue;
            const double gap = std::max(0.0, distance[i] - argmin);
            if (const double t = e + f * gap * gap; t < bestAtCentre) bestAtCentre = t, branch = u;
        }
        // None lowers the bound, yet groups grown by them may still beat the cutoff (the `keep` best).
        if (branch < 0 && undecided) branch = std::countr_zero(undecided);
        return base + constant + std::max(minimum, pairMinimum(g, undecided, distance));
    }

    void explore(const Partial& g, UnitMask undecided) {
        best_.offer(g.members, value(g));
        for (;;) {
            ++nodes_;
            stopped_ = stopped_ || (limits_.nodeLimit > 0 && nodes_ > limits_.nodeLimit) ||
                       (limits_.stop && nodes_ % 4096 == 0 && limits_.stop->expired(0));
            if (stopped_) return foldUnexplored(g, undecided);
            int branch = -1;
            const double b = bound(g, undecided, branch);
            if (!(b < best_.cutoff()) || branch < 0) { // nothing below the cutoff, or nothing left
                unexploredMinimum_ = std::min(unexploredMinimum_, b);
                return;
            }
            Partial child;
            include(child, g, branch);
            const auto i = static_cast<std::size_t>(branch);
            explore(child, undecided & ~bitOf(branch) & linked_[i] & ~model_.conflicts[i]);
            undecided &= ~bitOf(branch);
        }
    }

    // The second bound (GroupPricing.h): the centre form's scatter over the points {m_I} + J is
    //   (1/Phi) [ sum_u F_I F_u d_u^2 + sum_{u<v in J} F_u F_v d_uv^2 ],  Phi = F_I + F_J,
    // and d_uv^2 >= (delta_u^2 + delta_v^2) / 2 with delta_u the distance to u's nearest linked unit,
    // so each member u of J adds at least  e_u + F_u (F_I d_u^2 + delta_u^2 (F_J - F_u) / 2) / Phi.
    // For F_J in an interval that is monotone in F_J (a Moebius function): the lower end value bounds
    // it, and only units with F_u below the interval's top can be members. Exact for J of one unit.
    double pairMinimum(const Partial& g, UnitMask undecided, const std::array<double, 64>& distance) const {
        constexpr int kSteps = 8;
        double total = 0;
        for (UnitMask bits = undecided; bits; bits &= bits - 1) {
            const int u = std::countr_zero(bits);
            if (alone(u) < 0) total += model_.weight[static_cast<std::size_t>(u)];
        }
        double best = 0;
        for (int k = 0; k < kSteps; ++k) {
            const double from = total * k / kSteps, to = total * (k + 1) / kSteps;
            double sum = 0;
            for (UnitMask bits = undecided; bits; bits &= bits - 1) {
                const int u = std::countr_zero(bits);
                const auto i = static_cast<std::size_t>(u);
                const double f = model_.weight[i], e = alone(u);
                if (!(e < 0) || !(f > 0) || f > to * (1 + 1e-12)) continue;
                const double d2 = distance[i] * distance[i], half = 0.5 * nearest2_[i];
                // Without a partner, u joins alone: F_J = F_u.
                auto scatter = [&](double fj) {
                    return std::isfinite(half) ? (g.F * d2 + half * (fj - f)) / (g.F + fj)
                                               : g.F * d2 / (g.F + f);
                };
                sum += std::min(0.0, e + f * std::min(scatter(std::max(from, f)), scatter(to)));
            }
            best = std::min(best, sum);
        }
        return best;
    }

    // Units whose term c_u - pi_u + F_u |m_u - z|^2 is negative for some centre z hold a ball
    // |m_u - z| < rho_u = sqrt((pi_u - c_u) / F_u) (everywhere for F_u = 0). Some optimal group of two
    // or more units has every member's term negative at its own centre (a member with a non-negative
    // term can leave without raising the reduced cost), so its balls share a point and intersect
    // pairwise: the search grows groups only by units linked to every member.
    void linkIntersectingBalls() {
        const int n = model_.size();
        std::array<double, 64> radius{};
        for (int u = 0; u < n; ++u)
            if ((keyable_ & bitOf(u)) && alone(u) < 0) {
                balls_ |= bitOf(u);
                const double f = model_.weight[static_cast<std::size_t>(u)];
                radius[static_cast<std::size_t>(u)] = f > 0 ? std::sqrt(-alone(u) / f) : kInf;
            }
        for (int a = 0; a < n; ++a) {
            const auto i = static_cast<std::size_t>(a);
            if (!(balls_ & bitOf(a))) continue;
            for (int b = 0; b < n; ++b) {
                const auto j = static_cast<std::size_t>(b);
                if (a == b || !(balls_ & bitOf(b))) continue;
                const double fa = model_.weight[i], fb = model_.weight[j];
                bool linked = !(fa > 0) || !(fb > 0);
                if (!linked) {
                    const double d2 = meanNorm2_[i] - 2 * model_.h(a, b) / (fa * fb) + meanNorm2_[j];
                    const double reach = radius[i] + radius[j];
                    // A relative margin: rounding must never cut a link (that would cut a column).
                    linked = d2 <= reach * reach * (1 + 1e-9) + 1e-12 * (meanNorm2_[i] + meanNorm2_[j]);
                }
                if (!linked) continue;
                linked_[i] |= bitOf(b);
                if (fa > 0 && fb > 0) { // a partner that adds scatter: the nearest bounds every pair
                    const double d2 = meanNorm2_[i] - 2 * model_.h(a, b) / (fa * fb) + meanNorm2_[j];
                    nearest2_[i] = std::min(nearest2_[i], std::max(0.0, d2) * (1 - 1e-9));
                }
            }
        }
    }

    void foldUnexplored(const Partial& g, UnitMask undecided) {
        int branch = -1;
        unexploredMinimum_ = std::min(unexploredMinimum_, std::min(value(g), bound(g, undecided, branch)));
    }

    // The rest group: restUnit plus any units that do not conflict; r = sum (rest_u - pi_u) - mu.
    void searchRestGroups() {
        const int restUnit = model_.restUnit;
        auto term = [&](int u) { return model_.rest[static_cast<std::size_t>(u)] - pi(u); };
        const UnitMask undecided = ~bitOf(restUnit) & ~model_.conflicts[static_cast<std::size_t>(restUnit)] &
                                   (model_.size() == 64 ? ~UnitMask{0} : bitOf(model_.size()) - 1);
        restExplore(bitOf(restUnit), term(restUnit) - duals_.mu, undecided, term);
    }
    template <class Term>
    void restExplore(UnitMask members, double value, UnitMask undecided, const Term& term) {
        best_.offer(members, value);
        for (;;) {
            double bound = value;
            int branch = -1;
            double lowest = 0;
            for (UnitMask bits = undecided; bits; bits &= bits - 1) {
                const int u = std::countr_zero(bits);
                const double t = term(u);
                bound += std::min(0.0, t);
                if (t < lowest) lowest = t, branch = u;
            }
            if (branch < 0 && undecided) branch = std::countr_zero(undecided);
            if (!(bound < best_.cutoff()) || branch < 0) {
                unexploredMinimum_ = std::min(unexploredMinimum_, bound);
                return;
            }
            restExplore(members | bitOf(branch), value + term(branch),
                        undecided & ~bitOf(branch) & ~model_.conflicts[static_cast<std::size_t>(branch)],
                        term);
            undecided &= ~bitOf(branch);
        }
    }

    const GroupCostModel& model_;
    const MasterDuals& duals_;
    const PricingLimits& limits_;
    BestGroups best_;
    std::array<double, 64> spread_{}, meanNorm2_{};
    UnitMask keyable_ = 0;
    UnitMask balls_ = 0;                                 // units whose term can be negative
    std::array<UnitMask, 64> linked_{};                  // their balls intersect
    std::array<double, 64> nearest2_ = filledWith(kInf); // squared distance to the nearest linked unit
    std::uint64_t nodes_ = 0;
    bool stopped_ = false;
    double unexploredMinimum_ = kInf;
};

} // namespace

double reducedCost(const GroupCostModel& model, const MasterDuals& duals, UnitMask group) {
    double value = model.cost(group) - duals.mu;
    for (UnitMask bits = group; bits; bits &= bits - 1)
        value -= duals.pi[static_cast<std::size_t>(std::countr_zero(bits))];
    return value;
}

PricedGroups priceGroupsExactly(const GroupCostModel& model, const MasterDuals& duals,
                                const PricingLimits& limits) {
    ExactSearch all(model, duals, limits);
    all.searchRest();
    // Each seed's search on its own (own cutoff, own share of the node limit), merged in seed order:
    // the result does not depend on the thread count or the scheduling.
    const auto seeds = all.seeds();
    PricingLimits each = limits;
    if (limits.nodeLimit > 0)
        each.nodeLimit =
            std::max<std::uint64_t>(1, limits.nodeLimit / std::max<std::size_t>(1, seeds.size()));
    std::vector<std::optional<ExactSearch>> searches(seeds.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, seeds.size(), 1), [&](const auto& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            searches[k].emplace(model, duals, each);
            searches[k]->searchSeed(seeds[k]);
        }
    });
    for (auto& search : searches) all.absorb(std::move(*search));
    return all.finish();
}

PricedGroups priceGroupsByLocalSearch(const GroupCostModel& model, const MasterDuals& duals,
                                      const PricingLimits& limits, std::span<const UnitMask> seeds) {
    const int n = model.size();
    // The rest groups exactly (linear cost), the keyed groups by local search.
    ExactSearch restSearch(model, duals, limits);
    restSearch.searchRest();
    PricedGroups rest = restSearch.finish();
    BestGroups best(limits.threshold, limits.keep);
    for (const PricedGroup& g : rest.groups) best.offer(g.group, g.reducedCost); // already re-priced
    std::vector<UnitMask> starts;
    for (int u = 0; u < n; ++u)
        if (u != model.restUnit) starts.push_back(bitOf(u));
    for (const UnitMask s : seeds)
        if (model.restUnit < 0 || !(s >> model.restUnit & 1)) starts.push_back(s);
    std::vector<double> cross(static_cast<std::size_t>(n));
    for (const UnitMask start : starts) {
        UnitMask members = 0;
        GroupSums sums;
        double pi = 0;
        std::fill(cross.begin(), cross.end(), 0.0);
        auto add = [&](int u, double sign) {
            const auto i = static_cast<std::size_t>(u);
            sums = sign > 0 ? sums.plus(model, u, cross[i]) : sums.minus(model, u, cross[i]);
            pi += sign * duals.pi[i];
            for (int v = 0; v < n; ++v) cross[static_cast<std::size_t>(v)] += sign * model.h(v, u);
            members ^= bitOf(u);
        };
        for (UnitMask bits = start; bits; bits &= bits - 1) add(std::countr_zero(bits), 1);
        double value = sums.cost() - pi - duals.mu;
        for (int step = 0; step < 4 * n; ++step) {
            int move = -1;
            double moveValue = value - 1e-12 * std::abs(value);
            for (int u = 0; u < n; ++u) {
                const auto i = static_cast<std::size_t>(u);
                if (u == model.restUnit) continue;
                const bool in = members >> u & 1;
                if (in && members == bitOf(u)) continue; // keep the group non-empty
                if (!in && (model.conflicts[i] & members)) continue;
                const GroupSums next = in ? sums.minus(model, u, cross[i]) : sums.plus(model, u, cross[i]);
                const double v = next.cost() - (in ? pi - duals.pi[i] : pi + duals.pi[i]) - duals.mu;
                if (v < moveValue) moveValue = v, move = u;
            }
            if (move < 0) break;
            add(move, (members >> move & 1) ? -1.0 : 1.0);
            value = sums.cost() - pi - duals.mu;
        }
        // The master prices the column by GroupCostModel::cost: report that value.
        best.offer(members, reducedCost(model, duals, members));
    }
    PricedGroups out;
    out.groups = std::move(best).sorted();
    return out;
}

} // namespace vl
