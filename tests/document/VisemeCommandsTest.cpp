// Viseme authoring commands: every name that refers to a viseme follows a rename, duplicate, move
// or removal; storing the sliders gives the mesh the face generator gives for the same preset;
// bad edits are refused with a reason and the input document never changes.
#include "core/document/VisemeCommands.h"
#include "core/common/Error.h"
#include "core/deform/CascadeSampler.h"
#include "core/document/Commands.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"

#include "DocumentTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

namespace vl {
namespace {

using test::faceDocument;
using test::refusal;

// The face's set with the bundled en-us table and Oculus map, constraints and painted weights.
Document mappedDocument() {
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    Document document = faceDocument();
    FrequencySource source =
        loadPhonemeFrequencySource(defaultPhonemeTablePath(assets), assets / "phonemes" / "map_oculus.csv");
    document = edit::setFrequencies(document, source);
    document = edit::setConstraints(document, {{"PP"}, {{"PP", "aa"}}, {{"FF", "TH"}}});
    document = edit::setPaintedWeights(document, std::vector<double>(document.visemes->vertexCount(), 0.7));
    return document;
}

double frequencyOf(const Document& document, const std::string& name) {
    return documentFrequencies(document).at(static_cast<std::size_t>(document.visemes->find(name)));
}

const VisemeParameters* presetNamed(const Document& document, const std::string& name) {
    for (const VisemeParameters& preset : document.face.presets)
        if (preset.name == name) return &preset;
    return nullptr;
}

TEST(VisemeCommands, RenameFollowsTheMapConstraintsPresetAndFrequencies) {
    const Document start = mappedDocument();
    const Document copy = start;
    const int pp = start.visemes->find("PP");
    const Document renamed = edit::renameViseme(start, pp, "closed");
    EXPECT_EQ(start, copy); // the input is a value
    EXPECT_EQ(renamed.visemes->visemes[static_cast<std::size_t>(pp)].name, "closed");
    EXPECT_EQ(renamed.visemes->find("PP"), -1);
    EXPECT_EQ(*renamed.frequencies.map.visemeOf("P"), "closed");
    EXPECT_EQ(*renamed.frequencies.map.visemeOf("M"), "closed");
    EXPECT_EQ(renamed.constraints.pinned, std::vector<std::string>{"closed"});
    EXPECT_EQ(renamed.constraints.apart.at(0), std::make_pair(std::string("closed"), std::string("aa")));
    EXPECT_EQ(renamed.constraints.together, start.constraints.together);
    ASSERT_NE(presetNamed(renamed, "closed"), nullptr);
    EXPECT_EQ(presetNamed(renamed, "PP"), nullptr);
    EXPECT_EQ(presetNamed(renamed, "closed")->values, oculusVisemes()[1].values);
    EXPECT_EQ(renamed.weights, start.weights); // painted weights untouched (same pointer)
    EXPECT_EQ(documentFrequencies(renamed), documentFrequencies(start));
    // And back: the same document as before.
    EXPECT_EQ(edit::renameViseme(renamed, pp, "PP").frequencies, start.frequencies);

    // Direct frequencies follow the name too.
    const Document direct = edit::setVisemeFrequency(faceDocument(), 3, 4.0);
    const Document directRenamed = edit::renameViseme(direct, 3, "dental");
    EXPECT_EQ(*directRenamed.frequencies.visemeFrequencies.find("dental"), 4.0);
    EXPECT_EQ(directRenamed.frequencies.visemeFrequencies.find(direct.visemes->visemes[3].name), nullptr);
}

TEST(VisemeCommands, BadNamesAreRefusedWithTheReason) {
    const Document start = mappedDocument();
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, "aa"); }).find("already exists"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, ""); }).find("needs a name"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, "a+b"); }).find("'+'"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, " lead"); }).find("space"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, "tab\there"); }).find("control"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 1, "PP"); }).find("same"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::renameViseme(start, 99, "x"); }).find("outside"), std::string::npos);
    // A preset of the face that is not a viseme of the set still owns its name.
    Document fewer = edit::removeViseme(start, start.visemes->find("ou"), "oh");
    fewer.face.presets.push_back({"spare", {}});
    EXPECT_NE(refusal([&] { edit::renameViseme(fewer, 0, "spare"); }).find("preset"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::duplicateViseme(start, 0, "aa"); }), "(not refused)");
}

