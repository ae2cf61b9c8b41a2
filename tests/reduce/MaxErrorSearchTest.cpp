#include "core/reduce/MaxErrorSearch.h"

#include "core/common/Error.h"
#include "tests/reduce/RandomShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

using namespace vl;

namespace {

// The slow, obvious statement of the bound: means and distances from the definition.
bool allowedByDefinition(const std::vector<std::vector<Vec3>>& shapes, const std::vector<Vec3>& rest,
                         const std::vector<double>& f, const std::vector<double>& w, double x,
                         const std::vector<int>& groupOf) {
    const std::size_t n = shapes.size(), vertices = w.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t v = 0; v < vertices; ++v) {
            if (w[v] <= 0) continue;
            Vec3 shown;
            if (groupOf[i] < 0) {
                if (rest.empty()) return false;
                shown = rest[v];
            } else {
                double total = 0, count = 0;
                Vec3 sum(0, 0, 0), plain(0, 0, 0);
                for (std::size_t j = 0; j < n; ++j)
                    if (groupOf[j] == groupOf[i]) {
                        total += f[j];
                        sum += f[j] * shapes[j][v];
                        plain += shapes[j][v];
                        count += 1;
                    }
                shown = total > 0 ? sum / total : plain / count;
            }
            if ((shapes[i][v] - shown).norm() > x) return false;
        }
    }
    return true;
}

// Every labelling (rest or a key, keys numbered in order of first use) respecting the constraints:
// the fewest keys of an allowed one, or -1.
int bruteForceFewestKeys(const std::vector<std::vector<Vec3>>& shapes, const std::vector<Vec3>& rest,
                         const std::vector<double>& f, const std::vector<double>& w, double x,
                         const ReductionConstraints& c, const std::vector<int>& mustRest) {
    const int n = static_cast<int>(shapes.size());
    std::vector<int> label(static_cast<std::size_t>(n), -1);
    int best = -1;
    std::function<void(int, int)> visit = [&](int i, int used) {
        if (i == n) {
            for (const int p : c.pinned) {
                if (label[static_cast<std::size_t>(p)] < 0) return;
                for (int j = 0; j < n; ++j)
                    if (j != p && label[static_cast<std::size_t>(j)] == label[static_cast<std::size_t>(p)])
                        return;
            }
            for (const auto& [a, b] : c.apart)
                if (label[static_cast<std::size_t>(a)] >= 0 &&
                    label[static_cast<std::size_t>(a)] == label[static_cast<std::size_t>(b)])
                    return;
            for (const auto& [a, b] : c.together)
                if (label[static_cast<std::size_t>(a)] != label[static_cast<std::size_t>(b)]) return;
            for (const int r : mustRest)
                if (label[static_cast<std::size_t>(r)] >= 0) return;
            if (!allowedByDefinition(shapes, rest, f, w, x, label)) return;
            const int keys = std::max(used, 1);
            if (best < 0 || keys < best) best = keys;
            return;
        }
        for (int l = rest.empty() ? 0 : -1; l <= used; ++l) {
            label[static_cast<std::size_t>(i)] = l;
            visit(i + 1, l == used ? used + 1 : used);
        }
    };
    visit(0, 0);
    return best;
}

MaxErrorProblem problemOf(const test::RandomInstance& inst, const std::vector<Vec3>& rest, double x,
                          const ReductionConstraints& c) {
    MaxErrorProblem p;
    p.shapes = inst.shapes;
    p.rest = rest;
    p.frequencies = inst.frequencies;
    p.weights = inst.weights;
    p.maxError = x;
    p.units = constraintUnits(c, static_cast<int>(inst.shapes.size()));
    p.mustKey = c.pinned;
    return p;
}

} // namespace

