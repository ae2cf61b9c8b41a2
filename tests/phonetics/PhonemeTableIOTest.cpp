#include "PhoneticsTestSupport.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/phonetics/PhonemeTableIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace vl;

namespace {

FrequencyTable sampleTable() {
    FrequencyTable table;
    table.entries = {{"AH", 1234}, {"N", 977}, {"T", 977}, {"ZH", 3}, {"OY", 0}};
    return table;
}

PhonemeVisemeMap sampleMap() {
    PhonemeVisemeMap map;
    map.entries = {{"AH", "aa"}, {"N", "nn"}, {"T", "DD"}, {"ZH", "CH"}, {"OY", "oh"}};
    return map;
}

} // namespace

TEST(PhonemeTableIO, CsvRoundTripKeepsOrderAndCounts) {
    test::PhoneticsScratch dir("csv");
    const auto file = dir.path() / "table.csv";
    savePhonemeTable(file, sampleTable(), {"en-us", "corpus.txt"});
    const std::string csv = readFileToString(file);
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "phoneme,count,frequency,ipa");
    EXPECT_NE(csv.find("AH,1234,0.386713,ʌ\n"), std::string::npos) << csv;
    EXPECT_EQ(loadPhonemeTable(file).entries, sampleTable().entries);
}

TEST(PhonemeTableIO, JsonRoundTripWithMapIsAFrequencyFile) {
    test::PhoneticsScratch dir("json");
    const auto file = dir.path() / "table.json";
    const auto map = sampleMap();
    savePhonemeTable(file, sampleTable(), {"en-us", "corpus.txt"}, &map);
    const auto doc = nlohmann::json::parse(readFileToString(file));
    EXPECT_EQ(doc["voice"], "en-us");
    EXPECT_EQ(doc["total"], 3191);
    EXPECT_EQ(doc["ipa"]["ZH"], "ʒ");
    // What `visemelab reduce --freq-file` reads:
    const FrequencySource source = loadFrequencyFile(file);
    ASSERT_TRUE(source.isPhonemeBased());
    EXPECT_EQ(source.phonemes.entries, sampleTable().entries);
    EXPECT_EQ(source.map.entries.size(), 5u);
    EXPECT_EQ(*source.map.visemeOf("T"), "DD");
    EXPECT_EQ(loadPhonemeTable(file).entries, sampleTable().entries);
    const auto combined = loadPhonemeFrequencySource(file, {});
    EXPECT_EQ(combined.map.entries.size(), 5u);
}

TEST(PhonemeTableIO, CsvTablePlusSeparateMapFile) {
    test::PhoneticsScratch dir("table-map");
    const auto table = dir.path() / "table.csv";
    const auto mapFile = dir.path() / "map.csv";
    savePhonemeTable(table, sampleTable(), {});
    savePhonemeMap(mapFile, sampleMap());
    EXPECT_EQ(readFileToString(mapFile).substr(0, 22), "phoneme,viseme\nAH,aa\nN");
    const auto source = loadPhonemeFrequencySource(table, mapFile);
    const auto frequencies = visemeFrequencies(source, {"aa", "nn", "DD", "CH", "oh", "sil"});
    EXPECT_NEAR(frequencies[0], 1234.0 / 3191.0, 1e-15);
    EXPECT_NEAR(frequencies[2], 977.0 / 3191.0, 1e-15);
    EXPECT_EQ(frequencies[5], 0.0);

    PhonemeVisemeMap partial;
    partial.entries = {{"AH", "aa"}, {"T", "DD"}};
    savePhonemeMap(mapFile, partial);
    try {
        loadPhonemeFrequencySource(table, mapFile);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("3 phonemes not mapped to any viseme: N, ZH, OY"),
                  std::string::npos)
            << e.what();
    }
    try {
        loadPhonemeFrequencySource(table, {});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no phoneme -> viseme map"), std::string::npos) << e.what();
    }
}

TEST(PhonemeTableIO, MapJsonRoundTrip) {
    test::PhoneticsScratch dir("map-json");
    const auto file = dir.path() / "map.json";
    savePhonemeMap(file, sampleMap());
    const auto loaded = loadPhonemeMapFile(file);
    ASSERT_EQ(loaded.entries.size(), 5u);
    for (const auto& [phoneme, viseme] : sampleMap().entries) EXPECT_EQ(*loaded.visemeOf(phoneme), viseme);
}

TEST(PhonemeTableIO, BadTablesAndNamesAreRefused) {
    FrequencyTable negative;
    negative.entries = {{"AH", 3}, {"T", -1}};
    EXPECT_THROW(relativeFrequencies(negative, "t"), InputError);
    FrequencyTable zero;
    zero.entries = {{"AH", 0}, {"T", 0}};
    EXPECT_THROW(relativeFrequencies(zero, "t"), InputError);
    const auto shares = relativeFrequencies(sampleTable(), "t");
    EXPECT_NEAR(shares[0] + shares[1] + shares[2] + shares[3] + shares[4], 1.0, 1e-15);

    test::PhoneticsScratch dir("bad");
    EXPECT_THROW(savePhonemeTable(dir.path() / "table.txt", sampleTable(), {}), InputError);
    const auto map = sampleMap();
    EXPECT_THROW(savePhonemeTable(dir.path() / "table.csv", sampleTable(), {}, &map), InputError);
    EXPECT_THROW(loadPhonemeTable(dir.write("neg.csv", "phoneme,count\nAH,-3\n")), InputError);
}

TEST(PhonemeTableIO, TextTableAlignsIpaColumns) {
    const std::string text = formatPhonemeTableText(sampleTable());
    EXPECT_NE(text.find("AH       ʌ           1234    38.67 %\n"), std::string::npos) << text;
    EXPECT_NE(text.find("ZH       ʒ              3     0.09 %\n"), std::string::npos) << text;
    EXPECT_EQ(ipaOf("CH"), "tʃ");
    EXPECT_EQ(ipaOf("ʁ"), "ʁ"); // IPA tables name phonemes by their IPA already
}
