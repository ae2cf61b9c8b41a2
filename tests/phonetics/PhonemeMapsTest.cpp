#include "PhoneticsTestSupport.h"

#include "core/common/Error.h"
#include "core/phonetics/Arpabet.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace vl;

namespace {

const std::vector<std::string> kOculusVisemes = {"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                                 "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};

std::vector<std::string> sortedCopy(std::vector<std::string> names) {
    std::sort(names.begin(), names.end());
    return names;
}

PhonemeVisemeMap bundledMap(const std::string& id) {
    for (const auto& bundled : bundledPhonemeMaps(test::assetsDir()))
        if (bundled.id == id) return loadPhonemeMapFile(bundled.file);
    throw std::runtime_error("no bundled map " + id);
}

} // namespace

TEST(PhonemeMaps, EveryBundledMapCoversTheInventory) {
    const auto maps = bundledPhonemeMaps(test::assetsDir());
    ASSERT_EQ(maps.size(), 4u);
    for (const auto& bundled : maps) {
        SCOPED_TRACE(bundled.file.string());
        const auto map = loadPhonemeMapFile(bundled.file);
        EXPECT_NO_THROW(checkArpabetMap(map, bundled.file.string()));
        EXPECT_EQ(map.entries.size(), 40u);
        EXPECT_NE(map.visemeOf("sil"), nullptr);
    }
}

TEST(PhonemeMaps, BundledMapsUseTheirSetsVisemeNames) {
    // Every viseme of a set gets at least one phoneme; the pause (sil) gets the rest viseme.
    EXPECT_EQ(sortedCopy(mapVisemeNames(bundledMap("oculus"))), sortedCopy(kOculusVisemes));
    EXPECT_EQ(sortedCopy(mapVisemeNames(bundledMap("sample-face"))), sortedCopy(kOculusVisemes));
    const std::vector<std::string> mpeg4 = {"none", "p_b_m", "f_v", "T_D", "t_d", "k_g", "tS_dZ_S", "s_z",
                                            "n_l",  "r",     "A",   "e",   "I",   "Q",   "U"};
    EXPECT_EQ(sortedCopy(mapVisemeNames(bundledMap("mpeg4"))), sortedCopy(mpeg4));
    const std::vector<std::string> rhubarb = {"A", "B", "C", "D", "E", "F", "G", "H", "X"};
    EXPECT_EQ(sortedCopy(mapVisemeNames(bundledMap("rhubarb"))), sortedCopy(rhubarb));
    EXPECT_EQ(*bundledMap("oculus").visemeOf("sil"), "sil");
    EXPECT_EQ(*bundledMap("sample-face").visemeOf("sil"), "sil");
    EXPECT_EQ(*bundledMap("mpeg4").visemeOf("sil"), "none");
    EXPECT_EQ(*bundledMap("rhubarb").visemeOf("sil"), "X");
}

TEST(PhonemeMaps, SpotChecksOfTheStandardAssignments) {
    const auto oculus = bundledMap("oculus");
    for (const char* p : {"P", "B", "M"}) EXPECT_EQ(*oculus.visemeOf(p), "PP") << p;
    for (const char* p : {"F", "V"}) EXPECT_EQ(*oculus.visemeOf(p), "FF") << p;
    for (const char* p : {"TH", "DH"}) EXPECT_EQ(*oculus.visemeOf(p), "TH") << p;
    for (const char* p : {"CH", "JH", "SH"}) EXPECT_EQ(*oculus.visemeOf(p), "CH") << p;
    for (const char* p : {"N", "L"}) EXPECT_EQ(*oculus.visemeOf(p), "nn") << p;
    const auto rhubarb = bundledMap("rhubarb");
    for (const char* p : {"P", "B", "M"}) EXPECT_EQ(*rhubarb.visemeOf(p), "A") << p;
    for (const char* p : {"F", "V"}) EXPECT_EQ(*rhubarb.visemeOf(p), "G") << p;
    EXPECT_EQ(*rhubarb.visemeOf("AA"), "D");
    EXPECT_EQ(*rhubarb.visemeOf("UW"), "F");
    EXPECT_EQ(*rhubarb.visemeOf("L"), "H");
    // MPEG-4 and Oculus are the same partition under other names.
    const auto mpeg4 = bundledMap("mpeg4");
    std::map<std::string, std::string> rename;
    for (const auto& [phoneme, viseme] : oculus.entries) {
        const auto [it, fresh] = rename.emplace(viseme, *mpeg4.visemeOf(phoneme));
        EXPECT_EQ(it->second, *mpeg4.visemeOf(phoneme)) << phoneme;
    }
}

