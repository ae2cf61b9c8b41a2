// Documents made from an avatar (the editor's File > Import avatar... / Export avatar...): the
// avatar's visemes over all its meshes as the document's set, the avatar referenced (relative) by the
// project file, the target pattern as an undoable command, and the export equal to the CLI's.
#include "core/document/AvatarDocument.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/ProjectRun.h"
#include "tests/gltf/AvatarFixtures.h"

#include "tests/document/DocumentTestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace vl {
namespace {

FrequencySource oculusTable() {
    return bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus");
}

std::filesystem::path writeRpm(const std::filesystem::path& file) {
    std::filesystem::create_directories(file.parent_path());
    writeFileAtomically(file, test::rpmLikeAvatar());
    return file;
}

Document rpmDocument(const std::filesystem::path& file) {
    return documentFromAvatar(loadDocumentAvatar(file, ""), oculusTable());
}

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(AvatarDocument, ImportedAvatarIsOneVisemeSetOverItsMeshesWithTheOthersShown) {
    const auto dir = test::tempDir("avatar-document-import");
    const Document document = rpmDocument(writeRpm(dir / "rpm.glb"));
    ASSERT_TRUE(document.avatar.isSet());
    EXPECT_TRUE(document.avatar.file.is_absolute());
    EXPECT_EQ(visemeNames(document), test::rpmVisemeNames());
    // Head, teeth and both eyes carry the visemes; the body is only shown.
    int carriers = 0;
    for (const AvatarMesh& mesh : document.avatar.scan->meshes) carriers += mesh.carriesVisemes ? 1 : 0;
    EXPECT_EQ(carriers, 4);
    EXPECT_GT(document.avatar.scan->context.positions.size(), 0u);
    EXPECT_GT(document.avatar.scan->context.triangles.size(), 0u);
    // The set is the scan's (shared, not copied) and its frequencies are the bundled en-us table with
    // the Oculus map, matched to the avatar's names.
    EXPECT_EQ(document.visemes.get(), &document.avatar.scan->set);
    EXPECT_TRUE(document.frequencies.isPhonemeBased());
    for (const auto& [phoneme, viseme] : document.frequencies.map.entries)
        EXPECT_EQ(viseme.rfind("viseme_", 0), 0u) << phoneme << " -> " << viseme;
    EXPECT_EQ(document.target, 7);
    EXPECT_NO_THROW(validateDocument(document));
}

TEST(AvatarDocument, AnAvatarWithoutVisemesIsRefusedWithPatternsThatWouldMatch) {
    const auto dir = test::tempDir("avatar-document-none");
    writeFileAtomically(dir / "vroid.vrm", test::vroidLikeAvatar());
    try {
        rpmDocument(dir / "vroid.vrm");
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("vroid.vrm"), std::string::npos) << message;
        EXPECT_NE(message.find("Fcl_MTH_[AIUEO]"), std::string::npos) << message;
    }
    const Document vroid =
        documentFromAvatar(loadDocumentAvatar(dir / "vroid.vrm", "Fcl_MTH_[AIUEO]"), oculusTable());
    EXPECT_EQ(vroid.visemeCount(), 5u);
    EXPECT_FALSE(vroid.frequencies.isPhonemeBased()); // not Oculus names: equal frequencies
}

