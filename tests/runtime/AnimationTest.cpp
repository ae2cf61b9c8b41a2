#include "core/runtime/Animation.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/runtime/PackageFormat.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace vl {
namespace {

using runtime::Interpolation;
using runtime::Keyframe;
using runtime::KeyframeAnimation;
using runtime::KeyWeight;
using runtime::kRestKey;

class AnimationTest : public ::testing::Test {
  protected:
    void SetUp() override {
        model = test::randomModel(5, 4, 4, false, 11, 0.3);
        const std::string bytes = encodeRuntimePackage(model);
        std::string error;
        ASSERT_TRUE(package.load(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), error))
            << error;
        n = 3 * package.vertexCount();
    }
    std::vector<float> positionsOf(std::uint32_t key) const {
        std::vector<float> out(n);
        if (key == kRestKey)
            package.neutralPositions(out.data());
        else
            package.keyPositions(key, out.data());
        return out;
    }
    std::vector<float> evaluate(const KeyframeAnimation& a, double t) const {
        std::vector<float> out(n);
        a.evaluate(t, out.data());
        return out;
    }
    ReducedModel model;
    runtime::Package package;
    std::size_t n = 0;
};

void expectNear(const std::vector<float>& a, const std::vector<float>& b, double tolerance) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], tolerance) << i;
}

TEST_F(AnimationTest, LinearInterpolatesBetweenNeighbours) {
    KeyframeAnimation a;
    std::string error;
    ASSERT_TRUE(a.setKeyframes(package, {{0.0, kRestKey}, {0.2, 1}, {0.5, 3}}, Interpolation::Linear, error))
        << error;
    expectNear(evaluate(a, -1.0), positionsOf(kRestKey), 0);
    expectNear(evaluate(a, 0.2), positionsOf(1), 1e-6);
    expectNear(evaluate(a, 9.0), positionsOf(3), 0);
    const auto k1 = positionsOf(1), k3 = positionsOf(3);
    const auto mid = evaluate(a, 0.3); // a third of the way from key 1 to key 3
    for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(mid[i], k1[i] + (k3[i] - k1[i]) / 3.0, 1e-5);
}

// P(t) evaluated directly from the keyframe positions with Hermite tangents (P[i+1]-P[i-1]) /
// (t[i+1]-t[i-1]), ends using the end keyframe itself: the reference for the weight expansion.
std::vector<float> hermiteReference(const std::vector<std::vector<float>>& p,
                                    const std::vector<double>& times, double t) {
    const std::size_t last = times.size() - 1;
    std::size_t i = 0;
    while (i + 1 < last && t >= times[i + 1]) ++i;
    const std::size_t im1 = i > 0 ? i - 1 : i, ip2 = std::min(i + 2, last);
    const double h = times[i + 1] - times[i], s = (t - times[i]) / h;
    std::vector<float> out(p[0].size());
    for (std::size_t c = 0; c < out.size(); ++c) {
        const double m0 = (p[i + 1][c] - double(p[im1][c])) / (times[i + 1] - times[im1]);
        const double m1 = (p[ip2][c] - double(p[i][c])) / (times[ip2] - times[i]);
        out[c] = static_cast<float>(
            (2 * s * s * s - 3 * s * s + 1) * p[i][c] + (s * s * s - 2 * s * s + s) * h * m0 +
            (-2 * s * s * s + 3 * s * s) * p[i + 1][c] + (s * s * s - s * s) * h * m1);
    }
    return out;
}

TEST_F(AnimationTest, CubicMatchesHermiteReferenceAndHitsKeyframes) {
    const std::vector<Keyframe> keyframes{{0.0, kRestKey}, {0.07, 2}, {0.31, 0},
                                          {0.36, 3},       {0.9, 1},  {1.0, kRestKey}};
    KeyframeAnimation a;
    std::string error;
    ASSERT_TRUE(a.setKeyframes(package, keyframes, Interpolation::Cubic, error)) << error;
    std::vector<std::vector<float>> p;
    std::vector<double> times;
    for (const Keyframe& k : keyframes) {
        p.push_back(positionsOf(k.key));
        times.push_back(k.time);
    }
    for (const Keyframe& k : keyframes) expectNear(evaluate(a, k.time), positionsOf(k.key), 1e-5);
    for (double t = 0.0; t < 1.0; t += 0.0123) {
        expectNear(evaluate(a, t), hermiteReference(p, times, t), 2e-5);
        KeyWeight w[4];
        const std::size_t count = a.weightsAt(t, w);
        double sum = 0;
        for (std::size_t j = 0; j < count; ++j) sum += w[j].weight;
        EXPECT_NEAR(sum, 1.0, 1e-6);
    }
}

