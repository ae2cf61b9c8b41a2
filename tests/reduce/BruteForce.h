#pragma once
// The slow, obvious reference for the reduction: every set partition of n items into exactly m blocks
// (restricted growth strings), checked against the constraints one by one and evaluated directly from
// the meshes (groupingCost), with no Gram matrix, no units and no bounds.
#include "RandomShapes.h"

#include "core/reduce/Reduction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <span>

namespace vl::test {

// A few random pins, apart and together pairs among n >= 2 items (possibly contradictory).
inline ReductionConstraints randomConstraints(std::mt19937& rng, int n) {
    std::uniform_int_distribution<int> item(0, n - 1), count(0, 3);
    auto pair = [&] {
        const int a = item(rng);
        int b = item(rng);
        while (b == a) b = item(rng);
        return std::pair{a, b};
    };
    ReductionConstraints c;
    for (int k = count(rng) / 2; k > 0; --k) c.pinned.push_back(item(rng));
    for (int k = count(rng); k > 0; --k) c.apart.push_back(pair());
    for (int k = count(rng); k > 0; --k) c.together.push_back(pair());
    return c;
}

inline bool satisfies(const std::vector<int>& block, const ReductionConstraints& c) {
    for (const int i : c.pinned)
        for (std::size_t j = 0; j < block.size(); ++j)
            if (static_cast<int>(j) != i && block[j] == block[static_cast<std::size_t>(i)]) return false;
    for (const auto& [a, b] : c.apart)
        if (block[static_cast<std::size_t>(a)] == block[static_cast<std::size_t>(b)]) return false;
    for (const auto& [a, b] : c.together)
        if (block[static_cast<std::size_t>(a)] != block[static_cast<std::size_t>(b)]) return false;
    return true;
}

// The optimal cost of a grouping into exactly m groups satisfying `c`, or nullopt when none does.
inline std::optional<double> bruteForceBest(const RandomInstance& inst, int m,
                                            const ReductionConstraints& c = {}) {
    const int n = static_cast<int>(inst.shapes.size());
    std::vector<int> block(static_cast<std::size_t>(n), 0);
    double best = std::numeric_limits<double>::infinity();
    std::function<void(int, int)> recurse = [&](int i, int used) {
        if (n - i < m - used) return; // not enough items left to open the missing blocks
        if (i == n) {
            if (used != m || !satisfies(block, c)) return;
            std::vector<std::vector<int>> groups(static_cast<std::size_t>(m));
            for (int k = 0; k < n; ++k)
                groups[static_cast<std::size_t>(block[static_cast<std::size_t>(k)])].push_back(k);
            best = std::min(best, groupingCost(inst.shapes, inst.frequencies, inst.weights, groups));
            return;
        }
        for (int b = 0; b <= used && b < m; ++b) {
            block[static_cast<std::size_t>(i)] = b;
            recurse(i + 1, std::max(used, b + 1));
        }
    };
    recurse(0, 0);
    if (best == std::numeric_limits<double>::infinity()) return std::nullopt;
    return best;
}

// The rest-free model's reference (Reduction.h, RestPose): every assignment of each viseme to one of
// p keys (restricted growth, all p used) or to the rest, the rest viseme always resting, evaluated
// from the meshes by restFreeGroupingCost. Constraints: the rest is one more group (apart visemes do
// not both rest, together ones rest together), and a pinned viseme is a key of its own (or the rest
// alone when it is the rest viseme). Returns the optimal cost, or nullopt when nothing is feasible.
inline std::optional<double> bruteForceRestFree(const RandomInstance& inst, int p, int restViseme,
                                                std::span<const Vec3> neutral,
                                                const ReductionConstraints& c = {}) {
    const int n = static_cast<int>(inst.shapes.size());
    const int restLabel = p; // labels 0..p-1: keys
    std::vector<int> label(static_cast<std::size_t>(n), 0);
    double best = std::numeric_limits<double>::infinity();
    std::function<void(int, int)> recurse = [&](int i, int used) {
        if (i == n) {
            if (used != p || !satisfies(label, c)) return;
            for (const int pinned : c.pinned)
                if (pinned != restViseme && label[static_cast<std::size_t>(pinned)] == restLabel) return;
            std::vector<std::vector<int>> groups(static_cast<std::size_t>(p));
            std::vector<int> resting;
            for (int k = 0; k < n; ++k) {
                const int l = label[static_cast<std::size_t>(k)];
                (l == restLabel ? resting : groups[static_cast<std::size_t>(l)]).push_back(k);
            }
            best = std::min(best, restFreeGroupingCost(inst.shapes, inst.frequencies, inst.weights, groups,
                                                       resting, neutral));
            return;
        }
        label[static_cast<std::size_t>(i)] = restLabel;
        recurse(i + 1, used);
        if (i == restViseme) return;
        for (int b = 0; b <= used && b < p; ++b) {
            label[static_cast<std::size_t>(i)] = b;
            recurse(i + 1, std::max(used, b + 1));
        }
    };
    recurse(0, 0);
    if (best == std::numeric_limits<double>::infinity()) return std::nullopt;
    return best;
}

// The grouping is a partition of 0..n-1 into p non-empty groups that satisfies `c`.
inline ::testing::AssertionResult isValidGrouping(const std::vector<std::vector<int>>& groups, int n, int p,
                                                  const ReductionConstraints& c = {}) {
    if (static_cast<int>(groups.size()) != p)
        return ::testing::AssertionFailure() << groups.size() << " groups, expected " << p;
    std::vector<int> block(static_cast<std::size_t>(n), -1);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].empty()) return ::testing::AssertionFailure() << "group " << g << " is empty";
        for (const int i : groups[g]) {
            if (i < 0 || i >= n || block[static_cast<std::size_t>(i)] >= 0)
                return ::testing::AssertionFailure() << "item " << i << " out of range or repeated";
            block[static_cast<std::size_t>(i)] = static_cast<int>(g);
        }
    }
    for (const int b : block)
        if (b < 0) return ::testing::AssertionFailure() << "an item is in no group";
    if (!satisfies(block, c)) return ::testing::AssertionFailure() << "the constraints are violated";
    return ::testing::AssertionSuccess();
}

} // namespace vl::test