TEST(VisemeCommands, DuplicateInsertsACopyAfterTheOriginal) {
    const Document direct = edit::setVisemeFrequency(faceDocument(), 10, 3.0); // aa
    const Document copied = edit::duplicateViseme(direct, 10, "aa wide");
    ASSERT_EQ(copied.visemeCount(), direct.visemeCount() + 1);
    EXPECT_EQ(copied.visemes->visemes[11].name, "aa wide");
    EXPECT_EQ(copied.visemes->visemes[11].positions, direct.visemes->visemes[10].positions);
    EXPECT_EQ(copied.visemes->visemes[12].name, direct.visemes->visemes[11].name);
    EXPECT_EQ(copied.visemeFiles.size(), copied.visemeCount());
    EXPECT_EQ(*copied.frequencies.visemeFrequencies.find("aa wide"), 3.0);
    EXPECT_EQ(copied.frequencies.visemeFrequencies.entries[11].first, "aa wide"); // table in set order
    ASSERT_NE(presetNamed(copied, "aa wide"), nullptr);
    EXPECT_EQ(presetNamed(copied, "aa wide")->values, presetNamed(copied, "aa")->values);

    // With a phoneme map no phoneme maps to the copy yet: frequency 0, and the coverage says so.
    const Document mapped = edit::duplicateViseme(mappedDocument(), 1, "PP2");
    EXPECT_EQ(frequencyOf(mapped, "PP2"), 0.0);
    const edit::MapCoverage coverage = edit::mapCoverage(mapped);
    EXPECT_EQ(coverage.visemesWithoutPhoneme, std::vector<int>{2});
    EXPECT_TRUE(mapped.constraints.pinned == std::vector<std::string>{"PP"}); // not copied
}

TEST(VisemeCommands, MoveReordersTheSetAndWhatFollowsItsOrder) {
    const Document start = edit::setVisemeFrequency(faceDocument(), 2, 5.0);
    const std::vector<std::string> before = visemeNames(start);
    const Document moved = edit::moveViseme(start, 2, 6);
    std::vector<std::string> expected = before;
    const std::string name = expected[2];
    expected.erase(expected.begin() + 2);
    expected.insert(expected.begin() + 6, name);
    EXPECT_EQ(visemeNames(moved), expected);
    EXPECT_EQ(moved.visemes->visemes[6].positions, start.visemes->visemes[2].positions);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(moved.frequencies.visemeFrequencies.entries[i].first, expected[i]);
        EXPECT_EQ(moved.face.presets[i].name, expected[i]);
        EXPECT_DOUBLE_EQ(frequencyOf(moved, expected[i]), frequencyOf(start, expected[i]));
    }
    // Upwards, and back to where it was: the same document.
    const Document back = edit::moveViseme(moved, 6, 2);
    EXPECT_EQ(visemeNames(back), before);
    EXPECT_EQ(back.frequencies, start.frequencies);
    EXPECT_NE(refusal([&] { edit::moveViseme(start, 3, 3); }).find("already"), std::string::npos);
    EXPECT_NE(refusal([&] { edit::moveViseme(start, 3, 15); }).find("outside"), std::string::npos);
}

