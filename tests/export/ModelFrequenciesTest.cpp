// A glTF written by VisemeLab and read back keeps its frequencies: the phoneme table and map when it
// has them, else the keys' own frequencies; uniform only when the file carries none.
#include "core/import/ModelFrequencies.h"
#include "core/export/GltfExport.h"
#include "core/import/GltfImport.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

std::vector<std::string> keyNames(const ReducedModel& model) {
    std::vector<std::string> names;
    for (const KeyMesh& key : model.keys) names.push_back(key.name);
    return names;
}

// Unequal phoneme frequencies; each key's frequency is the normalised sum of its phonemes'.
ReducedModel unevenModel(unsigned seed) {
    ReducedModel model = test::randomModel(6, 5, 4, true, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.1, 5.0);
    double total = 0.0;
    for (auto& [phoneme, frequency] : model.phonemeFrequencies) total += (frequency = u(rng));
    for (KeyMesh& key : model.keys) key.frequency = 0.0;
    for (std::size_t p = 0; p < model.phonemeToKey.size(); ++p)
        model.keys[static_cast<std::size_t>(model.phonemeToKey[p].second)].frequency +=
            model.phonemeFrequencies[p].second / total;
    return model;
}

void expectKeyFrequencies(const FrequencySource& source, const ReducedModel& model) {
    const std::vector<double> got = visemeFrequencies(source, keyNames(model));
    ASSERT_EQ(got.size(), model.keys.size());
    for (std::size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], model.keys[k].frequency, 1e-9) << k;
}

TEST(ModelFrequencies, PhonemeTableAndMapSurviveAGlbRoundTrip) {
    const ReducedModel written = unevenModel(3);
    const ReducedModel read = parseGltf(formatGlb(written), "mem.glb", true);
    const FrequencySource source = modelFrequencies(read, "mem.glb");
    ASSERT_TRUE(source.isPhonemeBased());
    EXPECT_EQ(source.phonemes.entries.size(), written.phonemeFrequencies.size());
    EXPECT_EQ(*source.map.visemeOf("p5"), written.keys[2].name);
    expectKeyFrequencies(source, written);
}

TEST(ModelFrequencies, KeyFrequenciesWhenThereIsNoPhonemeTable) {
    ReducedModel written = unevenModel(4);
    written.phonemeFrequencies.clear(); // a project with direct viseme frequencies
    const FrequencySource source = modelFrequencies(parseGltf(formatGlb(written), "mem.glb", true));
    EXPECT_FALSE(source.isPhonemeBased());
    expectKeyFrequencies(source, written);
    // A phoneme table the map does not cover is not used either.
    ReducedModel partial = unevenModel(5);
    partial.phonemeFrequencies.emplace_back("unmapped", 1.0);
    const FrequencySource fallback = modelFrequencies(partial);
    EXPECT_FALSE(fallback.isPhonemeBased());
    expectKeyFrequencies(fallback, partial); // the keys' frequencies sum to 1
}

TEST(ModelFrequencies, UniformWhenTheModelCarriesNone) {
    ReducedModel model = unevenModel(6);
    model.phonemeFrequencies.clear();
    for (KeyMesh& key : model.keys) key.frequency = 0.0; // a glTF from another tool
    const FrequencySource source = modelFrequencies(model);
    const std::vector<double> got = visemeFrequencies(source, keyNames(model));
    for (double f : got) EXPECT_DOUBLE_EQ(f, 0.25);
}

} // namespace
} // namespace vl
