// Every edit of the document is a validated function: it returns the edited document or throws
// InputError naming what is wrong; the document it was given never changes.
#include "core/document/Commands.h"
#include "core/common/Error.h"

#include "DocumentTestSupport.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

namespace vl {
namespace {

using test::faceDocument;

FrequencySource phonemeSource(const Document& document) {
    FrequencySource source;
    const auto names = visemeNames(document);
    source.phonemes.entries = {{"p", 2.0}, {"a", 5.0}, {"s", 1.0}};
    source.map.entries = {{"p", names[1]}, {"a", names[10]}, {"s", names[7]}};
    return source;
}

TEST(Commands, EachEditChangesWhatItNamesAndNothingElse) {
    const Document start = faceDocument();
    const Document copy = start;
    const Document target = edit::setTarget(start, 4);
    EXPECT_EQ(target.target, 4);
    EXPECT_EQ(start, copy); // the input is a value: untouched
    Document expected = start;
    expected.target = 4;
    EXPECT_EQ(target, expected);

    const Document frequency = edit::setVisemeFrequency(start, 3, 7.0);
    EXPECT_EQ(frequency.frequencies.visemeFrequencies.entries[3].second, 7.0);
    EXPECT_EQ(frequency.visemes, start.visemes); // geometry shared, not copied

    const Document painted = edit::setWeightMode(start, WeightMode::Painted);
    ASSERT_NE(painted.weights.painted, nullptr);
    EXPECT_EQ(painted.weights.painted->size(), start.visemes->vertexCount());
    // Back to uniform and again painted: what was painted is kept.
    std::vector<double> mine(start.visemes->vertexCount(), 0.3);
    const Document repainted = edit::setWeightMode(
        edit::setWeightMode(edit::setPaintedWeights(start, mine), WeightMode::Uniform), WeightMode::Painted);
    EXPECT_EQ(*repainted.weights.painted, mine);

    const Document phonemes = edit::setFrequencies(start, phonemeSource(start));
    const Document remapped = edit::setPhonemeViseme(phonemes, 0, visemeNames(start)[2]);
    EXPECT_EQ(remapped.frequencies.map.entries[0].second, visemeNames(start)[2]);
    const Document louder = edit::setPhonemeFrequency(phonemes, 1, 9.0);
    EXPECT_EQ(louder.frequencies.phonemes.entries[1].second, 9.0);

    const Document keyed = edit::setRest(start, RestChoice::Key, ""); // every viseme may be a key
    const Document removed = edit::removeViseme(edit::setTarget(keyed, 15), 14);
    EXPECT_EQ(removed.visemeCount(), 14u);
    EXPECT_EQ(removed.visemeFiles.size(), 14u);
    EXPECT_EQ(removed.target, 14); // clamped
    const Document added = edit::addViseme(removed, "again", start.visemes->meshOf(14), {});
    EXPECT_EQ(added.visemes->visemes.back().positions, start.visemes->visemes[14].positions);

    const Document preset = edit::applyVisemePreset(start, "aa");
    EXPECT_NE(preset.face.parameters, start.face.parameters);
    EXPECT_EQ(preset.face.cascade, start.face.cascade);
    InfluenceField field = start.face.cascade->stages[1].field.influences.at(0);
    field.magnitude *= 2.0;
    const Document edited = edit::setInfluence(start, 1, 0, field);
    EXPECT_NE(edited.face.cascade, start.face.cascade);
    EXPECT_EQ(edited.face.cascade->stages[1].field.influences[0], field);
    const Document retargeted = edit::retarget(start, face::Individual::Retarget);
    EXPECT_EQ(retargeted.face.individual, face::Individual::Retarget);

    CriterionSettings settings = start.refinement;
    settings.kind = CriterionKind::Contour;
    EXPECT_EQ(edit::setRefinementSettings(start, settings).refinement.kind, CriterionKind::Contour);
}

TEST(Commands, BadEditsAreRefusedWithAReason) {
    const Document start = faceDocument();
    const Document phonemes = edit::setFrequencies(start, phonemeSource(start));
    const std::vector<std::function<void()>> refused = {
        [&] { edit::setTarget(start, 0); },
        [&] { edit::setTarget(start, 16); },
        [&] { edit::setVisemeFrequency(start, 99, 1.0); },
        [&] { edit::setVisemeFrequency(start, 1, -1.0); },
        [&] { edit::setVisemeFrequency(start, 1, std::numeric_limits<double>::infinity()); },
        [&] { edit::setVisemeFrequency(phonemes, 1, 1.0); }, // frequencies come from the phonemes
        [&] { edit::setPhonemeViseme(phonemes, 0, "no such viseme"); },
        [&] { edit::setPhonemeFrequency(phonemes, 7, 1.0); },
        [&] {
            edit::setPaintedWeights(start, {1.0, 2.0});
        }, // one per vertex
        [&] { edit::setPaintedWeights(start, std::vector<double>(start.visemes->vertexCount(), 0.0)); },
        [&] { edit::removeViseme(start, -1); },
        [&] { edit::addViseme(start, "aa", start.visemes->meshOf(0), {}); }, // the name exists
        [&] { edit::addViseme(start, "new", MeshData{}, {}); },              // not interpolable
        [&] { edit::setParameter(start, 0, 1e9); },
        [&] { edit::applyVisemePreset(start, "no such viseme"); },
        [&] { edit::setInfluence(start, 1, 99, InfluenceField{}); },
        [&] { edit::applyVisemePreset(Document{}, "aa"); }, // no face
    };
    for (std::size_t i = 0; i < refused.size(); ++i) EXPECT_THROW(refused[i](), InputError) << "edit " << i;
    // A set of two cannot lose another viseme.
    Document two = start;
    while (two.visemeCount() > 2) two = edit::removeViseme(two, 0);
    EXPECT_THROW(edit::removeViseme(two, 0), InputError);
}

} // namespace
} // namespace vl