TEST_F(AnimationTest, CubicWithEvenSpacingIsCatmullRom) {
    KeyframeAnimation a;
    std::string error;
    ASSERT_TRUE(a.setKeyframes(package, {{0, 0}, {1, 1}, {2, 2}, {3, 3}}, Interpolation::Cubic, error));
    const auto p0 = positionsOf(0), p1 = positionsOf(1), p2 = positionsOf(2), p3 = positionsOf(3);
    for (double s : {0.1, 0.5, 0.77}) {
        const auto got = evaluate(a, 1 + s);
        for (std::size_t i = 0; i < n; ++i) {
            const double expected = 0.5 * (2 * p1[i] + (-p0[i] + p2[i]) * s +
                                           (2 * p0[i] - 5 * p1[i] + 4 * p2[i] - p3[i]) * s * s +
                                           (-p0[i] + 3 * p1[i] - 3 * p2[i] + p3[i]) * s * s * s);
            ASSERT_NEAR(got[i], expected, 1e-5);
        }
    }
}

TEST_F(AnimationTest, PhonemesMapToTheirKeys) {
    std::vector<Keyframe> keyframes;
    std::string error;
    ASSERT_TRUE(
        runtime::keyframesFromPhonemes(package, {{0.0, ""}, {0.1, "p5"}, {0.2, "p0"}}, keyframes, error));
    ASSERT_EQ(keyframes.size(), 3u);
    EXPECT_EQ(keyframes[0].key, kRestKey);
    EXPECT_EQ(keyframes[1].key, 2u);
    EXPECT_EQ(keyframes[2].key, 0u);
    EXPECT_FALSE(runtime::keyframesFromPhonemes(package, {{0.0, "p1"}, {0.1, "zz"}}, keyframes, error));
    EXPECT_NE(error.find("keyframe 1: unknown phoneme 'zz'"), std::string::npos) << error;
}

TEST_F(AnimationTest, RejectsBadSequences) {
    KeyframeAnimation a;
    std::string error;
    EXPECT_FALSE(a.setKeyframes(package, {}, Interpolation::Linear, error));
    EXPECT_FALSE(a.setKeyframes(package, {{0.1, 0}, {0.1, 1}}, Interpolation::Linear, error));
    EXPECT_NE(error.find("keyframe 1: time does not increase"), std::string::npos);
    EXPECT_FALSE(a.setKeyframes(package, {{0.0, 0}, {std::nan(""), 1}}, Interpolation::Linear, error));
    EXPECT_FALSE(a.setKeyframes(package, {{0.0, 4}}, Interpolation::Linear, error));
    EXPECT_NE(error.find("key 4 of 4"), std::string::npos);
    runtime::Package empty;
    EXPECT_FALSE(a.setKeyframes(empty, {{0.0, 0}}, Interpolation::Linear, error));
    ASSERT_TRUE(a.setKeyframes(package, {{0.5, 2}}, Interpolation::Cubic, error));
    expectNear(evaluate(a, 0.0), positionsOf(2), 0);
    expectNear(evaluate(a, std::nan("")), positionsOf(2), 0);
}

// Dominance blending evaluated over every keyframe, each with its taper written out from the
// definition (0 before t_{i-2}, rising to 1 at t_{i-1}, 1 until t_{i+1}, falling to 0 at t_{i+2}):
// the slow reference for the windowed version.
std::vector<double> dominanceReference(const std::vector<Keyframe>& k, double rate, double t,
                                       std::size_t keys) {
    const std::size_t n = k.size();
    t = std::clamp(t, k.front().time, k.back().time);
    const auto smooth = [](double s) { return s * s * (3 - 2 * s); };
    std::vector<double> byKey(keys + 1, 0.0); // the last slot is the rest key
    double sum = 0;
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) {
        double taper = 1;
        if (i >= 2 && t <= k[i - 2].time)
            taper = 0;
        else if (i >= 2 && t < k[i - 1].time)
            taper = smooth((t - k[i - 2].time) / (k[i - 1].time - k[i - 2].time));
        if (i + 2 < n && t >= k[i + 2].time)
            taper = 0;
        else if (i + 2 < n && t > k[i + 1].time)
            taper = 1 - smooth((t - k[i + 1].time) / (k[i + 2].time - k[i + 1].time));
        d[i] = k[i].dominance * taper * std::exp(-rate * std::abs(t - k[i].time));
        sum += d[i];
    }
    for (std::size_t i = 0; i < n; ++i) byKey[k[i].key == kRestKey ? keys : k[i].key] += d[i] / sum;
    return byKey;
}

TEST_F(AnimationTest, DominanceMatchesTheReferenceOnRandomSequences) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> gap(0.01, 0.3), alpha(0.2, 4.0), rate(5.0, 60.0);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Keyframe> keyframes;
        double time = -0.1;
        const int count = 1 + static_cast<int>(rng() % 12);
        for (int i = 0; i < count; ++i) {
            time += gap(rng);
            const std::uint32_t key = rng() % 5 == 4 ? kRestKey : static_cast<std::uint32_t>(rng() % 4);
            keyframes.push_back({time, key, static_cast<float>(alpha(rng))});
        }
        const double theta = rate(rng);
        KeyframeAnimation a;
        std::string error;
        ASSERT_TRUE(a.setKeyframes(package, keyframes, Interpolation::Dominance, error, theta)) << error;
        for (double t = -0.2; t < time + 0.2; t += 0.0071) {
            KeyWeight w[4];
            const std::size_t terms = a.weightsAt(t, w);
            std::vector<double> byKey(5, 0.0);
            for (std::size_t j = 0; j < terms; ++j) {
                EXPECT_GE(w[j].weight, 0.0f);
                byKey[w[j].key == kRestKey ? 4 : w[j].key] += w[j].weight;
            }
            const auto expected = dominanceReference(keyframes, theta, t, 4);
            for (std::size_t key = 0; key < 5; ++key) ASSERT_NEAR(byKey[key], expected[key], 1e-6) << t;
        }
    }
}

