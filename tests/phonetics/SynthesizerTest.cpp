#include "PhoneticsTestSupport.h"

#include "core/common/Error.h"
#include "core/phonetics/Arpabet.h"
#include "core/phonetics/EspeakSynthesizer.h"
#include "core/phonetics/EspeakTranscriber.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace vl;

namespace {

constexpr const char* kParagraph =
    "When the sunlight strikes raindrops in the air, they act as a prism and form a rainbow. The "
    "rainbow is a division of white light into many beautiful colors. Four poor fire fighters came at "
    "noon; the judge measures the house!";

std::vector<std::string> withoutPauses(const std::vector<std::string>& phonemes) {
    std::vector<std::string> speech;
    for (const auto& p : phonemes)
        if (p != kSilencePhoneme) speech.push_back(p);
    return speech;
}

std::vector<std::string> names(const Utterance& utterance) {
    std::vector<std::string> result;
    for (const auto& p : utterance.phonemes) result.push_back(p.phoneme);
    return result;
}

// Index of the first phoneme of the utterance starting at `from` equal to `name`.
std::size_t find(const Utterance& u, const std::string& name, std::size_t from = 0) {
    for (std::size_t i = from; i < u.phonemes.size(); ++i)
        if (u.phonemes[i].phoneme == name) return i;
    return u.phonemes.size();
}

} // namespace

TEST(EspeakSynthesizer, TimingIsMonotonicContiguousAndCoversTheAudio) {
    auto synthesizer = makeEspeakSynthesizer();
    const Utterance u = synthesizer->synthesize(kParagraph);
    ASSERT_GT(u.sampleRate, 0);
    ASSERT_GT(u.samples.size(), std::size_t(u.sampleRate)); // several seconds of speech
    EXPECT_NO_THROW(checkTimedPhonemes(u.phonemes, "utterance"));
    EXPECT_EQ(u.phonemes.front().start, 0.0);
    EXPECT_DOUBLE_EQ(u.duration(), double(u.samples.size()) / u.sampleRate);
    for (std::size_t i = 0; i < u.phonemes.size(); ++i) {
        const auto& p = u.phonemes[i];
        EXPECT_TRUE(findArpabet(p.phoneme) || p.phoneme == kSilencePhoneme) << p.phoneme;
        if (i > 0) {
            EXPECT_FALSE(p.phoneme == kSilencePhoneme && u.phonemes[i - 1].phoneme == kSilencePhoneme);
        }
    }
    EXPECT_TRUE(synthesizer->skippedSymbols().empty());
}

// The slow obvious reference: the synthesiser speaks the phonemes the transcriber reads.
TEST(EspeakSynthesizer, SpeaksThePhonemesTheTranscriberReads) {
    auto synthesizer = makeEspeakSynthesizer();
    auto transcriber = makeEspeakTranscriber("en-us");
    for (const char* text : {"Hello, world. How are you?", "The judge measures the house.", kParagraph})
        EXPECT_EQ(withoutPauses(names(synthesizer->synthesize(text))),
                  withoutPauses(transcriber->transcribe(text)))
            << text;
}

TEST(EspeakSynthesizer, SilenceAtPunctuationAndAtTheStart) {
    const Utterance u = makeEspeakSynthesizer()->synthesize("Hello, world. How are you?");
    EXPECT_EQ(u.phonemes.front().phoneme, "sil");
    // A pause after "hello," (OW) and after "world." (D), each long enough to see.
    const std::size_t ow = find(u, "OW");
    ASSERT_LT(ow + 2, u.phonemes.size());
    EXPECT_EQ(u.phonemes[ow + 1].phoneme, "sil");
    EXPECT_EQ(u.phonemes[ow + 2].phoneme, "W");
    EXPECT_GT(u.phonemes[ow + 1].end - u.phonemes[ow + 1].start, 0.08);
    const std::size_t d = find(u, "D", ow);
    ASSERT_LT(d + 2, u.phonemes.size());
    EXPECT_EQ(u.phonemes[d + 1].phoneme, "sil");
    EXPECT_EQ(u.phonemes[d + 2].phoneme, "HH");
    EXPECT_GT(u.phonemes[d + 1].end - u.phonemes[d + 1].start, 0.15); // a sentence pauses longer
}

TEST(EspeakSynthesizer, RateChangesTheDuration) {
    const auto slow = makeEspeakSynthesizer({"en-us", 120})->synthesize(kParagraph);
    const auto fast = makeEspeakSynthesizer({"en-us", 300})->synthesize(kParagraph);
    EXPECT_GT(slow.duration(), 1.8 * fast.duration());
    EXPECT_EQ(withoutPauses(names(slow)), withoutPauses(names(fast)));
}

TEST(EspeakSynthesizer, AppendingAndStreamingContinueTheTimeline) {
    auto synthesizer = makeEspeakSynthesizer({"en-gb", 175});
    const Utterance first = synthesizer->synthesize("One, two.");
    const Utterance second = synthesizer->synthesize("Three.");
    Utterance both;
    std::vector<std::int16_t> streamed;
    const AudioSink sink = [&](std::span<const std::int16_t> s) {
        streamed.insert(streamed.end(), s.begin(), s.end());
    };
    synthesizer->speak("One, two.", both, sink);
    synthesizer->speak("Three.", both, sink);
    EXPECT_TRUE(both.samples.empty());
    // espeak-ng keeps a little state between calls: lengths agree to a few samples only.
    EXPECT_NEAR(double(streamed.size()), double(first.samples.size() + second.samples.size()), 50);
    EXPECT_NO_THROW(checkTimedPhonemes(both.phonemes, "both"));
    EXPECT_NEAR(both.duration(), double(streamed.size()) / both.sampleRate, 1e-9);
    EXPECT_EQ(withoutPauses(names(both)).size(),
              withoutPauses(names(first)).size() + withoutPauses(names(second)).size());
    Utterance punctuation;
    synthesizer->speak(" ... ", punctuation);
    for (const auto& p : punctuation.phonemes) EXPECT_EQ(p.phoneme, kSilencePhoneme);
}

TEST(EspeakSynthesizer, VoiceAndRateAreChecked) {
    const auto expectError = [](const SpeechVoice& voice, const std::string& phrase) {
        try {
            makeEspeakSynthesizer(voice);
            FAIL() << "expected InputError for " << voice.voice;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
        }
    };
    expectError({"xx-none", 175}, "xx-none");
    expectError({"de", 175}, "English voice");
    expectError({"en-us", 20}, "rate 20");
    expectError({"en-us", 9000}, "rate 9000");
}