TEST(VisemeCommands, RemovalThatWouldOrphanPhonemesIsRefusedUnlessTheyMove) {
    const Document start = mappedDocument();
    const int pp = start.visemes->find("PP");
    const std::string why = refusal([&] { edit::removeViseme(start, pp); });
    EXPECT_NE(why.find("M, P, B"), std::string::npos) << why;
    EXPECT_NE(why.find("% of the phonemes"), std::string::npos) << why;
    EXPECT_NE(refusal([&] { edit::removeViseme(start, pp, "PP"); }), "(not refused)");
    EXPECT_NE(refusal([&] { edit::removeViseme(start, pp, "nowhere"); }), "(not refused)");

    const Document removed = edit::removeViseme(start, pp, "FF");
    EXPECT_EQ(removed.visemes->find("PP"), -1);
    EXPECT_EQ(*removed.frequencies.map.visemeOf("B"), "FF");
    EXPECT_NEAR(frequencyOf(removed, "FF"), frequencyOf(start, "FF") + frequencyOf(start, "PP"), 1e-12);
    EXPECT_TRUE(removed.constraints.pinned.empty());
    EXPECT_TRUE(removed.constraints.apart.empty());
    EXPECT_EQ(removed.constraints.together, start.constraints.together);
    EXPECT_EQ(presetNamed(removed, "PP"), nullptr); // its preset went with it
    EXPECT_EQ(removed.weights, start.weights);
    // A viseme no phoneme maps to goes without a question.
    const Document spare = edit::duplicateViseme(start, 0, "spare");
    EXPECT_EQ(edit::removeViseme(spare, 1).visemeCount(), start.visemeCount());
}

TEST(VisemeCommands, StoredSlidersAreTheMeshTheFaceGeneratesForThatPreset) {
    Document start = faceDocument();
    start = edit::setParameter(start, 0, 0.6);
    start = edit::setParameter(start, 3, 0.25);
    const Document stored = edit::storeSlidersAsNewViseme(start, "mine");
    ASSERT_EQ(stored.visemeCount(), start.visemeCount() + 1);
    const VisemeParameters* preset = presetNamed(stored, "mine");
    ASSERT_NE(preset, nullptr);
    EXPECT_EQ(preset->values.size(), 2u); // only what differs from the defaults
    EXPECT_EQ(parameterVector(*stored.face.cascade, *preset), start.face.parameters);
    // The reference: the generator's mesh for the same preset on the same (u,v) mesh.
    const VisemeSet reference = generateVisemeSet(*start.face.cascade, *start.face.domain,
                                                  std::vector<VisemeParameters>{{"sil", {}}, *preset});
    EXPECT_EQ(stored.visemes->visemes.back().name, "mine");
    EXPECT_EQ(stored.visemes->visemes.back().positions, reference.visemes[1].positions);
    EXPECT_EQ(*stored.frequencies.visemeFrequencies.find("mine"), 1.0);
    // Applying the stored preset brings the sliders back.
    EXPECT_EQ(edit::applyVisemePreset(edit::setParameters(stored, stored.face.cascade->defaults()), "mine")
                  .face.parameters,
              start.face.parameters);
    EXPECT_NE(refusal([&] { edit::storeSlidersAsNewViseme(stored, "mine"); }).find("already"),
              std::string::npos);
    EXPECT_NE(refusal([&] { edit::storeSlidersAsNewViseme(Document{}, "x"); }).find("no face"),
              std::string::npos);
}

TEST(VisemeCommands, StoringIntoAVisemeRegeneratesItsMeshAndPreset) {
    Document start = faceDocument();
    start = edit::applyVisemePreset(start, "aa");
    start = edit::setParameter(start, 2, 0.5);
    const int aa = start.visemes->find("aa");
    start.visemeFiles[static_cast<std::size_t>(aa)] = "/somewhere/aa.obj"; // as if read from a file
    const Document stored = edit::storeSlidersInViseme(start, "aa");
    EXPECT_EQ(stored.visemeCount(), start.visemeCount());
    EXPECT_EQ(parameterVector(*stored.face.cascade, *presetNamed(stored, "aa")), start.face.parameters);
    const std::vector<Vec3> expected =
        CascadeSampler(*start.face.cascade, start.visemes->neutral.uvs).evaluate(start.face.parameters);
    EXPECT_EQ(stored.visemes->visemes[static_cast<std::size_t>(aa)].positions, expected);
    EXPECT_NE(stored.visemes->visemes[static_cast<std::size_t>(aa)].positions,
              start.visemes->visemes[static_cast<std::size_t>(aa)].positions);
    EXPECT_TRUE(stored.visemeFiles[static_cast<std::size_t>(aa)].empty());                // embedded now
    EXPECT_EQ(stored.visemes->visemes[3].positions, start.visemes->visemes[3].positions); // others kept
    EXPECT_NE(refusal([&] { edit::storeSlidersInViseme(start, "nope"); }).find("no preset"),
              std::string::npos);
}

