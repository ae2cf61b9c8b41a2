// "Add rest viseme" on an avatar document whose visemes lack one (edit::addAvatarRestViseme, issue
// 29): the base mesh as viseme_sil with the pause mapped to it, one undoable edit, stored in the
// project (version 4) and read back by the editor and ProjectRun alike, resting in the reduction and
// exported without a target.
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarRest.h"
#include "core/gltf/GltfDocument.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/ProjectRun.h"
#include "core/reduce/Reduction.h"
#include "tests/gltf/AvatarFixtures.h"

#include "tests/document/DocumentTestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace vl {
namespace {

std::filesystem::path writeNoRestAvatar(const char* name) {
    const auto dir = test::tempDir("avatar-rest-" + std::string(name));
    test::AvatarFixtureOptions options;
    options.restTarget = false;
    writeFileAtomically(dir / "norest.glb", test::rpmLikeAvatar(options));
    return dir / "norest.glb";
}

FrequencySource bundledOculus() {
    return bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus");
}

const std::string* visemeOfSilence(const Document& document) {
    return document.frequencies.map.visemeOf("sil");
}

TEST(AvatarRestCommand, AddsTheBaseMeshAsVisemeSilWithThePauseMappedToIt) {
    const auto file = writeNoRestAvatar("add");
    const Document before = documentFromAvatar(loadDocumentAvatar(file, ""), bundledOculus());
    ASSERT_EQ(before.visemeCount(), 14u);
    // Without sil the bundled Oculus map does not fit: equal frequencies, the rest a key (auto).
    EXPECT_FALSE(before.frequencies.isPhonemeBased());
    EXPECT_FALSE(documentRestPose(before).free);

    const Document after = edit::addAvatarRestViseme(before, bundledOculus());
    ASSERT_EQ(after.visemeCount(), 15u);
    EXPECT_EQ(visemeNames(after).back(), "viseme_sil");
    EXPECT_EQ(after.visemes->visemes.back().positions, after.visemes->neutral.positions);
    EXPECT_EQ(after.visemes.get(), &after.avatar.scan->set); // the set is still the scan's
    EXPECT_EQ(after.avatar.scan->addedRest, "viseme_sil");
    EXPECT_EQ(after.visemeFiles.size(), 15u);
    // The defaults follow: the bundled en-us table and Oculus map, the pause on viseme_sil.
    ASSERT_TRUE(after.frequencies.isPhonemeBased());
    ASSERT_NE(visemeOfSilence(after), nullptr);
    EXPECT_EQ(*visemeOfSilence(after), "viseme_sil");
    // Rest-free (auto), and viseme_sil rests.
    const RestPose pose = documentRestPose(after);
    EXPECT_TRUE(pose.free);
    EXPECT_EQ(pose.viseme, 14);
    // The document before is untouched (undo), and a second rest is refused.
    EXPECT_EQ(before.visemeCount(), 14u);
    EXPECT_THROW(edit::addAvatarRestViseme(after, bundledOculus()), InputError);
    std::filesystem::remove_all(file.parent_path());
}

TEST(AvatarRestCommand, TheDesignersMapSendsThePauseToItAndADirectTableGivesItOne) {
    const auto file = writeNoRestAvatar("tables");
    const Document start = documentFromAvatar(loadDocumentAvatar(file, ""), bundledOculus());
    // A phoneme map of the designer's, mapping the pause elsewhere: it goes to the rest now.
    FrequencySource mine;
    mine.phonemes.entries = {{"sil", 5.0}, {"AA", 3.0}, {"M", 2.0}};
    mine.map.entries = {{"sil", "viseme_PP"}, {"AA", "viseme_aa"}, {"M", "viseme_PP"}};
    const Document mapped = edit::addAvatarRestViseme(edit::setFrequencies(start, mine), bundledOculus());
    ASSERT_NE(visemeOfSilence(mapped), nullptr);
    EXPECT_EQ(*visemeOfSilence(mapped), "viseme_sil");
    // Direct frequencies that are not the defaults: the rest joins them with frequency 1.
    FrequencySource direct;
    for (const std::string& name : visemeNames(start))
        direct.visemeFrequencies.entries.emplace_back(name, 2.0);
    const Document added = edit::addAvatarRestViseme(edit::setFrequencies(start, direct), bundledOculus());
    ASSERT_NE(added.frequencies.visemeFrequencies.find("viseme_sil"), nullptr);
    EXPECT_EQ(*added.frequencies.visemeFrequencies.find("viseme_sil"), 1.0);
    // Without an avatar there is nothing to add it to.
    EXPECT_THROW(edit::addAvatarRestViseme(Document{}, bundledOculus()), InputError);
    std::filesystem::remove_all(file.parent_path());
}

TEST(AvatarRestCommand, ANameTheDesignerTypesIsARestVisemesName) {
    // The Frequencies panel's "Add rest viseme" sends the name typed: "sil" is taken on a viseme_*
    // avatar, any other name is refused with the names that are allowed.
    const auto file = writeNoRestAvatar("named");
    const Document start = documentFromAvatar(loadDocumentAvatar(file, ""), bundledOculus());
    const Document named = edit::addAvatarRestViseme(start, bundledOculus(), "sil");
    EXPECT_EQ(visemeNames(named).back(), "sil");
    EXPECT_EQ(named.avatar.scan->addedRest, "sil");
    EXPECT_TRUE(documentRestPose(named).free);
    EXPECT_THROW(edit::addAvatarRestViseme(start, bundledOculus(), "pause"), InputError);
    std::filesystem::remove_all(file.parent_path());
}

TEST(AvatarRestCommand, TheProjectKeepsItAndEditorAndProjectRunReadItBack) {
    const auto file = writeNoRestAvatar("project");
    const Document document = edit::addAvatarRestViseme(
        documentFromAvatar(loadDocumentAvatar(file, ""), bundledOculus()), bundledOculus());
    const auto projectFile = file.parent_path() / "norest.vlproj";
    saveProject(projectFile, projectFromDocument(document));
    std::ifstream in(projectFile);
    const nlohmann::json json = nlohmann::json::parse(in);
    EXPECT_EQ(json["version"], 4);
    EXPECT_EQ(json["avatar"]["addedRest"], "viseme_sil");
    EXPECT_EQ(json["visemes"].back()["name"], "viseme_sil");

    const Project project = loadProject(projectFile);
    EXPECT_EQ(project.avatar.addedRest, "viseme_sil");
    const LoadedProject loaded = documentFromProject(project);
    EXPECT_EQ(visemeNames(loaded.document), visemeNames(document));
    EXPECT_EQ(loaded.document.frequencies, document.frequencies);
    EXPECT_EQ(loaded.document.avatar.scan->addedRest, "viseme_sil");
    // ProjectRun (the CLI's `reduce --project`, `say --project`) reads the same set and rests it.
    const VisemeSet set = loadProjectVisemeSet(project);
    ASSERT_EQ(set.size(), 15u);
    EXPECT_EQ(set.visemes.back().positions, set.neutral.positions);
    const ReduceOutcome outcome = reduceProject(project, set);
    EXPECT_EQ(outcome.result.groupOf().back(), kRestGroup);
    const ReducedModel model = projectReducedModel(project, set);
    EXPECT_NE(std::find(model.resting.begin(), model.resting.end(), "viseme_sil"), model.resting.end());

    // The export: the grouping with viseme_sil resting, no target written for it.
    AvatarWriteSummary summary;
    const std::string glb = reducedAvatarGlb(document, outcome.result.groupOf(), {}, &summary);
    for (const AvatarMeshChange& change : summary.meshes)
        EXPECT_EQ(change.targetsAfter, change.targetsBefore);
    const AvatarScan out = scanAvatar(parseGltfDocument(glb, "out.glb", {}), {});
    EXPECT_EQ(out.visemes.size(), 14u);
    EXPECT_TRUE(out.own.recognised);
    EXPECT_TRUE(out.own.isResting("viseme_sil"));

    // A version 3 file holding it is refused; so is a name that is not a rest viseme's.
    nlohmann::json old = json;
    old["version"] = 3;
    EXPECT_THROW(projectFromJsonText(old.dump(), projectFile), InputError);
    nlohmann::json other = json;
    other["avatar"]["addedRest"] = "rest";
    EXPECT_THROW(projectFromJsonText(other.dump(), projectFile), InputError);
    std::filesystem::remove_all(file.parent_path());
}

TEST(AvatarRestCommand, ThePatternKeepsTheAddedRestWhileTheSelectionHasNone) {
    const auto file = writeNoRestAvatar("pattern");
    const Document added = edit::addAvatarRestViseme(
        documentFromAvatar(loadDocumentAvatar(file, ""), bundledOculus()), bundledOculus());
    const Document vowels = edit::setAvatarPattern(added, "viseme_[aEIOU]*", bundledOculus());
    EXPECT_EQ(visemeNames(vowels).back(), "viseme_sil");
    EXPECT_EQ(vowels.visemeCount(), 6u);
    EXPECT_EQ(vowels.avatar.scan->addedRest, "viseme_sil");
    std::filesystem::remove_all(file.parent_path());
}

} // namespace
} // namespace vl
