#include "PhoneticsTestSupport.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakTranscriber.h"
#include "core/phonetics/PhonemeCounting.h"

#include <gtest/gtest.h>

#include <random>

using namespace vl;

namespace {

// Phonemes worked out by hand from the CMU dictionary forms of the words:
//   the cat sat on the mat       DH AH  K AE T  S AE T  AO N  DH AH  M AE T
//   a boy sings                  AH  B OY  S IH NG Z
//   the judge measures the house DH AH  JH AH JH  M EH ZH ER Z  DH AH  HH AW S
// and a pause (sil) at each of the . ; . that end the clauses.
constexpr const char* kFixedText = "The cat sat on the mat.\nA boy sings; the judge measures the house.\n";
const std::map<std::string, double> kFixedCounts = {
    {"AH", 6}, {"DH", 4}, {"AE", 3}, {"S", 3},  {"T", 3},  {"JH", 2}, {"M", 2},
    {"Z", 2},  {"AO", 1}, {"AW", 1}, {"B", 1},  {"EH", 1}, {"ER", 1}, {"HH", 1},
    {"IH", 1}, {"K", 1},  {"N", 1},  {"NG", 1}, {"OY", 1}, {"ZH", 1}, {"sil", 3}};

std::map<std::string, double> asMap(const FrequencyTable& table) {
    std::map<std::string, double> counts;
    for (const auto& [phoneme, count] : table.entries)
        if (count > 0) counts[phoneme] = count;
    return counts;
}

} // namespace

TEST(PhonemeCounting, ExactCountsOnAFixedText) {
    test::PhoneticsScratch dir("fixed");
    auto transcriber = makeEspeakTranscriber("en-us");
    const auto result = countPhonemesInFile(dir.write("fixed.txt", kFixedText), *transcriber);
    EXPECT_EQ(asMap(result.counts), kFixedCounts);
    EXPECT_EQ(result.phonemeTotal, 40u);
    EXPECT_EQ(result.notation, PhonemeNotation::Arpabet);
    // All 39 phonemes and sil are listed, most frequent first, ties and unseen ones by name.
    ASSERT_EQ(result.counts.entries.size(), 40u);
    EXPECT_EQ(result.counts.entries[0].first, "AH");
    EXPECT_EQ(result.counts.entries[1].first, "DH");
    EXPECT_EQ(result.counts.entries[2].first, "AE");
    EXPECT_EQ(result.counts.entries[3].first, "S");
    EXPECT_EQ(result.counts.entries[5].first, "sil");
    EXPECT_EQ(result.counts.entries[21].first, "AA");
    EXPECT_EQ(result.counts.entries[21].second, 0.0);
    EXPECT_EQ(result.counts.entries.back().first, "Y");
}

// The slow obvious reference: transcribe the whole text at once. Streaming in small chunks must
// count the same, since chunks end where clauses end.
TEST(PhonemeCounting, StreamedCountsEqualOneShotTranscription) {
    const char* sentences[] = {"The judge measures the house. ", "A boy sings to the cat! ",
                               "Why would water flow uphill? ", "Four poor fire fighters came at noon.\n",
                               "Little buttons, rosy apples; thirty zebras.\n\n"};
    std::mt19937 rng(5);
    std::string text;
    for (int i = 0; i < 400; ++i) text += sentences[rng() % std::size(sentences)];
    auto transcriber = makeEspeakTranscriber("en-us");
    std::map<std::string, double> reference;
    for (const auto& p : transcriber->transcribe(text)) ++reference[p];

    test::PhoneticsScratch dir("stream-count");
    const auto file = dir.write("corpus.txt", text);
    std::uint64_t calls = 0;
    const auto result =
        countPhonemesInFile(file, *transcriber, [&](std::uint64_t, std::uint64_t) { ++calls; });
    EXPECT_EQ(asMap(result.counts), reference);
    const auto inMemory = countPhonemesInText(text, "text", *transcriber);
    EXPECT_EQ(asMap(inMemory.counts), reference);
    EXPECT_GE(calls, 1u);
}

TEST(PhonemeCounting, EmptyBinaryAndSpeechlessFilesAreErrors) {
    test::PhoneticsScratch dir("errors");
    auto transcriber = makeEspeakTranscriber();
    const auto expectError = [&](const std::filesystem::path& file, const std::string& phrase) {
        try {
            countPhonemesInFile(file, *transcriber);
            FAIL() << "expected InputError for " << file;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
        }
    };
    expectError(dir.write("empty.txt", ""), "empty file");
    expectError(dir.write("image.png", std::string("\x89PNG\r\n\x1A\n\0\0\0\rIHDR", 16)), "binary file");
    expectError(dir.write("punctuation.txt", "... ,,, ;;; - -\n"), "no phonemes");
}

TEST(PhonemeCounting, SortedCountTableOrdersByCountThenName) {
    const std::map<std::string, std::uint64_t> counts = {{"b", 2}, {"a", 2}, {"c", 5}};
    const auto ipaTable = sortedCountTable(counts, PhonemeNotation::Ipa);
    ASSERT_EQ(ipaTable.entries.size(), 3u); // IPA tables list only what was seen
    EXPECT_EQ(ipaTable.entries[0].first, "c");
    EXPECT_EQ(ipaTable.entries[1].first, "a");
    EXPECT_EQ(ipaTable.entries[2].first, "b");
    EXPECT_EQ(sortedCountTable({{"AH", 1}}, PhonemeNotation::Arpabet).entries.size(), 40u);
}