TEST_F(AnimationTest, DominanceIsContinuousAndDominantKeysWin) {
    // A short bilabial between two vowels: with high dominance it is nearly reached at its time,
    // with equal dominance it is not (coarticulation).
    const std::vector<Keyframe> equal{{0.0, 0}, {0.1, 1}, {0.14, 2}, {0.18, 1}, {0.3, 0}};
    std::vector<Keyframe> dominant = equal;
    dominant[2].dominance = 20.0f;
    KeyframeAnimation a, b;
    std::string error;
    ASSERT_TRUE(a.setKeyframes(package, equal, Interpolation::Dominance, error));
    ASSERT_TRUE(b.setKeyframes(package, dominant, Interpolation::Dominance, error));
    const auto weightOf = [](const KeyframeAnimation& anim, double t, std::uint32_t key) {
        KeyWeight w[4];
        double sum = 0;
        for (std::size_t j = 0, terms = anim.weightsAt(t, w); j < terms; ++j)
            if (w[j].key == key) sum += w[j].weight;
        return sum;
    };
    EXPECT_LT(weightOf(a, 0.14, 2), 0.6);
    EXPECT_GT(weightOf(b, 0.14, 2), 0.9);
    // Continuity across keyframe times (where the window of contributing keyframes moves).
    for (const Keyframe& k : equal) expectNear(evaluate(a, k.time - 1e-7), evaluate(a, k.time + 1e-7), 1e-4);
    // Far apart keyframes: no underflow to 0/0.
    ASSERT_TRUE(a.setKeyframes(package, {{0.0, 0}, {1000.0, 1}}, Interpolation::Dominance, error));
    expectNear(evaluate(a, 500.0), evaluate(a, 500.0), 0);
    EXPECT_NEAR(weightOf(a, 499.0, 0), 1.0, 1e-6);
    EXPECT_FALSE(a.setKeyframes(package, {{0.0, 0, 0.0f}}, Interpolation::Dominance, error));
    EXPECT_NE(error.find("dominance must be"), std::string::npos);
    EXPECT_FALSE(a.setKeyframes(package, {{0.0, 0}}, Interpolation::Dominance, error, -1.0));
}

// The curve alone (what a GPU renderer uses) gives the package's animation its weights: same
// terms at every time, for every interpolation, and the same checks without any mesh.
TEST_F(AnimationTest, CurveWithoutPackageGivesTheAnimationsWeights) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> gap(0.01, 0.3);
    for (auto interpolation : {Interpolation::Linear, Interpolation::Cubic, Interpolation::Dominance}) {
        std::vector<Keyframe> keyframes;
        double t = 0.0;
        for (int i = 0; i < 30; ++i) {
            const auto key = static_cast<std::uint32_t>(rng() % 5);
            keyframes.push_back({t += gap(rng), key == 4 ? kRestKey : key, 0.5f + 0.1f * float(i % 7)});
        }
        KeyframeAnimation a;
        runtime::KeyframeCurve curve;
        std::string error;
        ASSERT_TRUE(a.setKeyframes(package, keyframes, interpolation, error, 20.0)) << error;
        ASSERT_TRUE(curve.setKeyframes(package.keyCount(), keyframes, interpolation, error, 20.0)) << error;
        for (double u = -0.2; u < t + 0.2; u += 0.0071) {
            KeyWeight fromCurve[4], fromAnimation[4];
            const std::size_t count = curve.weightsAt(u, fromCurve);
            ASSERT_EQ(count, a.weightsAt(u, fromAnimation));
            std::vector<float> blended(n), expected = evaluate(a, u);
            package.blend(fromCurve, count, blended.data());
            expectNear(blended, expected, 0);
        }
    }
    runtime::KeyframeCurve curve;
    std::string error;
    KeyWeight out[4];
    EXPECT_EQ(curve.weightsAt(0.0, out), 0u);
    EXPECT_FALSE(curve.setKeyframes(3, {{0.0, 3}}, Interpolation::Linear, error));
    EXPECT_NE(error.find("key 3 of 3"), std::string::npos);
    EXPECT_TRUE(curve.setKeyframes(3, {{0.0, kRestKey}, {0.1, 2}}, Interpolation::Linear, error));
    EXPECT_FALSE(curve.setKeyframes(3, {{0.0, 0}, {0.0, 1}}, Interpolation::Cubic, error));
    EXPECT_TRUE(curve.empty()); // a refused sequence leaves nothing half-set
}

} // namespace
} // namespace vl