TEST(VisemeCommands, AForeignSetKeepsItsMeshesAndOnlyThePresetIsStored) {
    const Document start = faceDocument();
    EXPECT_TRUE(edit::visemeSetMadeByFace(start));
    // Retargeted, the face no longer made this set: its meshes are not the face's to regenerate.
    const Document retargeted = edit::setParameter(edit::retarget(start, face::Individual::Retarget), 0, 0.5);
    EXPECT_FALSE(edit::visemeSetMadeByFace(retargeted));
    const Document stored = edit::storeSlidersAsNewViseme(retargeted, "mine");
    EXPECT_EQ(stored.visemes, retargeted.visemes);
    ASSERT_NE(presetNamed(stored, "mine"), nullptr);
    const Document into = edit::storeSlidersInViseme(retargeted, "aa");
    EXPECT_EQ(into.visemes, retargeted.visemes);
    EXPECT_NE(presetNamed(into, "aa")->values,
              presetNamed(edit::storeSlidersInViseme(start, "aa"), "aa")->values);
    // The bundled sample, read from OBJ files (rounded to 6 digits), is the face's own set.
    const LoadedProject sample = documentFromProject(
        loadProject(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj"));
    EXPECT_TRUE(edit::visemeSetMadeByFace(sample.document));
}

TEST(VisemeCommands, PresetsAreRemovedUnlessTheyAreAVisemeOfTheFacesSet) {
    Document start = faceDocument();
    start = edit::storeSlidersAsNewViseme(edit::retarget(start, face::Individual::Retarget), "spare");
    EXPECT_EQ(presetNamed(edit::removePreset(start, "spare"), "spare"), nullptr);
    EXPECT_NE(refusal([&] { edit::removePreset(start, "nope"); }).find("no preset"), std::string::npos);
    const Document own = faceDocument();
    EXPECT_NE(refusal([&] { edit::removePreset(own, "aa"); }).find("remove the viseme"), std::string::npos);
}

TEST(VisemeCommands, RestVisemeIsTheNeutral) {
    const Document start = faceDocument();
    const Document rest = edit::addRestViseme(start, "rest");
    EXPECT_EQ(rest.visemes->visemes.back().positions, start.visemes->neutral.positions);
    EXPECT_EQ(*rest.frequencies.visemeFrequencies.find("rest"), 1.0);
    EXPECT_NE(refusal([&] { edit::addRestViseme(start, "sil"); }).find("already"), std::string::npos);
}

TEST(VisemeCommands, AuthoredDocumentSurvivesTheProjectFile) {
    Document document = mappedDocument();
    document = edit::renameViseme(document, document.visemes->find("PP"), "closed");
    document = edit::setParameter(document, 1, 0.4);
    document = edit::storeSlidersAsNewViseme(document, "half");
    document = edit::duplicateViseme(document, 0, "rest copy");
    document = edit::moveViseme(document, 3, 0);
    document = edit::setPhonemeViseme(document, 0, "half");
    const auto dir = std::filesystem::temp_directory_path() / "visemelab-document-authoring";
    std::filesystem::create_directories(dir);
    saveProject(dir / "p.vlproj", projectFromDocument(document));
    const Document back = documentFromProject(loadProject(dir / "p.vlproj")).document;
    EXPECT_EQ(visemeNames(back), visemeNames(document));
    EXPECT_EQ(back.face.presets, document.face.presets);
    EXPECT_EQ(back.frequencies, document.frequencies);
    EXPECT_EQ(back.constraints, document.constraints);
    for (std::size_t i = 0; i < document.visemeCount(); ++i)
        EXPECT_EQ(back.visemes->visemes[i].positions, document.visemes->visemes[i].positions);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl

namespace vl {
namespace {

using test::faceDocument;
using test::refusal;

TEST(VisemeCommands, ASculptedShapeReplacesTheVisemeAndIsEmbedded) {
    const Document document = faceDocument();
    std::vector<Vec3> shape = document.visemes->visemes[3].positions;
    shape[7] += Vec3(0.0, 0.0, 0.25);
    const Document sculpted = edit::setVisemeShape(document, 3, shape);
    EXPECT_EQ(sculpted.visemes->visemes[3].positions, shape);
    EXPECT_EQ(sculpted.visemes->visemes[3].name, document.visemes->visemes[3].name);
    EXPECT_TRUE(sculpted.visemeFiles[3].empty());
    EXPECT_EQ(document.visemes->visemes[3].positions[7], faceDocument().visemes->visemes[3].positions[7]);
    EXPECT_NE(refusal([&] { edit::setVisemeShape(document, 3, {}); }).find("vertices"), std::string::npos);
    shape[2][1] = std::nan("");
    EXPECT_NE(refusal([&] { edit::setVisemeShape(document, 3, shape); }).find("finite"), std::string::npos);
    EXPECT_FALSE(
        refusal([&] { edit::setVisemeShape(document, 99, document.visemes->neutral.positions); }).empty());
}

TEST(VisemeCommands, ABlendIsTheNeutralPlusTheWeightedDisplacements) {
    const Document document = faceDocument();
    const VisemeSet& set = *document.visemes;
    EXPECT_FALSE(refusal([&] { edit::addBlendedViseme(document, "bad+name", {{1, 1.0}}); }).empty());
    const Document mix = edit::addBlendedViseme(document, "aa ou mix", {{10, 0.5}, {14, 0.25}});
    ASSERT_EQ(mix.visemeCount(), set.size() + 1);
    const Viseme& added = mix.visemes->visemes[15]; // after the last one mixed (14)
    EXPECT_EQ(added.name, "aa ou mix");
    for (std::size_t v = 0; v < set.vertexCount(); ++v) {
        const Vec3 expected = set.neutral.positions[v] +
                              0.5 * (set.visemes[10].positions[v] - set.neutral.positions[v]) +
                              0.25 * (set.visemes[14].positions[v] - set.neutral.positions[v]);
        EXPECT_NEAR((added.positions[v] - expected).norm(), 0.0, 1e-12) << v;
    }
    // One viseme at weight 1 is a copy of its shape.
    const Document copy = edit::addBlendedViseme(document, "aa again", {{10, 1.0}});
    EXPECT_EQ(copy.visemes->visemes[11].positions, set.visemes[10].positions);
    EXPECT_NE(refusal([&] { edit::addBlendedViseme(document, "none", {}); }).find("at least one"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  edit::addBlendedViseme(document, "nan", {{1, std::nan("")}});
              }).find("finite"),
              std::string::npos);
}

} // namespace
} // namespace vl

namespace vl {
namespace {

// Issue 32: a face's first generated set is weighted by how often its visemes are spoken.
TEST(GenerateVisemes, AFirstSetTakesTheSpokenTableWhenItsMapFits) {
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    const FrequencySource table =
        loadPhonemeFrequencySource(defaultPhonemeTablePath(assets), assets / "phonemes" / "map_oculus.csv");
    Document face;
    face.face = makeFaceModel(face::Individual::Bundled, 12);
    const Document spoken = edit::generateVisemesFromFace(face, &table);
    EXPECT_TRUE(spoken.frequencies.isPhonemeBased());
    const std::vector<double> f = documentFrequencies(spoken);
    EXPECT_NE(*std::max_element(f.begin(), f.end()), *std::min_element(f.begin(), f.end())); // not equal
    // Without a table, or with a map naming visemes the presets lack: equal frequencies.
    EXPECT_FALSE(edit::generateVisemesFromFace(face).frequencies.isPhonemeBased());
    FrequencySource foreign = table;
    for (auto& [phoneme, viseme] : foreign.map.entries) viseme = "viseme_" + viseme;
    EXPECT_FALSE(edit::generateVisemesFromFace(face, &foreign).frequencies.isPhonemeBased());
    // A set that exists keeps its table: the user's choice wins over the bundled one.
    const Document direct = edit::setVisemeFrequency(edit::generateVisemesFromFace(face), 3, 5.0);
    const Document again = edit::generateVisemesFromFace(direct, &table);
    EXPECT_FALSE(again.frequencies.isPhonemeBased());
    EXPECT_EQ(again.frequencies, direct.frequencies);
}

} // namespace
} // namespace vl
