// The phoneme -> viseme map editor's commands: a bundled map assigned to the set's own visemes gives
// each viseme the summed frequency of its phonemes (checked against a plain sum), unassigned rows are
// refused naming their phonemes, and the document never holds an unmapped phoneme.
#include "core/document/PhonemeMapCommands.h"
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/VisemeCommands.h"
#include "core/io/VisemeSetFiles.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"

#include "DocumentTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <random>

namespace vl {
namespace {

using test::faceDocument;
using test::refusal;

const std::filesystem::path kAssets = VISEMELAB_ASSETS_DIR;

FrequencyTable bundledTable() {
    return loadPhonemeTable(defaultPhonemeTablePath(kAssets));
}

PhonemeVisemeMap oculusMap() {
    return loadPhonemeMapFile(kAssets / "phonemes" / "map_oculus.csv");
}

// A set whose visemes carry other names, like the ICT FaceKit mouth shapes.
Document ownNamesDocument() {
    Document document = faceDocument();
    const char* names[] = {"rest",    "mouthClose", "lipTuck", "teeth",  "tongueUp",
                           "back",    "funnelUp",   "hiss",    "nasal",  "roll",
                           "jawOpen", "stretch",    "smile",   "funnel", "pucker"};
    for (int i = 0; i < 15; ++i) document = edit::renameViseme(document, i, names[i]);
    return document;
}

TEST(PhonemeMapCommands, ABundledMapOnItsOwnVisemesNeedsNoAssignment) {
    const Document start = faceDocument();
    const std::vector<edit::MapAssignment> rows =
        edit::suggestMapAssignment(start, bundledTable(), oculusMap());
    ASSERT_EQ(rows.size(), 15u);
    double share = 0.0;
    for (const auto& row : rows) {
        EXPECT_EQ(row.to, row.from);
        share += row.share;
    }
    EXPECT_NEAR(share, 1.0, 1e-12);
    EXPECT_EQ(rows[1].from, "ih"); // order of first appearance in the table (AH, then IH)
    const Document mapped = edit::startPhonemeMap(start, bundledTable(), oculusMap(), rows);
    // The same frequencies as the bundled table and map read as one source.
    const FrequencySource bundled =
        loadPhonemeFrequencySource(defaultPhonemeTablePath(kAssets), kAssets / "phonemes" / "map_oculus.csv");
    EXPECT_EQ(documentFrequencies(mapped), documentFrequencies(edit::setFrequencies(start, bundled)));
}

TEST(PhonemeMapCommands, OwnVisemesGetTheSummedFrequencyOfTheirPhonemes) {
    const Document start = ownNamesDocument();
    std::vector<edit::MapAssignment> rows = edit::suggestMapAssignment(start, bundledTable(), oculusMap());
    for (const auto& row : rows) EXPECT_TRUE(row.to.empty()) << row.from;
    // Unassigned: refused, naming every row and its phonemes.
    const std::string why = refusal([&] { edit::startPhonemeMap(start, bundledTable(), oculusMap(), rows); });
    EXPECT_NE(why.find("PP (M, P, B)"), std::string::npos) << why;
    EXPECT_NE(why.find("sil (sil)"), std::string::npos) << why;

    // A random assignment of the 15 Oculus visemes to the set's 15 names.
    std::mt19937 random(7);
    const std::vector<std::string> names = visemeNames(start);
    for (auto& row : rows) row.to = names[random() % names.size()];
    const Document mapped = edit::startPhonemeMap(start, bundledTable(), oculusMap(), rows);
    // Reference: each viseme's frequency is the plain sum of its phonemes' counts over the total.
    std::map<std::string, double> expected;
    double total = 0.0;
    const FrequencyTable table = bundledTable();
    for (const auto& [phoneme, value] : table.entries) {
        const std::string oculus = *oculusMap().visemeOf(phoneme);
        const auto row =
            std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.from == oculus; });
        expected[row->to] += value;
        total += value;
    }
    const std::vector<double> frequencies = documentFrequencies(mapped);
    const edit::MapCoverage coverage = edit::mapCoverage(mapped);
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_NEAR(frequencies[i], expected[names[i]] / total, 1e-12) << names[i];
        EXPECT_NEAR(coverage.share[i], expected[names[i]] / total, 1e-12) << names[i];
        const bool without = expected[names[i]] == 0.0;
        EXPECT_EQ(coverage.phonemesOf[i].empty(), without);
        EXPECT_EQ(std::count(coverage.visemesWithoutPhoneme.begin(), coverage.visemesWithoutPhoneme.end(),
                             static_cast<int>(i)) == 1,
                  without);
    }
}

