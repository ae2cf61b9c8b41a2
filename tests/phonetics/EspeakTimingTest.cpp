#include "core/phonetics/EspeakTiming.h"

#include <gtest/gtest.h>

using namespace vl;

namespace {

std::string describe(const std::vector<SampleTimedPhoneme>& phonemes) {
    std::string text;
    for (const auto& p : phonemes)
        text += (text.empty() ? "" : " ") + p.phoneme + "@" + std::to_string(int(p.start));
    return text;
}

std::vector<SampleTimedPhoneme> timed(const std::vector<EspeakPhonemeEvent>& events, std::int64_t total) {
    std::map<std::string, std::size_t> skipped;
    return timeEspeakPhonemes(events, total, skipped);
}

} // namespace

TEST(EspeakTiming, LeadingAudioIsSilenceAndEachEventLastsUntilTheNext) {
    // "hello," as espeak-ng 1.51 en-us times it (sample positions at 22050 Hz).
    const auto result =
        timed({{"h", 264, true}, {"@", 1384}, {"l", 2472}, {"oU", 4840}, {"_:", 9692}, {"_", 12999}}, 12999);
    EXPECT_EQ(describe(result), "sil@0 HH@264 AH@1384 L@2472 OW@4840 sil@9692");
}

TEST(EspeakTiming, TwoPhonemeMnemonicsSplitTheirTimeAndDroppedOnesExtendThePrevious) {
    // "car" K AA R: A@ gives AA R and its 400 samples are halved. "bird" [b 3: r d]: the r after
    // the r-coloured vowel is dropped and ER keeps its time. An unknown symbol does the same.
    EXPECT_EQ(describe(timed({{"k", 0, true}, {"A@", 100}}, 500)), "K@0 AA@100 R@300");
    EXPECT_EQ(describe(timed({{"b", 0, true}, {"3:", 100}, {"r", 300}, {"d", 400}}, 500)),
              "B@0 ER@100 D@400");
    std::map<std::string, std::size_t> skipped;
    const std::vector<EspeakPhonemeEvent> foreign = {{"b", 0, true}, {"R2", 100}, {"d", 400}};
    EXPECT_EQ(describe(timeEspeakPhonemes(foreign, 500, skipped)), "B@0 D@400");
    EXPECT_EQ(skipped["R2"], 1u);
}

TEST(EspeakTiming, PausesMergeAndZeroLengthEventsVanish) {
    // "_:" then "_" at the same and at a later sample, then a word; a glottal onset "_!" gives its
    // time to the phoneme before it; a pause right at the end of the audio lasts 0 and is dropped.
    const auto result = timed({{"s", 0, true},
                               {"_:", 100},
                               {"_", 200},
                               {"_", 200},
                               {"_!", 300, true},
                               {"i:", 350},
                               {"_!", 400},
                               {"t", 450},
                               {"_:", 600}},
                              600);
    EXPECT_EQ(describe(result), "S@0 sil@100 IY@350 T@450");
}

TEST(EspeakTiming, EveryResultIsStrictlyIncreasingFromZero) {
    // Events out of order or beyond the audio are clamped; the result never goes back in time.
    const auto result = timed({{"m", 50, true}, {"a", 40}, {"n", 900}, {"_:", 30}}, 400);
    ASSERT_FALSE(result.empty());
    EXPECT_EQ(result.front().start, 0.0);
    for (std::size_t i = 1; i < result.size(); ++i) EXPECT_GT(result[i].start, result[i - 1].start);
    EXPECT_LT(result.back().start, 400.0);
    EXPECT_TRUE(timed({}, 0).empty());
    EXPECT_EQ(describe(timed({}, 100)), "sil@0");
}

TEST(EspeakTiming, PhonemeWrittenAfterAPauseMarkerKeepsTheSecondHalf) {
    EXPECT_EQ(describe(timed({{"_:k", 0, true}, {"w", 200}}, 300)), "sil@0 K@100 W@200");
}
