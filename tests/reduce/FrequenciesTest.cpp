#include "core/reduce/Frequencies.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace vl;

namespace {

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("visemelab_freq_" + name);
    std::ofstream(path) << text;
    return path;
}

void expectError(const std::function<void()>& fn, const std::string& fragment) {
    try {
        fn();
        ADD_FAILURE() << "expected an error containing '" << fragment << "'";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

const std::vector<std::string> kNames = {"aa", "PP", "FF"};

} // namespace

TEST(Frequencies, DirectCsvIsNormalised) {
    const auto src = loadFrequencyFile(writeTemp("a.csv", "viseme,frequency\naa,2\nPP,1\n# comment\nFF,1\n"));
    EXPECT_FALSE(src.isPhonemeBased());
    EXPECT_EQ(visemeFrequencies(src, kNames), (std::vector<double>{0.5, 0.25, 0.25}));
}

TEST(Frequencies, PhonemeTablePlusMapSumsPerViseme) {
    const auto src = loadFrequencyFile(writeTemp(
        "b.json",
        R"({"phonemes": {"AA": 3, "P": 1, "B": 1, "F": 2, "V": 1}, "map": {"AA": "aa", "P": "PP", "B": "PP", "F": "FF", "V": "FF"}})"));
    ASSERT_TRUE(src.isPhonemeBased());
    EXPECT_EQ(visemeFrequencies(src, kNames), (std::vector<double>{3.0 / 8, 2.0 / 8, 3.0 / 8}));
}

TEST(Frequencies, SeparateMapFile) {
    FrequencySource src;
    src.phonemes = parseFrequencyCsv("phoneme,frequency\nAA,1\nP,1\n", "t.csv");
    src.map = loadPhonemeMapFile(writeTemp("m.csv", "phoneme,viseme\nAA,aa\nP,PP\n"));
    EXPECT_EQ(visemeFrequencies(src, kNames), (std::vector<double>{0.5, 0.5, 0.0}));
}

TEST(Frequencies, ErrorsNameTheProblem) {
    expectError([] { loadFrequencyFile(writeTemp("c.csv", "aa,1\nPP,-1\n")); },
                "visemelab_freq_c.csv:2: frequency must be");
    expectError([] { loadFrequencyFile(writeTemp("d.csv", "aa,1\nPP,abc\n")); },
                "visemelab_freq_d.csv:2: expected a number");
    expectError([] { loadFrequencyFile(writeTemp("e.csv", "aa,1\naa,2\n")); }, "listed twice");
    expectError([] { loadFrequencyFile(writeTemp("f.csv", "")); }, "empty frequency file");
    expectError([] { loadFrequencyFile(writeTemp("g.json", R"({"aa": "x"})")); },
                ":/aa: expected a non-negative number");
    expectError(
        [] { visemeFrequencies(loadFrequencyFile(writeTemp("h.csv", "aa,0\nPP,0\nFF,0\n")), kNames); },
        "all viseme frequencies are zero");
    expectError([] { visemeFrequencies(loadFrequencyFile(writeTemp("i.csv", "aa,1\nPP,1\n")), kNames); },
                "no frequency given for viseme 'FF'");
    expectError(
        [] { visemeFrequencies(loadFrequencyFile(writeTemp("j.csv", "aa,1\nPP,1\nFF,1\nXX,1\n")), kNames); },
        "unknown viseme 'XX'");
    expectError(
        [] {
            visemeFrequencies(
                loadFrequencyFile(
                    writeTemp("k.json", R"({"phonemes": {"AA": 1, "ZH": 1, "NG": 2}, "map": {"AA": "aa"}})")),
                kNames);
        },
        "phonemes not mapped to any viseme: ZH, NG");
    expectError(
        [] {
            visemeFrequencies(
                loadFrequencyFile(writeTemp("l.json", R"({"phonemes": {"AA": 1}, "map": {"AA": "nope"}})")),
                kNames);
        },
        "maps to viseme 'nope'");
}
