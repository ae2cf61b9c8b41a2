#include "SpeechTestModels.h"

#include "core/common/Error.h"
#include "core/speech/TrackKeyframes.h"
#include "core/speech/VisemeTrack.h"

#include <gtest/gtest.h>

using namespace vl;

TEST(VisemeTrack, CuesAreContiguousMergedRunsOfOneKey) {
    // v0 v1 v1 | v2 ; reduced: {v0, v1} {v2}: P0 P2 P3 merge into one cue there.
    const auto m = test::speechModels(3, {0, 0, 1}, 1);
    const auto phonemes = test::timed({{"sil", 0.1}, {"P2", 0.05}, {"P3", 0.07}, {"P4", 0.1}, {"sil", 0.2}});
    const auto fullKeys = keysOfPhonemes(phonemes, m.full, "t");
    const auto full = cuesOf(phonemes, fullKeys, m.full);
    ASSERT_EQ(full.size(), 4u);
    EXPECT_EQ(full[0], (Cue{0.0, 0.1, "v0"}));
    EXPECT_EQ(full[1].value, "v1");
    EXPECT_DOUBLE_EQ(full[1].end, phonemes[2].end);
    EXPECT_EQ(full[3].value, "v0");
    EXPECT_NO_THROW(checkCues(full, "full"));
    const auto reducedKeys = keysOfPhonemes(phonemes, m.reduced, "t");
    const auto reduced = cuesOf(phonemes, reducedKeys, m.reduced);
    ASSERT_EQ(reduced.size(), 3u);
    EXPECT_EQ(reduced[0].value, "v0+v1");
    EXPECT_DOUBLE_EQ(reduced[0].end, phonemes[2].end);
    EXPECT_EQ(reduced[1].value, "v2");
    EXPECT_DOUBLE_EQ(reduced.back().end, phonemes.back().end);
    EXPECT_NO_THROW(checkCues(reduced, "reduced"));
}

TEST(VisemeTrack, UnmappedSilenceIsRestOtherUnmappedPhonemesAreListed) {
    const auto m = test::speechModels(2, {0, 1}, 2, false);
    const auto phonemes = test::timed({{"sil", 0.1}, {"P1", 0.1}, {"sil", 0.1}});
    const auto keys = keysOfPhonemes(phonemes, m.full, "t");
    EXPECT_EQ(keys, (std::vector<int>{kNeutralKey, 0, kNeutralKey}));
    EXPECT_EQ(cuesOf(phonemes, keys, m.full).front().value, kRestCue);
    try {
        keysOfPhonemes(test::timed({{"XX", 0.1}, {"P0", 0.1}, {"YY", 0.1}, {"XX", 0.1}}), m.full, "say");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "say: the phoneme -> viseme map does not map XX, YY");
    }
}

TEST(VisemeTrack, CueChecksNameTheCue) {
    EXPECT_THROW(checkCues({}, "c"), InputError);
    const std::vector<Cue> gap = {{0, 0.1, "A"}, {0.2, 0.3, "B"}};
    try {
        checkCues(gap, "t.json:/mouthCues");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("t.json:/mouthCues/1: starts at"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(checkCues(std::vector<Cue>{{0, 0, "A"}}, "c"), InputError);
}

TEST(TrackKeyframes, ShortPhonemesOneKeyframeLongOnesHold) {
    const auto phonemes = test::timed({{"sil", 0.3}, {"P", 0.05}, {"AA", 0.2}, {"HH", 0.04}});
    const std::vector<int> keys = {kNeutralKey, 1, 2, 0};
    const PlaybackSettings settings;
    const auto keyframes = keyframesOf(phonemes, keys, settings);
    ASSERT_EQ(keyframes.size(), 6u);
    EXPECT_EQ(keyframes[0].key, runtime::kRestKey);
    EXPECT_DOUBLE_EQ(keyframes[0].time, settings.hold);
    EXPECT_DOUBLE_EQ(keyframes[1].time, 0.3 - settings.hold);
    EXPECT_DOUBLE_EQ(keyframes[2].time, 0.325);
    EXPECT_EQ(keyframes[2].key, 1u);
    EXPECT_GT(keyframes[2].dominance, keyframes[5].dominance); // P dominates, HH yields
    for (std::size_t i = 1; i < keyframes.size(); ++i) EXPECT_GT(keyframes[i].time, keyframes[i - 1].time);
    EXPECT_EQ(fromString<runtime::Interpolation>("dominance"), runtime::Interpolation::Dominance);
    // A phoneme of 2,646 samples at 22,050 Hz (0.12 s = 2 x hold, a hair more after rounding) after
    // 1,436 samples: its hold times round to reversed ones; one keyframe instead (issue 34: 3 % of
    // ten-word sentences failed with "time does not increase").
    const std::vector<TimedPhoneme> edge = {{"sil", 0, 1436 / 22050.0},
                                            {"P", 1436 / 22050.0, 4082 / 22050.0}};
    const auto held = keyframesOf(edge, std::vector<int>{kNeutralKey, 1}, settings);
    for (std::size_t i = 1; i < held.size(); ++i) EXPECT_GT(held[i].time, held[i - 1].time) << i;
    EXPECT_FALSE(fromString<runtime::Interpolation>("spline"));
}
