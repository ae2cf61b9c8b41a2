#include "core/reduce/ReducedModel.h"
#include "core/common/Error.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReduceRun.h"
#include "tests/export/TestModels.h"
#include "tests/reduce/InputErrorText.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

VisemeSet fourVisemes() {
    VisemeSet set;
    set.neutral = test::gridMesh(3, 3, true);
    const char* names[] = {"aa", "f", "oh", "th"};
    for (int v = 0; v < 4; ++v) {
        Viseme viseme{names[v], set.neutral.positions};
        for (Vec3& p : viseme.positions) p += Vec3(v, 2.0 * v, -v);
        set.visemes.push_back(viseme);
    }
    return set;
}

TEST(ReducedModel, MergesGroupsWithFrequencyWeightedMeans) {
    const VisemeSet set = fourVisemes();
    FrequencySource source;
    source.phonemes.entries = {{"AA", 0.3}, {"F", 0.1}, {"V", 0.1}, {"OW", 0.2}, {"TH", 0.3}};
    source.map.entries = {{"AA", "aa"}, {"F", "f"}, {"V", "f"}, {"OW", "oh"}, {"TH", "th"}};
    const std::vector<double> frequencies{0.3, 0.2, 0.2, 0.3};
    const ReducedModel model = buildReducedModel(set, frequencies, {0, 1, 0, 1}, source);
    ASSERT_EQ(model.keys.size(), 2u);
    EXPECT_EQ(model.keys[0].name, "aa+oh");
    EXPECT_EQ(model.keys[1].name, "f+th");
    EXPECT_EQ(model.keys[1].members, (std::vector<std::string>{"f", "th"}));
    EXPECT_DOUBLE_EQ(model.keys[0].frequency, 0.5);
    // f (offset 1) weighs 0.2, th (offset 3) weighs 0.3: mean offset 2.2.
    for (std::size_t i = 0; i < set.vertexCount(); ++i)
        EXPECT_LT((model.keys[1].positions[i] - (set.neutral.positions[i] + Vec3(2.2, 4.4, -2.2))).norm(),
                  1e-12);
    const std::vector<std::pair<std::string, int>> expectedMap{
        {"AA", 0}, {"F", 1}, {"V", 1}, {"OW", 0}, {"TH", 1}};
    EXPECT_EQ(model.phonemeToKey, expectedMap);
    EXPECT_EQ(model.phonemeFrequencies, source.phonemes.entries);
    EXPECT_EQ(model.neutral.uvs, set.neutral.uvs);
}

TEST(ReducedModel, DirectFrequenciesMapEachVisemeName) {
    const VisemeSet set = fourVisemes();
    FrequencySource source;
    source.visemeFrequencies.entries = {{"aa", 1}, {"f", 1}, {"oh", 1}, {"th", 1}};
    const ReducedModel model = unreducedModel(set, {0.25, 0.25, 0.25, 0.25}, source);
    ASSERT_EQ(model.keys.size(), 4u);
    EXPECT_EQ(model.keys[2].name, "oh");
    EXPECT_EQ(model.keys[2].positions, set.visemes[2].positions);
    const std::vector<std::pair<std::string, int>> expectedMap{{"aa", 0}, {"f", 1}, {"oh", 2}, {"th", 3}};
    EXPECT_EQ(model.phonemeToKey, expectedMap);
    EXPECT_TRUE(model.phonemeFrequencies.empty());
}

TEST(ReducedModel, BadInputIsNamed) {
    const VisemeSet set = fourVisemes();
    FrequencySource source;
    EXPECT_THROW(buildReducedModel(set, {1, 1, 1}, {0, 0, 0, 0}, source), InputError);
    EXPECT_THROW(buildReducedModel(set, {1, 1, 1, 1}, {0, 2, 0, 0}, source), InputError); // group 1 empty
    source.phonemes.entries = {{"X", 1}};
    source.map.entries = {{"X", "nope"}};
    try {
        buildReducedModel(set, {1, 1, 1, 1}, {0, 1, 2, 3}, source);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown viseme 'nope'"), std::string::npos);
    }
    ReducedModel model = test::randomModel(3, 3, 2, false, 71);
    model.keys[0].positions.pop_back();
    EXPECT_THROW(validateReducedModel(model, "m"), InputError);
    model = test::randomModel(3, 3, 2, false, 71);
    model.keys[1].positions[0][1] = std::nan("");
    EXPECT_THROW(validateReducedModel(model, "m"), InputError);
    model = test::randomModel(3, 3, 2, false, 71);
    model.phonemeToKey.push_back(model.phonemeToKey.front());
    EXPECT_THROW(validateReducedModel(model, "m"), InputError);
}

