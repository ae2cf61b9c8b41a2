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

TEST(Frequencies, HostileJsonIsADataErrorNamingTheFile) {
    // Deep nesting crashed the reader (stack overflow); 1e999 ended as an internal error.
    expectError([] { loadFrequencyFile(writeTemp("deep.json", std::string(100000, '[') + "]")); },
                "visemelab_freq_deep.json: /0/0/0");
    expectError([] { loadFrequencyFile(writeTemp("inf.json", R"({"visemes": {"aa": 1e999}})")); },
                "visemelab_freq_inf.json: /visemes/aa: number out of range: 1e999");
    expectError([] { loadFrequencyFile(writeTemp("dup.json", R"({"aa": 1, "aa": 2})")); },
                "visemelab_freq_dup.json: /aa: duplicate key");
    expectError([] { loadFrequencyFile(writeTemp("arr.json", R"({"phonemes": [["AA", 1], ["AA", 2]]})")); },
                "visemelab_freq_arr.json:/phonemes/1: 'AA' is listed twice");
    expectError([] { loadPhonemeMapFile(writeTemp("mdeep.json", "{\"map\":" + std::string(100, '{'))); },
                "visemelab_freq_mdeep.json: /map/");
    expectError([] { loadPhonemeMapFile(writeTemp("mnum.json", R"({"map": {"AA": 1e999}})")); },
                "visemelab_freq_mnum.json: /map/AA: number out of range");
    expectError([] { loadPhonemeMapFile(writeTemp("mval.json", R"({"map": {"AA": 3}})")); },
                "visemelab_freq_mval.json:/map/AA: expected a viseme name, found number");
    expectError([] { loadFrequencyFile(writeTemp("bom.csv", "\xEF\xBB\xBF \n")); }, "empty frequency file");
}

TEST(Frequencies, ErrorsFoundAfterLoadingNameTheFile) {
    expectError([] { visemeFrequencies(loadFrequencyFile(writeTemp("m.csv", "aa,1\nPP,1\n")), kNames); },
                "visemelab_freq_m.csv: no frequency given for viseme 'FF'");
    FrequencySource source = loadFrequencyFile(writeTemp("p.json", R"({"phonemes": {"AA": 1, "B": 1}})"));
    source.map = loadPhonemeMapFile(writeTemp("pm.csv", "AA,aa\nB,nope\n"));
    expectError([&] { visemeFrequencies(source, kNames); },
                "visemelab_freq_pm.csv: phoneme 'B' maps to viseme 'nope'");
}

TEST(Frequencies, ByteOrderMarkIsSkipped) {
    const auto src = loadFrequencyFile(writeTemp("bom2.csv", "\xEF\xBB\xBF"
                                                             "aa,1\nPP,1\nFF,2\n"));
    EXPECT_EQ(visemeFrequencies(src, kNames), (std::vector<double>{0.25, 0.25, 0.5}));
}

TEST(Frequencies, LongTablesAreCheckedInLinearTime) {
    // 200k rows took minutes with the old pairwise duplicate checks; a hash set takes milliseconds.
    std::string csv, map;
    for (int i = 0; i < 200000; ++i) {
        csv += "p" + std::to_string(i) + "," + std::to_string(i % 7) + "\n";
        map += "p" + std::to_string(i) + "," + kNames[static_cast<std::size_t>(i) % 3] + "\n";
    }
    FrequencySource source;
    source.phonemes = loadFrequencyFile(writeTemp("long.csv", csv)).visemeFrequencies;
    source.map = loadPhonemeMapFile(writeTemp("longmap.csv", map));
    EXPECT_EQ(source.phonemes.entries.size(), 200000u);
    EXPECT_EQ(visemeFrequencies(source, kNames).size(), 3u);
    expectError([&] { loadFrequencyFile(writeTemp("longdup.csv", csv + "p5,1\n")); },
                "visemelab_freq_longdup.csv:200001: 'p5' is listed twice");
}
