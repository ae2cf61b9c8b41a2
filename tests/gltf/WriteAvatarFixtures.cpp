// Writes the avatar fixtures (tests/gltf/AvatarFixtures.h) into a folder: for the Khronos validator
// test, the avatar CLI tests, the benchmark (--bench: a 30,000-vertex avatar) and manual checks.
#include "core/common/AtomicFile.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "core/project/ProjectRun.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/AvatarSpeechFixture.h"
#include "tests/gltf/KeyTableVersion1.h"
#include "tests/gltf/TexturedAvatar.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>

namespace {

// <stem>_original.glb and <stem>_merged.glb: the avatar reduced to m keys in both name modes.
void writeReductions(const std::filesystem::path& dir, const std::string& stem, const std::string& glb, int m,
                     const std::string& pattern) {
    const vl::GltfDocument doc = vl::parseGltfDocument(glb, stem, {});
    const vl::AvatarScan scan = vl::scanAvatar(doc, {pattern});
    vl::ReduceSettings settings;
    settings.target = m;
    settings.weightMode = vl::WeightMode::Area;
    for (vl::AvatarNames names : {vl::AvatarNames::Original, vl::AvatarNames::Merged}) {
        vl::AvatarWriteOptions write;
        write.names = names;
        const auto r = vl::reduceAvatar(doc, scan, vl::uniformFrequencies(scan), settings, write);
        vl::writeFileAtomically(dir / (stem + "_" + vl::toString(names) + ".glb"), r.glb);
    }
}

// <stem>_editor.glb: what the editor's File > Export avatar... writes for the avatar file, imported
// as a document (equal frequencies: no bundled table here), reduced to m keys by the document's settings.
void writeEditorExport(const std::filesystem::path& dir, const std::string& stem, const std::string& pattern,
                       int m, vl::AvatarNames names) {
    const vl::Document document = vl::edit::setTarget(
        vl::documentFromAvatar(vl::loadDocumentAvatar(dir / (stem + ".glb"), pattern), {}), m);
    const std::vector<int> groupOf =
        vl::reduceProject(vl::projectFromDocument(document), *document.visemes).result.groupOf();
    vl::AvatarWriteOptions options;
    options.names = names;
    vl::writeFileAtomically(dir / (stem + "_editor.glb"), vl::reducedAvatarGlb(document, groupOf, options));
}

// rpm_norest.glb (no viseme_sil) and rpm_norest_editor_<names>.glb: exported by the editor after "Add
// rest viseme" (issue 29), the added viseme_sil resting with no target written for it.
void writeAddedRestExports(const std::filesystem::path& dir) {
    vl::test::AvatarFixtureOptions options;
    options.restTarget = false;
    vl::writeFileAtomically(dir / "rpm_norest.glb", vl::test::rpmLikeAvatar(options));
    const vl::Document document = vl::edit::setTarget(
        vl::edit::addAvatarRestViseme(
            vl::documentFromAvatar(vl::loadDocumentAvatar(dir / "rpm_norest.glb", ""), {}), {}),
        5);
    const std::vector<int> groupOf =
        vl::reduceProject(vl::projectFromDocument(document), *document.visemes).result.groupOf();
    for (vl::AvatarNames names : {vl::AvatarNames::Original, vl::AvatarNames::Merged}) {
        vl::AvatarWriteOptions write;
        write.names = names;
        vl::writeFileAtomically(dir / ("rpm_norest_editor_" + std::string(vl::toString(names)) + ".glb"),
                                vl::reducedAvatarGlb(document, groupOf, write));
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR [--bench]\n", argv[0]);
        return 2;
    }
    try {
        using vl::test::FixtureStorage;
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        const std::pair<const char*, FixtureStorage> kinds[] = {{"rpm_plain", FixtureStorage::Plain},
                                                                {"rpm_quantised", FixtureStorage::Quantised},
                                                                {"rpm_meshopt", FixtureStorage::Meshopt},
                                                                {"rpm_sparse", FixtureStorage::Sparse},
                                                                {"rpm_draco", FixtureStorage::Draco}};
        for (const auto& [name, storage] : kinds) {
            vl::test::AvatarFixtureOptions options;
            options.storage = storage;
            const std::string glb = vl::test::rpmLikeAvatar(options);
            vl::writeFileAtomically(dir / (std::string(name) + ".glb"), glb);
            writeReductions(dir, std::string(name) + "_reduced", glb, 6, "");
            // Few keys: most targets are new, in the input's storage (core/gltf/TargetStorage.h).
            writeReductions(dir, std::string(name) + "_reduced2", glb, 2, "");
        }
        // The small textured avatar of the material tests (guide picture, manual checks).
        vl::writeFileAtomically(dir / "textured.glb", vl::test::texturedAvatar());
        // A merged-name reduction as VisemeLab wrote it before key table version 2 (core/gltf/KeyTable.h),
        // for the three.js player's test.
        vl::writeFileAtomically(
            dir / "rpm_plain_reduced_merged_v1.glb",
            vl::test::withKeyTableVersion1(vl::readFileToString(dir / "rpm_plain_reduced_merged.glb")));
        for (bool vrm1 : {false, true}) {
            const std::string stem = vrm1 ? "vroid_vrm1" : "vroid_vrm0",
                              glb = vl::test::vroidLikeAvatar(vrm1);
            vl::writeFileAtomically(dir / (stem + ".glb"), glb);
            writeReductions(dir, stem + "_reduced", glb, 3, "Fcl_MTH_[AIUEO]");
        }
        writeEditorExport(dir, "rpm_plain", "", 5, vl::AvatarNames::Original);
        writeEditorExport(dir, "vroid_vrm0", "Fcl_MTH_[AIUEO]", 3, vl::AvatarNames::Merged);
        writeAddedRestExports(dir);
        // What `say --avatar ... --glb` writes: the avatar itself speaking (full track, and reduced in
        // memory, compressed inputs included; cubic keyframes and sampled dominance).
        using vl::runtime::Interpolation;
        vl::writeFileAtomically(dir / "rpm_plain_speech.glb",
                                vl::test::speakingFixtureGlb(dir / "rpm_plain.glb", 0, Interpolation::Cubic));
        vl::writeFileAtomically(
            dir / "rpm_meshopt_speech_m4.glb",
            vl::test::speakingFixtureGlb(dir / "rpm_meshopt.glb", 4, Interpolation::Linear));
        vl::writeFileAtomically(
            dir / "rpm_draco_speech_m4.glb",
            vl::test::speakingFixtureGlb(dir / "rpm_draco.glb", 4, Interpolation::Dominance));
        // say --reduced on an avatar reduced with merged names: the speech drives the key targets.
        vl::writeFileAtomically(dir / "rpm_plain_speech_merged.glb",
                                vl::test::speakingReducedFixtureGlb(dir / "rpm_plain.glb",
                                                                    dir / "rpm_plain_reduced_merged.glb",
                                                                    Interpolation::Linear));
        if (argc > 2 && std::strcmp(argv[2], "--bench") == 0) {
            // About 30,000 vertices on the 4 meshes that carry the 15 visemes.
            vl::test::AvatarFixtureOptions options;
            options.headColumns = 180;
            options.headRows = 140;
            options.teethColumns = 100;
            options.teethRows = 20;
            options.eyeSegments = 48;
            vl::writeFileAtomically(dir / "rpm_30k.glb", vl::test::rpmLikeAvatar(options));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
