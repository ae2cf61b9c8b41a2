#include "SpeechTestModels.h"

#include "core/common/Error.h"
#include "core/speech/UtteranceError.h"

#include <gtest/gtest.h>

#include <random>

using namespace vl;

namespace {

// The slow obvious reference: both faces evaluated vertex by vertex through the runtime, then
// sum_k w_k |f_k - r_k|^2.
double bruteForceError(const FaceTrack& full, const FaceTrack& reduced, const std::vector<double>& weights,
                       double t) {
    std::vector<float> f(3 * weights.size()), r(3 * weights.size());
    full.evaluate(t, f.data());
    reduced.evaluate(t, r.data());
    double sum = 0;
    for (std::size_t v = 0; v < weights.size(); ++v)
        for (std::size_t c = 0; c < 3; ++c) {
            const double diff = double(f[3 * v + c]) - double(r[3 * v + c]);
            sum += weights[v] * diff * diff;
        }
    return sum;
}

std::vector<std::pair<std::string, double>> randomSpeech(int visemes, int count, std::mt19937& rng) {
    std::uniform_real_distribution<double> duration(0.02, 0.3);
    std::vector<std::pair<std::string, double>> items;
    for (int i = 0; i < count; ++i) {
        const int p = static_cast<int>(rng() % (2 * visemes + 1));
        items.emplace_back(p == 2 * visemes ? "sil" : "P" + std::to_string(p), duration(rng));
    }
    return items;
}

} // namespace

TEST(UtteranceError, GramEvaluationMatchesBruteForceForEveryInterpolation) {
    std::mt19937 rng(7);
    for (auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        for (int trial = 0; trial < 4; ++trial) {
            const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 10 + trial);
            const auto phonemes = test::timed(randomSpeech(5, 20, rng));
            std::vector<double> weights(m.set.vertexCount());
            for (auto& w : weights) w = std::uniform_real_distribution<double>(0.0, 2.0)(rng);
            const PlaybackSettings settings{interpolation};
            const FaceTrack full(m.full, phonemes, settings, "full"),
                reduced(m.reduced, phonemes, settings, "reduced");
            const UtteranceError error = measureUtteranceError(full, reduced, weights, 50.0);
            ASSERT_EQ(error.frames.size(),
                      static_cast<std::size_t>(std::ceil(full.duration() * 50.0 - 1e-9)) + 1);
            double max = 0;
            for (std::size_t f = 0; f < error.frames.size(); ++f) {
                const double t = std::min(f / 50.0, full.duration());
                const double expected = bruteForceError(full, reduced, weights, t);
                ASSERT_NEAR(error.frames[f], expected, 1e-5 * (1e-3 + expected)) << f;
                max = std::max(max, expected);
            }
            EXPECT_NEAR(error.max, max, 1e-5 * max);
            EXPECT_GT(error.mean, 0.0);
            EXPECT_LE(error.mean, error.max);
            EXPECT_GT(error.relative, 0.0);
        }
    }
}

TEST(UtteranceError, NoReductionNoError) {
    std::mt19937 rng(3);
    const auto m = test::speechModels(4, {0, 1, 2, 3}, 5);
    const auto phonemes = test::timed(randomSpeech(4, 15, rng));
    const std::vector<double> weights(m.set.vertexCount(), 1.0);
    const FaceTrack full(m.full, phonemes, {}, "full"), same(m.reduced, phonemes, {}, "same");
    const UtteranceError error = measureUtteranceError(full, same, weights, 30.0);
    EXPECT_EQ(error.max, 0.0);
    EXPECT_EQ(error.mean, 0.0);
    EXPECT_GT(error.motion, 0.0);
}

// A phoneme held alone: every frame is the reduction's own dissimilarity rho(A_i, B_group(i)).
TEST(UtteranceError, AHeldVisemeCostsItsDissimilarityToItsMergedKey) {
    const auto m = test::speechModels(3, {0, 0, 1}, 9);
    const auto phonemes = test::timed({{"P2", 0.5}}); // viseme v1, merged with v0
    std::vector<double> weights(m.set.vertexCount());
    for (std::size_t v = 0; v < weights.size(); ++v) weights[v] = 0.5 + 0.1 * double(v % 3);
    const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
    const UtteranceError error = measureUtteranceError(full, reduced, weights, 24.0);
    const double rho = dissimilarity(m.set.visemes[1].positions, m.reduced.keys[0].positions, weights);
    for (const double frame : error.frames) EXPECT_NEAR(frame, rho, 1e-5 * rho);
    EXPECT_NEAR(error.mean, rho, 1e-5 * rho);
    EXPECT_THROW(measureUtteranceError(full, reduced, std::vector<double>(3, 1.0), 24.0), InputError);
    EXPECT_THROW(measureUtteranceError(full, reduced, weights, 0.0), InputError);
}
