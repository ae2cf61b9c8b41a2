#include "SpeechTestModels.h"

#include "core/common/Error.h"
#include "core/speech/UtteranceError.h"

#include <gtest/gtest.h>

#include <random>

using namespace vl;

namespace {

// The slow obvious reference: both faces evaluated vertex by vertex as a device does (runtime
// package + KeyframeAnimation), then
// sum_k w_k |f_k - r_k|^2.
double bruteForceError(const test::RuntimeFace& full, const test::RuntimeFace& reduced,
                       const std::vector<double>& weights, double t) {
    const std::vector<float> f = full.positions(t), r = reduced.positions(t);
    double sum = 0;
    for (std::size_t v = 0; v < weights.size(); ++v)
        for (std::size_t c = 0; c < 3; ++c) {
            const double diff = double(f[3 * v + c]) - double(r[3 * v + c]);
            sum += weights[v] * diff * diff;
        }
    return sum;
}

} // namespace

TEST(UtteranceError, GramEvaluationMatchesBruteForceForEveryInterpolation) {
    std::mt19937 rng(7);
    for (auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        for (int trial = 0; trial < 4; ++trial) {
            const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 10 + trial);
            const auto phonemes = test::timed(test::randomSpeech(5, 20, rng));
            std::vector<double> weights(m.set.vertexCount());
            for (auto& w : weights) w = std::uniform_real_distribution<double>(0.0, 2.0)(rng);
            const PlaybackSettings settings{interpolation};
            const FaceTrack full(m.full, phonemes, settings, "full"),
                reduced(m.reduced, phonemes, settings, "reduced");
            const UtteranceError error = measureUtteranceError(full, reduced, weights, 50.0);
            const test::RuntimeFace fullDevice(full), reducedDevice(reduced);
            ASSERT_EQ(error.frames.size(),
                      static_cast<std::size_t>(std::ceil(full.duration() * 50.0 - 1e-9)) + 1);
            double max = 0;
            for (std::size_t f = 0; f < error.frames.size(); ++f) {
                const double t = std::min(f / 50.0, full.duration());
                const double expected = bruteForceError(fullDevice, reducedDevice, weights, t);
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
    const auto phonemes = test::timed(test::randomSpeech(4, 15, rng));
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

// One evaluator: the key weights the CLI, the editor and the glTF export take from a FaceTrack
// blend the model's keys into exactly the mesh a device computes from the exported package.
TEST(FaceTrack, KeyWeightsAreTheRuntimeAnimation) {
    std::mt19937 rng(21);
    for (auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 30);
        const auto phonemes = test::timed(test::randomSpeech(5, 25, rng));
        for (const ReducedModel* model : {&m.full, &m.reduced}) {
            const FaceTrack track(*model, phonemes, {interpolation}, "face");
            const test::RuntimeFace device(track);
            for (double t = -0.1; t < track.duration() + 0.1; t += 0.0137) {
                const std::vector<float> w = track.keyWeights(t), onDevice = device.positions(t);
                for (std::size_t v = 0; v < model->neutral.positions.size(); ++v)
                    for (std::size_t c = 0; c < 3; ++c) {
                        double p = model->neutral.positions[v][c];
                        for (std::size_t k = 0; k < w.size(); ++k)
                            p += w[k] * (model->keys[k].positions[v][c] - model->neutral.positions[v][c]);
                        ASSERT_NEAR(p, onDevice[3 * v + c], 1e-5) << toString(interpolation) << " t " << t;
                    }
            }
        }
    }
}

TEST(FaceTrack, GivenKeysAreChecked) {
    const auto m = test::speechModels(3, {0, 0, 1}, 9);
    const auto phonemes = test::timed({{"P0", 0.2}, {"P3", 0.3}});
    const FaceTrack track(m.full, phonemes, std::vector<int>{2, kNeutralKey}, {}, "typed");
    ASSERT_EQ(track.cues().size(), 2u);
    EXPECT_EQ(track.cues()[0].value, "v2");
    EXPECT_EQ(track.cues()[1].value, kRestCue);
    EXPECT_THROW(FaceTrack(m.full, phonemes, std::vector<int>{3, 0}, {}, "typed"), InputError);
    EXPECT_THROW(FaceTrack(m.full, phonemes, std::vector<int>{0}, {}, "typed"), InputError);
}