TEST(PhonemeMapCommands, NamesMatchIgnoringCaseAndUnlistedPhonemesAreARow) {
    Document start = faceDocument();
    start = edit::renameViseme(start, start.visemes->find("PP"), "pp");
    FrequencyTable table = bundledTable();
    table.entries.emplace_back("XX", 5.0); // a phoneme the map does not know
    std::vector<edit::MapAssignment> rows = edit::suggestMapAssignment(start, table, oculusMap());
    ASSERT_EQ(rows.back().from, edit::kPhonemesNotInMap);
    EXPECT_EQ(rows.back().phonemes, std::vector<std::string>{"XX"});
    EXPECT_TRUE(rows.back().to.empty());
    const auto pp = std::find_if(rows.begin(), rows.end(), [](const auto& r) { return r.from == "PP"; });
    EXPECT_EQ(pp->to, "pp");
    EXPECT_NE(refusal([&] { edit::startPhonemeMap(start, table, oculusMap(), rows); }).find("XX"),
              std::string::npos);
    rows.back().to = "sil";
    const Document mapped = edit::startPhonemeMap(start, table, oculusMap(), rows);
    EXPECT_EQ(*mapped.frequencies.map.visemeOf("XX"), "sil");
    // A row assigned to a name outside the set is refused too.
    rows.back().to = "nowhere";
    EXPECT_NE(refusal([&] { edit::startPhonemeMap(start, table, oculusMap(), rows); }), "(not refused)");
}

TEST(PhonemeMapCommands, RowsNoNameMatchesFollowTheCurrentMap) {
    const Document start = faceDocument();
    const Document oculus = edit::startPhonemeMap(
        start, bundledTable(), oculusMap(), edit::suggestMapAssignment(start, bundledTable(), oculusMap()));
    const PhonemeVisemeMap mpeg4 = loadPhonemeMapFile(kAssets / "phonemes" / "map_mpeg4.csv");
    // Without a phoneme map only the names can suggest: MPEG-4's "e" is the set's "E".
    for (const auto& row : edit::suggestMapAssignment(start, bundledTable(), mpeg4))
        EXPECT_EQ(row.to.empty(), row.from != "e") << row.from;
    // With the Oculus map current, each row goes where most of its phonemes' frequency maps now.
    const std::vector<edit::MapAssignment> rows = edit::suggestMapAssignment(oculus, bundledTable(), mpeg4);
    std::map<std::string, std::string> to;
    for (const auto& row : rows) to[row.from] = row.to;
    EXPECT_EQ(to["p_b_m"], "PP");
    EXPECT_EQ(to["A"], "aa");
    EXPECT_EQ(to["none"], "sil");
    EXPECT_EQ(to["e"], "E");
    for (const auto& row : rows) {
        // The reference: the largest summed frequency over the row's phonemes, by current viseme.
        std::map<std::string, double> mass;
        for (const std::string& phoneme : row.phonemes)
            mass[*oculus.frequencies.map.visemeOf(phoneme)] += *bundledTable().find(phoneme);
        double best = 0.0;
        for (const auto& [viseme, m] : mass) best = std::max(best, m);
        if (row.from != "e") {
            EXPECT_EQ(mass[row.to], best) << row.from;
        }
    }
}

TEST(PhonemeMapCommands, OneRowPerPhonemeMapsEachPhonemeOnItsOwn) {
    const Document start = ownNamesDocument();
    const FrequencyTable table = bundledTable();
    std::vector<edit::MapAssignment> rows =
        edit::suggestMapAssignment(start, table, edit::phonemePerVisemeMap(table));
    ASSERT_EQ(rows.size(), table.entries.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].phonemes, std::vector<std::string>{table.entries[i].first});
        rows[i].to = i % 2 ? "jawOpen" : "mouthClose";
    }
    const Document mapped = edit::startPhonemeMap(start, table, edit::phonemePerVisemeMap(table), rows);
    EXPECT_EQ(*mapped.frequencies.map.visemeOf(table.entries[1].first), "jawOpen");
    EXPECT_EQ(edit::mapCoverage(mapped).visemesWithoutPhoneme.size(), 13u);
}