TEST(MaxErrorSearch, AgreesWithBruteForceOnRandomSets) {
    std::mt19937 rng(11);
    int cases = 0, withRest = 0, constrained = 0;
    for (int trial = 0; trial < 240; ++trial) {
        const int n = 3 + trial % 5;
        test::RandomInstance inst = test::rigInstance(rng, n, 12, 3);
        if (trial % 7 == 0) inst.frequencies[0] = 0.0;
        std::vector<Vec3> rest;
        std::vector<int> mustRest;
        if (trial % 3 !=
            0) { // the rest pose: viseme 0 is 'sil' every other time, else a shape near the others
            rest = inst.shapes[0];
            if (trial % 2 == 0) mustRest = {0};
            for (auto& p : rest) p += Vec3(0.02, -0.01, 0.0) * static_cast<double>(trial % 4);
            ++withRest;
        }
        ReductionConstraints c;
        std::uniform_int_distribution<int> pick(1, n - 1);
        if (trial % 4 == 1) c.apart.push_back({pick(rng), pick(rng)});
        if (trial % 4 == 2) c.together.push_back({1, 2});
        if (trial % 8 == 3) c.pinned.push_back(n - 1);
        c.apart.erase(
            std::remove_if(c.apart.begin(), c.apart.end(), [](auto& a) { return a.first == a.second; }),
            c.apart.end());
        constrained += !c.empty();
        std::uniform_real_distribution<double> fraction(0.05, 0.9);
        const double x = fraction(rng);
        MaxErrorProblem problem = problemOf(inst, rest, x, c);
        problem.mustRest = mustRest;
        const int expected =
            bruteForceFewestKeys(inst.shapes, rest, inst.frequencies, inst.weights, x, c, mustRest);
        if (expected < 0) {
            EXPECT_THROW(smallestKeysWithin(problem), InputError) << "trial " << trial;
            continue;
        }
        MaxErrorResult result;
        try {
            result = smallestKeysWithin(problem);
        } catch (const InputError& e) {
            ADD_FAILURE() << "trial " << trial << ": " << e.what() << " (brute force: " << expected
                          << " keys)";
            continue;
        }
        ++cases;
        EXPECT_EQ(result.keys, expected) << "trial " << trial << ", n " << n << ", X " << x;
        EXPECT_TRUE(result.certified) << "trial " << trial;
        EXPECT_TRUE(allowedByDefinition(inst.shapes, rest, inst.frequencies, inst.weights, x, result.groupOf))
            << "trial " << trial;
        EXPECT_TRUE(withinMaxError(problem, result.groupOf));
        for (const int r : mustRest) EXPECT_EQ(result.groupOf[static_cast<std::size_t>(r)], -1);
        const int used = 1 + *std::max_element(result.groupOf.begin(), result.groupOf.end());
        EXPECT_LE(used, result.keys);
    }
    EXPECT_GT(cases, 150);
    EXPECT_GT(withRest, 100);
    EXPECT_GT(constrained, 80);
}

TEST(MaxErrorSearch, ApartPairsAreExactlyThePairsFartherThanTwiceTheBound) {
    std::mt19937 rng(5);
    const test::RandomInstance inst = test::rigInstance(rng, 6, 10, 3);
    const MaxErrorProblem problem = problemOf(inst, {}, 0.3, {});
    const auto pairs = maxErrorApartPairs(problem);
    for (int i = 0; i < 6; ++i)
        for (int j = i + 1; j < 6; ++j) {
            double far = 0;
            for (std::size_t v = 0; v < inst.weights.size(); ++v)
                if (inst.weights[v] > 0)
                    far = std::max(far, (inst.shapes[static_cast<std::size_t>(i)][v] -
                                         inst.shapes[static_cast<std::size_t>(j)][v])
                                            .norm());
            const bool listed = std::find(pairs.begin(), pairs.end(), std::pair{i, j}) != pairs.end();
            EXPECT_EQ(listed, far > 0.6) << i << ", " << j;
        }
}

TEST(MaxErrorSearch, ARestVisemeThatMovesTooMuchIsAnError) {
    std::mt19937 rng(3);
    const test::RandomInstance inst = test::rigInstance(rng, 4, 8, 2);
    std::vector<Vec3> rest = inst.shapes[0];
    for (auto& p : rest) p += Vec3(5, 0, 0);
    MaxErrorProblem problem = problemOf(inst, rest, 0.5, {});
    problem.mustRest = {0};
    EXPECT_THROW(smallestKeysWithin(problem), InputError);
    problem.maxError = -1;
    EXPECT_THROW(smallestKeysWithin(problem), InputError);
}