TEST(AvatarDocument, ProjectStoresTheAvatarRelativeAndLoadsTheSameDocument) {
    const auto dir = test::tempDir("avatar-document-project");
    const auto avatarFile = writeRpm(dir / "avatars" / "rpm.glb");
    Document document = rpmDocument(avatarFile);
    document = edit::setTarget(document, 5);
    document = edit::setWeightMode(document, WeightMode::Area);
    document =
        edit::setConstraints(document, ConstraintNames{{"viseme_sil"}, {{"viseme_PP", "viseme_aa"}}, {}});
    std::vector<double> painted(document.visemes->vertexCount(), 1.0);
    painted[3] = 0.25;
    document = edit::setPaintedWeights(document, painted);

    const auto projectFile = dir / "projects" / "me.vlproj";
    std::filesystem::create_directories(projectFile.parent_path());
    const Project project = projectFromDocument(document, {}, "viseme_E");
    saveProject(projectFile, project);
    const auto json = nlohmann::json::parse(readText(projectFile));
    EXPECT_EQ(json["avatar"]["file"], "../avatars/rpm.glb");
    EXPECT_FALSE(json["avatar"].contains("targets")); // the Oculus names
    EXPECT_TRUE(json["neutral"].is_null());
    ASSERT_EQ(json["visemes"].size(), 15u);
    EXPECT_EQ(json["visemes"][0], nlohmann::json({{"name", "viseme_sil"}}));

    const LoadedProject loaded = documentFromProject(loadProject(projectFile));
    const Document& back = loaded.document;
    ASSERT_TRUE(back.avatar.isSet());
    EXPECT_EQ(back.avatar.file, std::filesystem::absolute(avatarFile).lexically_normal());
    EXPECT_EQ(back.visemes->neutral, document.visemes->neutral);
    for (std::size_t i = 0; i < document.visemeCount(); ++i)
        EXPECT_EQ(back.visemes->visemes[i].positions, document.visemes->visemes[i].positions);
    EXPECT_EQ(back.frequencies, document.frequencies);
    EXPECT_EQ(back.weights.mode, WeightMode::Painted);
    EXPECT_EQ(back.weights.paintedOrEmpty(), painted);
    EXPECT_EQ(back.target, 5);
    EXPECT_EQ(back.constraints, document.constraints);
    EXPECT_EQ(loaded.selectedViseme, "viseme_E");
    Project again = projectFromDocument(back, {}, "viseme_E");
    again.path = projectFile;
    EXPECT_EQ(rebaseProject(again, projectFile), loadProject(projectFile));

    // Moved as a whole (project and avatar folders), the project still opens.
    const auto moved = test::tempDir("avatar-document-project-moved");
    std::filesystem::copy(dir, moved, std::filesystem::copy_options::recursive);
    std::filesystem::remove_all(dir);
    EXPECT_EQ(visemeNames(documentFromProject(loadProject(moved / "projects" / "me.vlproj")).document),
              test::rpmVisemeNames());
    // The same project through the CLI's path (reduce/export --project) reads the avatar's set.
    EXPECT_EQ(loadProjectVisemeSet(loadProject(moved / "projects" / "me.vlproj")).visemes.size(), 15u);
    std::filesystem::remove_all(moved);
}

