#include "PhoneticsTestSupport.h"

#include "core/common/Error.h"
#include "core/phonetics/CorpusText.h"

#include <gtest/gtest.h>

#include <random>

using namespace vl;

namespace {

struct Collected {
    std::vector<std::string> chunks;
    std::string joined() const {
        std::string all;
        for (const auto& c : chunks) all += c;
        return all;
    }
};

CorpusChunkFn collectInto(Collected& collected) {
    return [&collected](std::string_view chunk, std::uint64_t, std::uint64_t) {
        collected.chunks.emplace_back(chunk);
    };
}

// Expects an InputError whose message names `source` and contains `phrase`.
template <typename Fn> void expectInputError(Fn fn, const std::string& source, const std::string& phrase) {
    try {
        fn();
        FAIL() << "expected InputError about " << phrase;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(source), std::string::npos) << message;
        EXPECT_NE(message.find(phrase), std::string::npos) << message;
    }
}

std::string randomProse(std::mt19937& rng, std::size_t words) {
    const char* vocabulary[] = {"the", "cat",   "sat",  "on",    "mat",     "über", "naïve",  "zoë",
                                "boy", "house", "sing", "judge", "measure", "a",    "thought"};
    const char* separators[] = {" ", " ", " ", ", ", ". ", "! ", "\n", "\n\n", "; ", "  "};
    std::string text;
    for (std::size_t i = 0; i < words; ++i) {
        text += vocabulary[rng() % std::size(vocabulary)];
        text += separators[rng() % std::size(separators)];
    }
    return text;
}

} // namespace

TEST(CorpusText, ChunksReassembleTheTextAndEndAtBoundaries) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        const std::string text = randomProse(rng, 50 + rng() % 2000);
        const std::size_t chunkBytes = 16 + rng() % 400;
        Collected collected;
        const auto stats = forEachTextChunk(text, "prose", collectInto(collected), chunkBytes);
        EXPECT_EQ(collected.joined(), text);
        EXPECT_EQ(stats.bytes, text.size());
        EXPECT_EQ(stats.replacedBytes, 0u);
        for (std::size_t i = 0; i + 1 < collected.chunks.size(); ++i) {
            const char last = collected.chunks[i].back();
            EXPECT_TRUE(last == ' ' || last == '\n') << "chunk " << i << " ends inside a word";
        }
    }
}

TEST(CorpusText, OneGiantWordIsCutOnCharacterBoundaries) {
    std::string word;
    for (int i = 0; i < 3000; ++i) word += "é€"; // 2- and 3-byte characters, no space at all
    Collected collected;
    forEachTextChunk(word, "word", collectInto(collected), 100);
    EXPECT_GT(collected.chunks.size(), 10u);
    EXPECT_EQ(collected.joined(), word); // a cut inside a character would have been replaced
}

TEST(CorpusText, FileIsStreamedWithProgress) {
    test::PhoneticsScratch dir("stream");
    std::mt19937 rng(3);
    const std::string text = randomProse(rng, 20000);
    const auto file = dir.write("corpus.txt", "\xEF\xBB\xBF" + text); // with a UTF-8 byte order mark
    Collected collected;
    std::uint64_t lastDone = 0, total = 0;
    const auto stats = forEachCorpusChunk(
        file,
        [&](std::string_view chunk, std::uint64_t done, std::uint64_t size) {
            collected.chunks.emplace_back(chunk);
            EXPECT_GT(done, lastDone);
            lastDone = done;
            total = size;
        },
        4096);
    EXPECT_EQ(collected.joined(), text);
    EXPECT_GT(collected.chunks.size(), 5u);
    EXPECT_EQ(total, text.size() + 3);
    EXPECT_EQ(lastDone, total);
    EXPECT_EQ(stats.bytes, text.size());
}

TEST(CorpusText, EmptyAndBlankFilesAreErrorsNamingTheFile) {
    test::PhoneticsScratch dir("empty");
    const auto empty = dir.write("empty.txt", "");
    const auto blank = dir.write("blank.txt", " \n\n\t \r\n");
    const auto nothing = [](std::string_view, std::uint64_t, std::uint64_t) {};
    expectInputError([&] { forEachCorpusChunk(empty, nothing); }, "empty.txt", "empty file");
    expectInputError([&] { forEachCorpusChunk(blank, nothing); }, "blank.txt", "only white space");
    expectInputError([&] { forEachCorpusChunk(dir.path() / "missing.txt", nothing); }, "missing.txt",
                     "not found");
    expectInputError([&] { forEachCorpusChunk(dir.path(), nothing); }, dir.path().string(), "directory");
}

TEST(CorpusText, BinaryFilesAreErrorsNamingTheFile) {
    test::PhoneticsScratch dir("binary");
    const auto nothing = [](std::string_view, std::uint64_t, std::uint64_t) {};
    std::string withNul = "Some text that looks fine\n";
    withNul += '\0';
    withNul += "and then a NUL byte.";
    expectInputError([&] { forEachCorpusChunk(dir.write("nul.bin", withNul), nothing); }, "nul.bin",
                     "NUL byte at offset 26");

    std::mt19937 rng(11);
    std::string noise;
    for (int i = 0; i < 100000; ++i) noise += static_cast<char>(0x80 + rng() % 0x80); // mostly invalid UTF-8
    expectInputError([&] { forEachCorpusChunk(dir.write("noise.dat", noise), nothing); }, "noise.dat",
                     "binary file");
    expectInputError(
        [&] { forEachCorpusChunk(dir.write("utf16.txt", std::string("\xFF\xFEh\0i\0", 6)), nothing); },
        "utf16.txt", "UTF-16");
    // Too many control characters is binary too, even without NUL or invalid UTF-8.
    expectInputError(
        [&] { forEachCorpusChunk(dir.write("ctrl.txt", std::string(50, '\x01') + "text"), nothing); },
        "ctrl.txt", "binary file");
}

TEST(CorpusText, StrayLatin1BytesAreReplacedNotFatal) {
    test::PhoneticsScratch dir("latin1");
    std::string text;
    for (int i = 0; i < 200; ++i)
        text += "A caf\xE9 in the old town, and a na\xEFve reader.\n"; // Latin-1 é, ï
    Collected collected;
    const auto stats = forEachCorpusChunk(dir.write("latin1.txt", text), collectInto(collected));
    EXPECT_EQ(stats.replacedBytes, 400u);
    const std::string joined = collected.joined();
    EXPECT_EQ(joined.size(), text.size());
    EXPECT_EQ(joined.find('\xE9'), std::string::npos);
    EXPECT_NE(joined.find("caf  in"), std::string::npos);
}

TEST(CorpusText, OverlongAndSurrogateSequencesAreInvalid) {
    // C0 AF (overlong '/'), ED A0 80 (a UTF-16 surrogate), F4 90 80 80 (above U+10FFFF): 9 bytes.
    const std::string text = "ok \xC0\xAF ok \xED\xA0\x80 ok \xF4\x90\x80\x80 " + std::string(200, 'x');
    Collected collected;
    const auto stats = forEachTextChunk(text, "odd", collectInto(collected));
    EXPECT_EQ(stats.replacedBytes, 9u);
}