TEST(PhonemeMapCommands, MovingPhonemesAndGoingBackToDirectFrequencies) {
    const Document start =
        edit::startPhonemeMap(faceDocument(), bundledTable(), oculusMap(),
                              edit::suggestMapAssignment(faceDocument(), bundledTable(), oculusMap()));
    const Document moved = edit::movePhonemes(start, "PP", "FF");
    EXPECT_TRUE(edit::phonemesMappedTo(moved.frequencies, "PP").empty());
    EXPECT_EQ(edit::phonemesMappedTo(moved.frequencies, "FF"),
              (std::vector<std::string>{"M", "V", "P", "B", "F"}));
    EXPECT_NE(refusal([&] { edit::movePhonemes(moved, "PP", "FF"); }).find("no phoneme"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::movePhonemes(start, "PP", "zz"); }).find("not a viseme"),
              std::string::npos);

    const Document direct = edit::useDirectFrequencies(moved);
    EXPECT_FALSE(direct.frequencies.isPhonemeBased());
    const std::vector<double> before = documentFrequencies(moved), after = documentFrequencies(direct);
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_NEAR(after[i], before[i], 1e-15);
    EXPECT_NE(refusal([&] { edit::useDirectFrequencies(direct); }).find("direct"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::movePhonemes(direct, "PP", "FF"); }).find("direct"), std::string::npos);
}

// Real data nobody here made: the ICT FaceKit mouth shapes (VISEMELAB_SHARED_DATA_DIR) carry blend
// shape names no bundled map knows. Started from the Oculus map with a rest viseme for the pause,
// every shape gets the summed frequency of the phonemes assigned to it.
TEST(PhonemeMapCommands, IctMouthShapesGetPhonemeDerivedFrequencies) {
    const std::filesystem::path folder =
        std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) / "ict-facekit-mouth";
    if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "shared data folder absent: " << folder;
    Document document;
    const auto files = listVisemeFolder(folder, folder / "generic_neutral_mesh.obj");
    document.visemes =
        std::make_shared<const VisemeSet>(loadVisemeSet(folder / "generic_neutral_mesh.obj", files));
    document.neutralFile = folder / "generic_neutral_mesh.obj";
    for (const auto& file : files) document.visemeFiles.push_back(file.second);
    FrequencySource direct;
    for (const auto& file : files) direct.visemeFrequencies.entries.emplace_back(file.first, 1.0);
    document = edit::setFrequencies(document, direct);
    ASSERT_EQ(document.visemeCount(), 7u);

    // No name matches and no current map: nothing is suggested, and applying is refused.
    std::vector<edit::MapAssignment> rows = edit::suggestMapAssignment(document, bundledTable(), oculusMap());
    for (const auto& row : rows) EXPECT_TRUE(row.to.empty()) << row.from;
    EXPECT_NE(refusal([&] { edit::startPhonemeMap(document, bundledTable(), oculusMap(), rows); }),
              "(not refused)");

    document = edit::addRestViseme(document, "rest");
    const std::map<std::string, std::string> shapeOf = {
        {"sil", "rest"},          {"PP", "mouthClose"},  {"FF", "mouthRollLower"}, {"TH", "mouthStretch_L"},
        {"DD", "jawOpen"},        {"kk", "jawOpen"},     {"CH", "mouthFunnel"},    {"SS", "mouthSmile_L"},
        {"nn", "mouthStretch_L"}, {"RR", "mouthPucker"}, {"aa", "jawOpen"},        {"E", "mouthSmile_L"},
        {"ih", "mouthStretch_L"}, {"oh", "mouthFunnel"}, {"ou", "mouthPucker"}};
    for (auto& row : rows) row.to = shapeOf.at(row.from);
    const Document mapped = edit::startPhonemeMap(document, bundledTable(), oculusMap(), rows);

    // Reference: plain sums of the table's counts through both maps.
    std::map<std::string, double> expected;
    double total = 0.0;
    for (const auto& [phoneme, value] : bundledTable().entries) {
        expected[shapeOf.at(*oculusMap().visemeOf(phoneme))] += value;
        total += value;
    }
    const std::vector<double> frequencies = documentFrequencies(mapped);
    const std::vector<std::string> names = visemeNames(mapped);
    ASSERT_EQ(names.size(), 8u);
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_NEAR(frequencies[i], expected[names[i]] / total, 1e-12) << names[i];
        EXPECT_GT(frequencies[i], 0.0) << names[i];
    }
    EXPECT_TRUE(edit::mapCoverage(mapped).visemesWithoutPhoneme.empty());
}

} // namespace
} // namespace vl
