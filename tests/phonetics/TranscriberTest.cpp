#include "core/common/Error.h"
#include "core/phonetics/Arpabet.h"
#include "core/phonetics/EspeakTranscriber.h"
#include "core/speech/Utterance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

using namespace vl;

namespace {

std::string join(const std::vector<std::string>& phonemes) {
    std::string text;
    for (const auto& p : phonemes) text += (text.empty() ? "" : " ") + p;
    return text;
}

struct WordCase {
    const char* word;
    const char* arpabet;
};

} // namespace

// American English words and their phonemes as in the CMU Pronouncing Dictionary (stress dropped).
TEST(EspeakTranscriber, KnownWordsGiveTheirArpabet) {
    const WordCase cases[] = {
        {"cat", "K AE T"},
        {"thought", "TH AO T"},
        {"measure", "M EH ZH ER"},
        {"judge", "JH AH JH"},
        {"sing", "S IH NG"},
        {"boy", "B OY"},
        {"house", "HH AW S"},
        {"cheese", "CH IY Z"},
        {"she", "SH IY"},
        {"vision", "V IH ZH AH N"},
        {"yes", "Y EH S"},
        {"water", "W AO T ER"},
        {"bird", "B ER D"},
        {"car", "K AA R"},
        {"four", "F AO R"},
        {"care", "K EH R"},
        {"poor", "P UH R"},
        {"fire", "F AY ER"},
        {"button", "B AH T AH N"},
        {"little", "L IH T AH L"},
        {"go", "G OW"},
        {"day", "D EY"},
        {"book", "B UH K"},
        {"two", "T UW"},
        {"father", "F AA DH ER"},
        {"thin", "TH IH N"},
        {"hello", "HH AH L OW"},
    };
    auto transcriber = makeEspeakTranscriber("en-us");
    ASSERT_EQ(transcriber->notation(), PhonemeNotation::Arpabet);
    for (const auto& c : cases) EXPECT_EQ(join(transcriber->transcribe(c.word)), c.arpabet) << c.word;
    EXPECT_TRUE(transcriber->skippedSymbols().empty());
}

TEST(EspeakTranscriber, WholeTextAcrossClausesAndLines) {
    auto transcriber = makeEspeakTranscriber();
    // Clauses end at punctuation and blank lines; every one must be transcribed, in order, with a
    // pause after each (none after the last clause when the text ends without punctuation).
    EXPECT_EQ(join(transcriber->transcribe("Yes, sing.\n\nBoy! Cat?\nhouse")),
              "Y EH S sil S IH NG sil B OY sil K AE T sil HH AW S");
    EXPECT_EQ(join(transcriber->transcribe("Boy! \"Cat.\"  ")), "B OY sil K AE T sil");
    EXPECT_TRUE(transcriber->transcribe("").empty());
    EXPECT_TRUE(transcriber->transcribe(" ... ,,, ;;; ").empty());
}

TEST(EspeakTranscriber, EveryPhonemeOfLongTextIsInTheInventory) {
    auto transcriber = makeEspeakTranscriber();
    const auto phonemes = transcriber->transcribe(
        "The quick brown fox jumps over the lazy dog; pack my box with five dozen liquor jugs. "
        "Sphinx of black quartz, judge my vow! How vexingly quick daft zebras jump.");
    EXPECT_GT(phonemes.size(), 100u);
    for (const auto& p : phonemes) EXPECT_TRUE(findArpabet(p) || p == kSilencePhoneme) << p;
    EXPECT_EQ(std::count(phonemes.begin(), phonemes.end(), kSilencePhoneme), 5); // ; . , ! .
}

// espeak writes a pause inside a clause (before "and" in a long clause, at a quotation mark);
// each is one silence, and the phoneme written right after a pause marker is kept.
TEST(EspeakTranscriber, PausesInsideAClauseAreSilences) {
    auto transcriber = makeEspeakTranscriber();
    EXPECT_EQ(join(transcriber->transcribe("They act as a prism and form a rainbow")),
              "DH EY AE K T AE Z AH P R IH Z AH M sil AE N D F AO R M AH R EY N B OW");
    EXPECT_EQ(join(transcriber->transcribe("He said. \"Quoted\" again")),
              "HH IY S EH D sil K W OW T IH D sil AH G EH N");
    EXPECT_TRUE(transcriber->transcribe(" ... ,,, ;;; ").empty());
}

TEST(EspeakTranscriber, OtherLanguagesPauseAtPunctuation) {
    auto german = makeEspeakTranscriber("de");
    EXPECT_EQ(join(german->transcribe("Haus, Haus.")), "h aʊ s sil h aʊ s sil");
}

TEST(EspeakTranscriber, ForeignLetterNamesAreSkippedNotMisCounted) {
    auto transcriber = makeEspeakTranscriber("en-us");
    const auto phonemes = transcriber->transcribe("Москва");
    for (const auto& p : phonemes) EXPECT_NE(findArpabet(p), nullptr) << p;
    EXPECT_FALSE(transcriber->skippedSymbols().empty());
}

TEST(EspeakTranscriber, OtherLanguagesGiveIpa) {
    auto german = makeEspeakTranscriber("de");
    EXPECT_EQ(german->notation(), PhonemeNotation::Ipa);
    EXPECT_EQ(join(german->transcribe("Haus")), "h aʊ s");
    // Switching back and forth between voices keeps each transcriber's own voice.
    auto english = makeEspeakTranscriber("en-us");
    EXPECT_EQ(join(english->transcribe("house")), "HH AW S");
    EXPECT_EQ(join(german->transcribe("Haus")), "h aʊ s");
}

TEST(EspeakTranscriber, VoicesByLanguageCode) {
    // British English is espeak-ng's voice "en", language code "en-gb": both names work.
    EXPECT_EQ(join(makeEspeakTranscriber("en-gb")->transcribe("house")), "HH AW S");
    EXPECT_EQ(join(makeEspeakTranscriber("en")->transcribe("house")), "HH AW S");
}

TEST(EspeakTranscriber, UnknownVoiceIsAnInputErrorNamingIt) {
    try {
        makeEspeakTranscriber("xx-nonexistent");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("xx-nonexistent"), std::string::npos) << e.what();
    }
}

TEST(EspeakTranscriber, ConcurrentUseGivesTheSameResults) {
    const std::string text = "Measure the judge's house, and sing to the boy.";
    const auto expected = join(makeEspeakTranscriber()->transcribe(text));
    std::vector<std::string> results(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < results.size(); ++t)
        threads.emplace_back([&, t] {
            auto transcriber = makeEspeakTranscriber(t % 2 ? "en-us" : "de");
            for (int i = 0; i < 20; ++i) {
                const auto result = join(transcriber->transcribe(text));
                if (t % 2) results[t] = result;
            }
        });
    for (auto& thread : threads) thread.join();
    EXPECT_EQ(results[1], expected);
    EXPECT_EQ(results[3], expected);
}

TEST(EspeakTranscriber, ListsInstalledVoices) {
    const auto voices = espeakVoiceNames();
    EXPECT_NE(std::find(voices.begin(), voices.end(), "en-us"), voices.end());
    EXPECT_TRUE(std::is_sorted(voices.begin(), voices.end()));
}