TEST(AvatarDocument, ProjectAvatarErrorsNameTheJsonPath) {
    const auto dir = test::tempDir("avatar-document-errors");
    const auto avatarFile = writeRpm(dir / "rpm.glb");
    const auto projectFile = dir / "p.vlproj";
    saveProject(projectFile, projectFromDocument(rpmDocument(avatarFile)));
    const std::string text = readText(projectFile);
    const auto expectError = [&](const std::string& edited, const std::string& part) {
        writeFileAtomically(projectFile, edited);
        try {
            documentFromProject(loadProject(projectFile));
            ADD_FAILURE() << "no error for " << part;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    auto withTargets = json;
    withTargets["avatar"]["targets"] = "viseme_[";
    expectError(withTargets.dump(), "/avatar/targets");
    auto missing = json;
    missing["avatar"]["file"] = "nosuch.glb";
    expectError(missing.dump(), "/avatar/file: file not found");
    auto withNeutral = json;
    withNeutral["neutral"] = {{"file", "rpm.glb"}};
    expectError(withNeutral.dump(), "/neutral: must be null");
    auto withFile = json;
    withFile["visemes"][2]["file"] = "rpm.glb";
    expectError(withFile.dump(), "/visemes/2");
    // The avatar file replaced by one with other visemes: the project says which it expected.
    writeFileAtomically(avatarFile, test::vroidLikeAvatar());
    auto vroid = json;
    vroid["avatar"]["targets"] = "Fcl_MTH_[AIUEO]";
    expectError(vroid.dump(), "/visemes: the project lists the visemes viseme_sil");
    std::filesystem::remove_all(dir);
}

TEST(AvatarDocument, TargetPatternIsACommandThatKeepsWhatStillFits) {
    const auto dir = test::tempDir("avatar-document-pattern");
    Document document = rpmDocument(writeRpm(dir / "rpm.glb"));
    document = edit::setTarget(document, 9);
    document = edit::setConstraints(document, ConstraintNames{{"viseme_aa", "viseme_PP"}, {}, {}});
    document = edit::setWeightMode(document, WeightMode::Area);

    const Document vowels = edit::setAvatarPattern(document, "viseme_[aEIOU]*", oculusTable());
    EXPECT_EQ(visemeNames(vowels),
              (std::vector<std::string>{"viseme_aa", "viseme_E", "viseme_I", "viseme_O", "viseme_U"}));
    EXPECT_EQ(vowels.avatar.pattern, "viseme_[aEIOU]*");
    EXPECT_EQ(vowels.avatar.gltf, document.avatar.gltf);                         // the file is not read again
    EXPECT_EQ(vowels.target, 5);                                                 // clamped
    EXPECT_EQ(vowels.constraints.pinned, std::vector<std::string>{"viseme_aa"}); // PP is gone
    EXPECT_EQ(vowels.weights.mode, WeightMode::Area);
    // The Oculus map names visemes this set lacks: equal frequencies.
    EXPECT_FALSE(vowels.frequencies.isPhonemeBased());
    EXPECT_NO_THROW(validateDocument(vowels));

    // Back to the Oculus names: the bundled table applies again; the input document is unchanged.
    const Document all = edit::setAvatarPattern(vowels, "", oculusTable());
    EXPECT_EQ(visemeNames(all), test::rpmVisemeNames());
    EXPECT_TRUE(all.frequencies.isPhonemeBased());
    EXPECT_EQ(visemeNames(document), test::rpmVisemeNames());

    EXPECT_THROW(edit::setAvatarPattern(document, "viseme_si*", oculusTable()), InputError); // 1 viseme
    EXPECT_THROW(edit::setAvatarPattern(document, "nothing*", oculusTable()), InputError);
    EXPECT_THROW(edit::setAvatarPattern(document, "viseme_[", oculusTable()), InputError);
    Document plain;
    EXPECT_THROW(edit::setAvatarPattern(plain, "*", oculusTable()), InputError);
}

TEST(AvatarDocument, PaintedWeightsSurviveAPatternOverTheSameMeshes) {
    const auto dir = test::tempDir("avatar-document-painted");
    Document document = rpmDocument(writeRpm(dir / "rpm.glb"));
    std::vector<double> painted(document.visemes->vertexCount(), 0.5);
    painted[0] = 1.0;
    document = edit::setPaintedWeights(document, painted);
    // Every mesh carries the vowels too: the same concatenated geometry, the same painted weights.
    const Document vowels = edit::setAvatarPattern(document, "viseme_[aEIOU]*", oculusTable());
    ASSERT_EQ(vowels.visemes->neutral, document.visemes->neutral);
    EXPECT_EQ(vowels.weights.mode, WeightMode::Painted);
    EXPECT_EQ(vowels.weights.paintedOrEmpty(), painted);
}

TEST(AvatarDocument, TheAvatarsVisemeSetIsEditedOnlyThroughThePattern) {
    const auto dir = test::tempDir("avatar-document-refuse");
    const Document document = rpmDocument(writeRpm(dir / "rpm.glb"));
    EXPECT_THROW(edit::removeViseme(document, 0), InputError);
    EXPECT_THROW(edit::addViseme(document, "extra", document.visemes->neutral, {}), InputError);
    // A frequency table naming visemes the bundled way ("aa", "ih") applies to the avatar's names.
    FrequencySource table;
    table.visemeFrequencies.entries = {{"sil", 3.0}, {"aa", 2.0}, {"ih", 1.0}};
    for (const std::string& name : test::rpmVisemeNames())
        if (name != "viseme_sil" && name != "viseme_aa" && name != "viseme_I")
            table.visemeFrequencies.entries.emplace_back(name, 1.0);
    const Document edited = edit::setFrequencies(document, table);
    const std::vector<double> f = documentFrequencies(edited);
    EXPECT_DOUBLE_EQ(f[0], 3.0 / 18.0); // viseme_sil
}

// The editor's export writes exactly what `visemelab avatar reduce` writes for the same grouping.
TEST(AvatarDocument, ExportIsTheCoresReducedAvatar) {
    const auto dir = test::tempDir("avatar-document-export");
    const auto file = writeRpm(dir / "rpm.glb");
    Document document = rpmDocument(file);
    document = edit::setTarget(document, 6);

    const GltfDocument gltf = loadGltfDocument(file);
    const AvatarScan scan = scanAvatar(gltf, {""});
    ReduceSettings settings;
    settings.target = 6;
    for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
        AvatarWriteOptions options;
        options.names = names;
        const AvatarReduction cli = reduceAvatar(gltf, scan, document.frequencies, settings, options);
        AvatarWriteSummary summary;
        const std::string glb = reducedAvatarGlb(document, cli.outcome.result.groupOf(), options, &summary);
        EXPECT_EQ(glb, cli.glb) << toString(names);
        EXPECT_EQ(summary.meshes.size(), 4u);
        // The output reads back as VisemeLab's reduction: the same visemes (original names) or its
        // keys (merged names).
        const AvatarScan out = scanAvatar(parseGltfDocument(glb, "out.glb", {}), {""});
        EXPECT_TRUE(out.own.recognised);
        if (names == AvatarNames::Original) {
            EXPECT_EQ(out.visemes, scan.visemes);
        } else {
            EXPECT_EQ(out.visemes.size(), 6u);
        }
    }
    EXPECT_THROW(reducedAvatarGlb(document, {0, 1}), InputError);
    EXPECT_THROW(checkAvatarOutput(document, file), InputError);
    EXPECT_THROW(checkAvatarOutput(document, dir / "." / "rpm.glb"), InputError);
    EXPECT_THROW(checkAvatarOutput(document, dir / "out.gltf"), InputError);
    EXPECT_NO_THROW(checkAvatarOutput(document, dir / "out.glb"));
    EXPECT_THROW(checkAvatarOutput(Document{}, dir / "out.glb"), InputError);
}

} // namespace
} // namespace vl
