#include "SpeechTestModels.h"

#include "core/common/Error.h"
#include "core/speech/SpeechErrors.h"

#include <gtest/gtest.h>

#include <random>

using namespace vl;

// One pass over the frames gives each measure exactly what it gives alone, for random faces,
// reductions (keys merged or left alone), mouths, utterances and both interpolations.
TEST(SpeechErrors, OnePassGivesExactlyWhatEachMeasureGivesAlone) {
    std::mt19937 rng(41);
    for (int trial = 0; trial < 24; ++trial) {
        const int visemes = 3 + trial % 5;
        std::vector<int> groupOf(visemes);
        const int groups = 1 + static_cast<int>(rng() % static_cast<unsigned>(visemes));
        for (int v = 0; v < visemes; ++v)
            groupOf[v] = v < groups ? v : static_cast<int>(rng() % unsigned(groups));
        const auto m = test::speechModels(visemes, groupOf, 100 + unsigned(trial));
        std::vector<double> weights(m.set.vertexCount(), 0.0);
        for (double& w : weights) w = rng() % 3 == 0 ? 0.0 : 0.25 + double(rng() % 4);
        weights[0] = 1.0; // a mouth of at least one vertex
        const SpeechErrorBasis basis(m.full, m.reduced, weights);
        const auto interpolation = trial % 2 ? runtime::Interpolation::Cubic : runtime::Interpolation::Linear;
        const auto phonemes = test::timed(test::randomSpeech(visemes, 4 + trial, rng, 0.01, 0.4));
        const FaceTrack full(m.full, phonemes, {interpolation}, "full"),
            reduced(m.reduced, phonemes, {interpolation}, "reduced");
        const double fps = trial % 3 ? 60.0 : 24.0;
        const SpeechErrors both = measureSpeechErrors(basis, full, reduced, fps, millimetresFromMetres());
        const UtteranceError utterance = measureUtteranceError(basis, full, reduced, fps);
        const DisplacementError displacement =
            measureDisplacementError(basis, full, reduced, fps, millimetresFromMetres());
        ASSERT_GT(utterance.frames.size(), 1u) << trial;
        EXPECT_EQ(both.utterance.frames, utterance.frames) << trial;
        EXPECT_EQ(both.utterance.mean, utterance.mean) << trial;
        EXPECT_EQ(both.utterance.max, utterance.max) << trial;
        EXPECT_EQ(both.utterance.maxTime, utterance.maxTime) << trial;
        EXPECT_EQ(both.utterance.motion, utterance.motion) << trial;
        EXPECT_EQ(both.utterance.relative, utterance.relative) << trial;
        EXPECT_EQ(both.displacement.unit, "mm");
        EXPECT_EQ(both.displacement.rmsFrames, displacement.rmsFrames) << trial;
        EXPECT_EQ(both.displacement.maxFrames, displacement.maxFrames) << trial;
        EXPECT_EQ(both.displacement.rms, displacement.rms) << trial;
        EXPECT_EQ(both.displacement.max, displacement.max) << trial;
        EXPECT_EQ(both.displacement.maxTime, displacement.maxTime) << trial;
    }
}

TEST(SpeechErrors, RefusesWhatEitherMeasureRefuses) {
    const auto m = test::speechModels(4, {0, 0, 1, 1}, 3);
    const auto other = test::speechModels(4, {0, 1, 2, 2}, 3);
    const auto phonemes = test::timed({{"P1", 0.2}, {"P4", 0.15}});
    const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
    const std::vector<double> weights(m.set.vertexCount(), 1.0);
    const SpeechErrorBasis basis(m.full, m.reduced, weights);
    EXPECT_THROW(measureSpeechErrors(basis, full, reduced, 0.0, {}), InputError);
    EXPECT_THROW(
        measureSpeechErrors(SpeechErrorBasis(other.full, other.reduced, weights), full, reduced, 30.0, {}),
        InputError);
    const SpeechErrorBasis noMouth(m.full, m.reduced, std::vector<double>(m.set.vertexCount(), 0.0));
    EXPECT_THROW(measureSpeechErrors(noMouth, full, reduced, 30.0, {}), InputError);
}