// One policy for names, wherever a model is built: a map entry naming a viseme the set lacks is an
// error at the map's origin that lists every such viseme with its phonemes, even when the table
// never counts those phonemes (so the frequencies alone are valid and nothing would be noticed).
FrequencySource mapWithUnknownVisemes() {
    FrequencySource source;
    source.phonemes.entries = {{"AA", 0.4}, {"F", 0.2}, {"OW", 0.2}, {"TH", 0.2}};
    source.map.entries = {{"AA", "aa"}, {"F", "f"},   {"OW", "oh"}, {"TH", "th"},
                          {"M", "mbp"}, {"B", "mbp"}, {"R", "rr"}};
    source.map.origin.text = "map.csv";
    return source;
}

TEST(ReducedModel, UnknownVisemesInTheMapAreOneErrorNamingThemAll) {
    const VisemeSet set = fourVisemes();
    const FrequencySource source = mapWithUnknownVisemes();
    const std::vector<double> frequencies = visemeFrequencies(source, {"aa", "f", "oh", "th"});
    const std::string error = test::errorOf([&] {
        buildReducedModel(set, frequencies, {0, 1, 0, 1}, source);
    });
    EXPECT_EQ(error, "map.csv: the phoneme map names visemes the set does not have: unknown viseme 'mbp' "
                     "(phonemes M, B); unknown viseme 'rr' (phonemes R)");
    EXPECT_EQ(test::errorOf([&] { unreducedModel(set, frequencies, source); }), error);
    EXPECT_EQ(test::errorOf([&] { requireKnownVisemes(set, source); }), error);
    // Without an origin the error says what it is about.
    FrequencySource unnamed = source;
    unnamed.map.origin.text.clear();
    EXPECT_EQ(test::errorOf([&] { requireKnownVisemes(set, unnamed); }).rfind("phoneme map: ", 0), 0u);
    // Direct viseme frequencies have no map: nothing to check.
    FrequencySource direct;
    direct.visemeFrequencies.entries = {{"aa", 1}, {"f", 1}, {"oh", 1}, {"th", 1}};
    EXPECT_EQ(test::errorOf([&] { buildReducedModel(set, frequencies, {0, 1, 0, 1}, direct); }), "");
}

TEST(ReducedModel, ReductionRunRefusesUnknownVisemesBeforeReducing) {
    const VisemeSet set = fourVisemes();
    ReduceSettings settings;
    settings.target = 2;
    int progressCalls = 0;
    const std::string error = test::errorOf(
        [&] { runReduction(set, mapWithUnknownVisemes(), settings, [&](double) { ++progressCalls; }); });
    EXPECT_NE(error.find("unknown viseme 'mbp' (phonemes M, B)"), std::string::npos) << error;
    EXPECT_EQ(progressCalls, 0);
    // Without the unknown entries the run's model is buildReducedModel's for its grouping.
    FrequencySource known = mapWithUnknownVisemes();
    known.map.entries.resize(4);
    const ReduceOutcome outcome = runReduction(set, known, settings);
    const ReducedModel expected =
        buildReducedModel(set, outcome.frequencies, outcome.result.groupOf(), known);
    ASSERT_EQ(outcome.model.keys.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(outcome.model.keys[k].name, expected.keys[k].name);
        EXPECT_EQ(outcome.model.keys[k].positions, expected.keys[k].positions);
    }
    EXPECT_EQ(outcome.model.phonemeToKey, expected.phonemeToKey);
}

} // namespace
} // namespace vl
