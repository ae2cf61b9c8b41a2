#include "SpeechTestModels.h"

#include "core/common/Error.h"
#include "core/speech/DisplacementError.h"
#include "core/speech/UtteranceError.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vl;

namespace {

// The obvious reference: both faces' vertices at t from their key weights, then the weighted RMS
// and the largest distance over the vertices of nonzero weight, in mm for metres.
struct Frame {
    double rms = 0, max = 0;
};

std::vector<Vec3> positionsAt(const FaceTrack& track, double t) {
    const std::vector<float> w = track.keyWeights(t);
    const ReducedModel& model = track.model();
    std::vector<Vec3> out = model.neutral.positions;
    for (std::size_t k = 0; k < w.size(); ++k)
        for (std::size_t v = 0; v < out.size(); ++v)
            out[v] += (model.keys[k].positions[v] - model.neutral.positions[v]) * double(w[k]);
    return out;
}

Frame bruteForce(const FaceTrack& full, const FaceTrack& reduced, const std::vector<double>& weights,
                 double t) {
    const auto f = positionsAt(full, t), r = positionsAt(reduced, t);
    double sum = 0, total = 0;
    Frame frame;
    for (std::size_t v = 0; v < weights.size(); ++v) {
        if (weights[v] <= 0) continue;
        const double distance = (f[v] - r[v]).norm() * 1000.0;
        sum += weights[v] * distance * distance;
        total += weights[v];
        frame.max = std::max(frame.max, distance);
    }
    frame.rms = std::sqrt(sum / total);
    return frame;
}

} // namespace

TEST(DisplacementError, MatchesBruteForceOverTheMouthInMillimetres) {
    for (auto interpolation : {runtime::Interpolation::Linear, runtime::Interpolation::Cubic}) {
        const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 17);
        const auto phonemes =
            test::timed({{"sil", 0.1}, {"P2", 0.2}, {"P5", 0.05}, {"P8", 0.3}, {"P0", 0.12}, {"sil", 0.1}});
        // The mouth: half the vertices; the others (weight 0) may move as they like.
        std::vector<double> weights(m.set.vertexCount(), 0.0);
        for (std::size_t v = 0; v < weights.size(); v += 2) weights[v] = 0.5 + 0.25 * double(v % 3);
        const FaceTrack full(m.full, phonemes, {interpolation}, "full"),
            reduced(m.reduced, phonemes, {interpolation}, "reduced");
        const DisplacementError error =
            measureDisplacementError(full, reduced, weights, 40.0, millimetresFromMetres());
        EXPECT_EQ(error.unit, "mm");
        ASSERT_EQ(error.rmsFrames.size(), measureUtteranceError(full, reduced, weights, 40.0).frames.size());
        double max = 0;
        for (std::size_t f = 0; f < error.rmsFrames.size(); ++f) {
            const double t = std::min(f / 40.0, full.duration());
            const Frame expected = bruteForce(full, reduced, weights, t);
            // Key weights are floats (as on a device): agreement to their precision.
            ASSERT_NEAR(error.rmsFrames[f], expected.rms, 1e-9 + 1e-5 * expected.rms) << f;
            ASSERT_NEAR(error.maxFrames[f], expected.max, 1e-9 + 1e-5 * expected.max) << f;
            max = std::max(max, expected.max);
        }
        EXPECT_GT(max, 1.0); // the fixture's visemes differ by centimetres: mm figures, not metres
        EXPECT_NEAR(error.max, max, 1e-5 * max);
        // maxTime is a frame where the largest distance occurs (held poses may tie).
        EXPECT_NEAR(bruteForce(full, reduced, weights, error.maxTime).max, max, 1e-5 * max);
        EXPECT_GT(error.rms, 0.0);
        EXPECT_LT(error.rms, error.max);
    }
}

TEST(DisplacementError, IsTheSquareRootOfTheUtteranceErrorPerWeight) {
    // Same weights, same blend: RMS(t)^2 * sum(w) is the utterance error's rho(t) (in model units).
    const auto m = test::speechModels(4, {0, 0, 1, 1}, 3);
    const auto phonemes = test::timed({{"P1", 0.2}, {"P4", 0.15}, {"P7", 0.25}});
    const std::vector<double> weights(m.set.vertexCount(), 2.0);
    const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
    const DisplacementError error =
        measureDisplacementError(full, reduced, weights, 30.0, DisplacementUnit{});
    const UtteranceError rho = measureUtteranceError(full, reduced, weights, 30.0);
    EXPECT_EQ(error.unit, "model units");
    const double total = 2.0 * double(weights.size());
    for (std::size_t f = 0; f < rho.frames.size(); ++f)
        EXPECT_NEAR(error.rmsFrames[f] * error.rmsFrames[f] * total, rho.frames[f],
                    1e-9 + 1e-6 * rho.frames[f]);
    EXPECT_NEAR(error.rms * error.rms * total, rho.mean, 1e-6 * rho.mean);
}

TEST(DisplacementError, RefusesNoMouthAndMismatchedWeights) {
    const auto m = test::speechModels(3, {0, 0, 1}, 9);
    const auto phonemes = test::timed({{"P2", 0.5}});
    const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
    EXPECT_THROW(
        measureDisplacementError(full, reduced, std::vector<double>(m.set.vertexCount(), 0.0), 24.0, {}),
        InputError);
    EXPECT_THROW(measureDisplacementError(full, reduced, std::vector<double>(3, 1.0), 24.0, {}), InputError);
    EXPECT_THROW(
        measureDisplacementError(full, reduced, std::vector<double>(m.set.vertexCount(), 1.0), 0.0, {}),
        InputError);
}