TEST(PhonemeMaps, DefaultTableIsCoveredByEveryMapAndGivesOculusFrequencies) {
    const auto table = loadPhonemeTable(defaultPhonemeTablePath(test::assetsDir()));
    ASSERT_EQ(table.entries.size(), 40u);
    std::vector<std::string> phonemes;
    for (const auto& [phoneme, count] : table.entries) {
        EXPECT_TRUE(findArpabet(phoneme) || phoneme == "sil") << phoneme;
        EXPECT_GT(count, 0) << phoneme;
        phonemes.push_back(phoneme);
    }
    for (const auto& bundled : bundledPhonemeMaps(test::assetsDir()))
        EXPECT_NO_THROW(checkMapCovers(loadPhonemeMapFile(bundled.file), phonemes, bundled.file.string()));

    const auto source = loadPhonemeFrequencySource(defaultPhonemeTablePath(test::assetsDir()),
                                                   test::assetsDir() / "phonemes" / "map_oculus.csv");
    const auto frequencies = visemeFrequencies(source, kOculusVisemes);
    double sum = 0;
    for (const double f : frequencies) sum += f;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // sil has its measured share of pauses: more than the rarest visemes, less than the most common.
    for (std::size_t i = 0; i < frequencies.size(); ++i) EXPECT_GT(frequencies[i], 0.0) << kOculusVisemes[i];
    EXPECT_GT(frequencies[0], 0.02);
    EXPECT_LT(frequencies[0], 0.15);
}

TEST(PhonemeMaps, CoverageErrorListsAllUnmappedPhonemesAtOnce) {
    PhonemeVisemeMap map;
    for (const auto& phoneme : arpabetInventory())
        if (phoneme.symbol != "ZH" && phoneme.symbol != "OY" && phoneme.symbol != "AA")
            map.entries.emplace_back(phoneme.symbol, "x");
    try {
        checkArpabetMap(map, "my_map.csv");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "my_map.csv: 3 phonemes not mapped to any viseme: AA, OY, ZH");
    }
    map.entries.emplace_back("sil", "x"); // the pause is allowed, not required
    map.entries.emplace_back("AX", "x");
    map.entries.emplace_back("sh", "x");
    try {
        checkArpabetMap(map, "my_map.csv");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "my_map.csv: not ARPAbet phonemes (see docs/phonemes.md): AX, sh");
    }
}

TEST(PhonemeMaps, UnmappedSilenceErrorSaysWhatToMapItTo) {
    PhonemeVisemeMap map;
    map.entries = {{"AA", "aa"}};
    try {
        checkMapCovers(map, std::vector<std::string>{"AA", "sil"}, "old_map.csv");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not mapped to any viseme: sil (sil is the pause"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PhonemeMaps, VisemeNamesOutsideTheSetAreListed) {
    PhonemeVisemeMap map;
    map.entries = {{"P", "PP"}, {"B", "PP"}, {"AA", "ah"}, {"F", "FF"}, {"IY", "ee"}};
    EXPECT_NO_THROW(checkMapVisemes(map, std::vector<std::string>{"PP", "ah", "FF", "ee", "sil"}, "m"));
    try {
        checkMapVisemes(map, kOculusVisemes, "m.csv");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not in the viseme set: ah, ee"), std::string::npos) << e.what();
    }
}