TEST(DisplacementError, NoReductionIsZero) {
    const auto m = test::speechModels(4, {0, 1, 2, 3}, 5);
    const auto phonemes = test::timed({{"P1", 0.2}, {"P4", 0.15}, {"sil", 0.1}, {"P7", 0.25}});
    const std::vector<double> weights(m.set.vertexCount(), 1.0);
    const FaceTrack full(m.full, phonemes, {}, "full"), same(m.reduced, phonemes, {}, "same");
    const DisplacementError error =
        measureDisplacementError(full, same, weights, 30.0, millimetresFromMetres());
    EXPECT_LT(error.max, 1e-12); // mm: rounding at most
    EXPECT_LT(error.rms, 1e-12);
    const DisplacementError itself =
        measureDisplacementError(full, full, weights, 30.0, millimetresFromMetres());
    EXPECT_EQ(itself.max, 0.0); // the same keys cancel exactly
}

TEST(DisplacementError, OneBasisServesEveryUtteranceOfItsFacesAtAnyMouthSize) {
    // The per-frame sums run in lanes of four: mouths of 1..9 vertices cover every remainder.
    const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 23);
    const std::vector<std::vector<std::pair<std::string, double>>> utterances = {
        {{"sil", 0.1}, {"P2", 0.2}, {"P5", 0.05}, {"P8", 0.3}, {"sil", 0.1}},
        {{"P1", 0.3}, {"P3", 0.3}, {"P3", 0.2}, {"P9", 0.15}},
    };
    for (std::size_t mouth = 1; mouth <= 9; ++mouth) {
        std::vector<double> weights(m.set.vertexCount(), 0.0);
        for (std::size_t v = 0; v < mouth; ++v) weights[3 * v % weights.size()] = 1.0 + double(v);
        const SpeechErrorBasis basis(m.full, m.reduced, weights);
        EXPECT_EQ(basis.mouthSize(), mouth);
        for (const auto& spoken : utterances) {
            const auto phonemes = test::timed(spoken);
            const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
            const DisplacementError shared =
                measureDisplacementError(basis, full, reduced, 50.0, millimetresFromMetres());
            const UtteranceError rho = measureUtteranceError(basis, full, reduced, 50.0);
            ASSERT_EQ(shared.maxFrames.size(), rho.frames.size());
            for (std::size_t f = 0; f < shared.maxFrames.size(); ++f) {
                const double t = std::min(f / 50.0, full.duration());
                const Frame expected = bruteForce(full, reduced, weights, t);
                ASSERT_NEAR(shared.rmsFrames[f], expected.rms, 1e-9 + 1e-5 * expected.rms)
                    << mouth << " " << f;
                ASSERT_NEAR(shared.maxFrames[f], expected.max, 1e-9 + 1e-5 * expected.max)
                    << mouth << " " << f;
            }
        }
    }
}

TEST(DisplacementError, RefusesABasisOfOtherFaces) {
    const auto m = test::speechModels(4, {0, 0, 1, 1}, 3);
    const auto other = test::speechModels(4, {0, 1, 2, 2}, 3);
    const std::vector<double> weights(m.set.vertexCount(), 1.0);
    const SpeechErrorBasis basis(other.full, other.reduced, weights); // 3 reduced keys, not 2
    const auto phonemes = test::timed({{"P1", 0.2}, {"P4", 0.15}});
    const FaceTrack full(m.full, phonemes, {}, "full"), reduced(m.reduced, phonemes, {}, "reduced");
    EXPECT_THROW(measureDisplacementError(basis, full, reduced, 30.0, {}), InputError);
    EXPECT_THROW(measureUtteranceError(basis, full, reduced, 30.0), InputError);
}

// A basis taken back from its stored parts (the speech cache keeps them) is the basis itself; parts
// that do not fit the faces are refused.
TEST(DisplacementError, AStoredBasisIsTheBasisAndMustFitItsFaces) {
    const auto m = test::speechModels(5, {0, 1, 1, 2, 0}, 23);
    std::vector<double> weights(m.set.vertexCount(), 0.0);
    for (std::size_t v = 0; v < weights.size(); v += 2) weights[v] = 0.5 + double(v);
    const SpeechErrorBasis basis(m.full, m.reduced, weights);
    const SpeechErrorBasis::Stored stored = basis.stored();
    const SpeechErrorBasis back(m.full, m.reduced, weights, stored);
    const SpeechErrorBasis::Stored again = back.stored();
    EXPECT_EQ(again.mouth, stored.mouth);
    EXPECT_EQ(again.gram, stored.gram);
    EXPECT_EQ(again.lengths, stored.lengths);
    EXPECT_EQ(back.mouthWeights(), basis.mouthWeights());
    EXPECT_EQ(back.totalWeight(), basis.totalWeight());
    ASSERT_EQ(back.vectorCount(), basis.vectorCount());
    for (std::size_t a = 0; a < basis.vectorCount(); ++a)
        for (int c = 0; c < 3; ++c)
            for (std::size_t v = 0; v < basis.paddedSize(); ++v)
                ASSERT_EQ(back.coordinate(a, c)[v], basis.coordinate(a, c)[v]) << a << " " << c << " " << v;

    auto wrong = stored;
    wrong.mouth.front() = 1; // a vertex of zero weight
    EXPECT_THROW(SpeechErrorBasis(m.full, m.reduced, weights, wrong), InputError);
    wrong = stored;
    wrong.gram.pop_back();
    EXPECT_THROW(SpeechErrorBasis(m.full, m.reduced, weights, wrong), InputError);
    wrong = stored;
    wrong.lengths.pop_back();
    EXPECT_THROW(SpeechErrorBasis(m.full, m.reduced, weights, wrong), InputError);
}
