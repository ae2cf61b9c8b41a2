// `visemelab project new --avatar` and `visemelab say --avatar`: an avatar speaks without a
// hand-written project; the animated GLB is the avatar itself.
#include "core/common/AtomicFile.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/TargetNames.h"
#include "core/project/Project.h"
#include "core/speech/TrackJson.h"
#include "tests/cli/CliRunner.h"
#include "tests/gltf/AvatarFolderTest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace vl {
namespace {

class SayAvatarCli : public test::AvatarFolderTest {
  protected:
    // Runs `say`; skips (loudly) when espeak-ng cannot speak here (no voice data).
    test::CliResult say(const std::string& arguments) {
        auto r = test::runCli("say 'Hello, world. How are you?' " + arguments);
        if (r.exitCode != 0 && r.output.find("espeak") != std::string::npos &&
            r.output.find("voice") != std::string::npos)
            skipped = "espeak-ng cannot speak here: " + r.output;
        return r;
    }
    std::string skipped;
};

std::string bundled(const char* file) {
    return (std::filesystem::path(VISEMELAB_ASSETS_DIR) / "phonemes" / file).string();
}

} // namespace

TEST_F(SayAvatarCli, ProjectNewFromAnAvatarRoundTrips) {
    const auto r = test::runCli("project new --avatar " + path("rpm.glb") + " --out " + path("p.vlproj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Project project = loadProject(dir / "p.vlproj");
    EXPECT_EQ(project.avatar.file, std::filesystem::path("rpm.glb")); // relative to the project
    EXPECT_TRUE(project.avatar.targets.empty());
    ASSERT_EQ(project.visemes.size(), 15u);
    EXPECT_EQ(project.visemes.front().name, "viseme_sil");
    EXPECT_EQ(project.reduction.target, 7); // n / 2, as File > Import avatar...
    EXPECT_TRUE(project.frequencies.isPhonemeBased());
    const auto check = test::runCli("project check " + path("p.vlproj"));
    ASSERT_EQ(check.exitCode, 0) << check.output;
    EXPECT_NE(check.output.find("15 visemes"), std::string::npos) << check.output;
    // Saved again it is the same file.
    saveProject(dir / "again.vlproj", project);
    EXPECT_EQ(loadProject(dir / "again.vlproj").visemes, project.visemes);

    const auto target = test::runCli("project new --avatar " + path("rpm.glb") +
                                     " --target 4 --reduce --out " + path("q.vlproj"));
    ASSERT_EQ(target.exitCode, 0) << target.output;
    EXPECT_EQ(loadProject(dir / "q.vlproj").reduction.target, 4);
    EXPECT_TRUE(loadProject(dir / "q.vlproj").reduction.result);
    EXPECT_EQ(test::runCli("project new --out " + path("r.vlproj")).exitCode, 2);
    EXPECT_EQ(test::runCli("project new --avatar " + path("rpm.glb") + " --visemes " + dir.string() +
                           " --out " + path("r.vlproj"))
                  .exitCode,
              2);

    // An Oculus-named project speaks with the Rhubarb map, its error in mm (glTF is in metres).
    const auto rhubarb = say("--project " + path("p.vlproj") + " --map " + bundled("map_rhubarb.csv") +
                             " --out " + path("t.json"));
    if (!skipped.empty()) GTEST_SKIP() << skipped;
    ASSERT_EQ(rhubarb.exitCode, 0) << rhubarb.output;
    EXPECT_NE(rhubarb.output.find("speech error (m = 7): RMS "), std::string::npos) << rhubarb.output;
    EXPECT_NE(rhubarb.output.find(" mm"), std::string::npos) << rhubarb.output;
}

// An avatar without a rest viseme (issue 29): `project new --avatar` adds viseme_sil (the base mesh,
// no target) when the rest is free or auto, so the pause rests and the bundled en-us table applies;
// --no-add-rest keeps the avatar's visemes, --add-rest adds it with the rest keyed too.
TEST_F(SayAvatarCli, ProjectNewAddsTheRestAnAvatarLacks) {
    test::AvatarFixtureOptions options;
    options.restTarget = false;
    writeFileAtomically(dir / "norest.glb", test::rpmLikeAvatar(options));
    const auto r =
        test::runCli("project new --avatar " + path("norest.glb") + " --reduce --out " + path("p.vlproj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("15 visemes (viseme_sil added: the base mesh, no target)"), std::string::npos)
        << r.output;
    const Project project = loadProject(dir / "p.vlproj");
    EXPECT_EQ(project.avatar.addedRest, "viseme_sil");
    ASSERT_EQ(project.visemes.size(), 15u);
    EXPECT_EQ(project.visemes.back().name, "viseme_sil");
    ASSERT_TRUE(project.frequencies.isPhonemeBased());
    ASSERT_NE(project.frequencies.map.visemeOf("sil"), nullptr);
    EXPECT_EQ(*project.frequencies.map.visemeOf("sil"), "viseme_sil");
    ASSERT_TRUE(project.reduction.result);
    EXPECT_TRUE(project.reduction.result->restFree);
    EXPECT_EQ(test::runCli("project check " + path("p.vlproj")).exitCode, 0);

    const auto kept = test::runCli("project new --avatar " + path("norest.glb") + " --no-add-rest --out " +
                                   path("q.vlproj"));
    ASSERT_EQ(kept.exitCode, 0) << kept.output;
    EXPECT_TRUE(loadProject(dir / "q.vlproj").avatar.addedRest.empty());
    EXPECT_EQ(loadProject(dir / "q.vlproj").visemes.size(), 14u);
    const auto keyed =
        test::runCli("project new --avatar " + path("norest.glb") + " --rest key --out " + path("k.vlproj"));
    ASSERT_EQ(keyed.exitCode, 0) << keyed.output;
    EXPECT_TRUE(loadProject(dir / "k.vlproj").avatar.addedRest.empty());
    const auto forced = test::runCli("project new --avatar " + path("norest.glb") +
                                     " --rest key --add-rest --out " + path("f.vlproj"));
    ASSERT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_EQ(loadProject(dir / "f.vlproj").avatar.addedRest, "viseme_sil");
    // An avatar with its own rest gains nothing; the flags are refused where they mean nothing.
    ASSERT_EQ(
        test::runCli("project new --avatar " + path("rpm.glb") + " --out " + path("own.vlproj")).exitCode, 0);
    EXPECT_TRUE(loadProject(dir / "own.vlproj").avatar.addedRest.empty());
    EXPECT_EQ(test::runCli("project new --avatar " + path("norest.glb") + " --add-rest --no-add-rest --out " +
                           path("x.vlproj"))
                  .exitCode,
              2);
    EXPECT_EQ(test::runCli("project new --visemes " + dir.string() + " --add-rest --out " + path("x.vlproj"))
                  .exitCode,
              2);

    // The project speaks with the bundled table: the pauses are its rest.
    const auto spoken = say("--project " + path("p.vlproj") + " --out " + path("t.json"));
    if (!skipped.empty()) GTEST_SKIP() << skipped;
    ASSERT_EQ(spoken.exitCode, 0) << spoken.output;
    EXPECT_EQ(loadTrackJson(dir / "t.json").mouthCues.front().value, "viseme_sil");
}

TEST_F(SayAvatarCli, SaysWithAnAvatarReducedInMemoryAndWritesTheAvatarSpeaking) {
    const auto r = say("--avatar " + path("rpm.glb") + " -m 4 --out " + path("t.json") + " --glb " +
                       path("anim.glb") + " --blend linear");
    if (!skipped.empty()) GTEST_SKIP() << skipped;
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("speech error (m = 4): RMS "), std::string::npos) << r.output;
    const SpeechTrackFile track = loadTrackJson(dir / "t.json");
    ASSERT_TRUE(track.error && track.error->displacement);
    const TrackDisplacementError& d = *track.error->displacement;
    EXPECT_EQ(d.unit, "mm");
    EXPECT_GT(d.max, 0.0);
    EXPECT_LE(d.rms, d.max);
    EXPECT_EQ(d.rmsFrames.size(), track.error->frames.size());
    EXPECT_EQ(track.mouthCues.front().value, "viseme_sil"); // the avatar's names

    const GltfDocument input = loadGltfDocument(dir / "rpm.glb"), anim = loadGltfDocument(dir / "anim.glb");
    EXPECT_EQ(anim.model.meshes.size(), input.model.meshes.size());
    EXPECT_EQ(anim.model.skins.size(), input.model.skins.size());
    EXPECT_EQ(anim.model.materials.size(), input.model.materials.size());
    ASSERT_EQ(anim.model.animations.size(), input.model.animations.size() + 1);
    EXPECT_EQ(anim.model.animations.back().channels.size(), 4u); // head, teeth, eyes
    EXPECT_TRUE(anim.json["extras"].contains("visemelab"));      // the reduced avatar

    // The same reduction from a file `avatar reduce` wrote: the same reduced track.
    const auto reduce =
        test::runCli("avatar reduce " + path("rpm.glb") + " -m 4 --out " + path("reduced.glb"));
    ASSERT_EQ(reduce.exitCode, 0) << reduce.output;
    const auto fromFile =
        say("--avatar " + path("rpm.glb") + " --reduced " + path("reduced.glb") + " --out " +
            path("t2.json") + " --glb " + path("anim2.glb") + " --blend linear");
    ASSERT_EQ(fromFile.exitCode, 0) << fromFile.output;
    const SpeechTrackFile second = loadTrackJson(dir / "t2.json");
    EXPECT_EQ(second.reducedCues, track.reducedCues);
    EXPECT_EQ(second.mouthCues, track.mouthCues);
    EXPECT_NEAR(second.error->displacement->rms, d.rms, 1e-6 * (1 + d.rms));
    EXPECT_EQ(loadGltfDocument(dir / "anim2.glb").model.animations.size(), input.model.animations.size() + 1);

    // Without a reduction the avatar speaks its full track; the Rhubarb map is read by meaning.
    const auto full = say("--avatar " + path("rpm.glb") + " --map " + bundled("map_rhubarb.csv") + " --out " +
                          path("t3.json") + " --glb " + path("anim3.glb"));
    ASSERT_EQ(full.exitCode, 0) << full.output;
    EXPECT_EQ(loadTrackJson(dir / "t3.json").error->displacement->max, 0.0);

    // Usage: -m and --reduced together, avatar options without --avatar, --glb over the input.
    EXPECT_EQ(say("--avatar " + path("rpm.glb") + " -m 4 --reduced " + path("reduced.glb") + " --out " +
                  path("x.json"))
                  .exitCode,
              2);
    EXPECT_EQ(say("--project p.vlproj -m 4 --out " + path("x.json")).exitCode, 2);
    EXPECT_EQ(say("--avatar " + path("rpm.glb") + " --out " + path("x.json") + " --glb " + path("rpm.glb"))
                  .exitCode,
              2);
}

TEST_F(SayAvatarCli, SaysOnAnAvatarReducedWithMergedNamesByTheNamesItsTargetsHave) {
    const auto reduce =
        test::runCli("avatar reduce " + path("rpm.glb") + " -m 4 --names merged --out " + path("merged.glb"));
    ASSERT_EQ(reduce.exitCode, 0) << reduce.output;
    const auto inspect = test::runCli("avatar inspect " + path("merged.glb"));
    ASSERT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("Visemes: 4 (keys of VisemeLab's reduction)"), std::string::npos)
        << inspect.output;
    EXPECT_NE(inspect.output.find("reduced by VisemeLab: 4 keys from 15 visemes (names merged)"),
              std::string::npos)
        << inspect.output;
    ASSERT_EQ(
        test::runCli("avatar inspect " + path("merged.glb") + " --json " + path("inspect.json")).exitCode, 0);
    const auto report = nlohmann::json::parse(readFileToString(dir / "inspect.json"));
    EXPECT_EQ(report["visemelab"]["names"], "merged");
    EXPECT_EQ(report["visemelab"]["visemes"], 15);
    ASSERT_EQ(report["visemelab"]["keys"].size(), 4u);
    std::size_t members = report["visemelab"]["resting"].size();
    for (const auto& key : report["visemelab"]["keys"]) members += key["members"].size();
    EXPECT_EQ(members, 15u);

    const auto r = say("--avatar " + path("rpm.glb") + " --reduced " + path("merged.glb") + " --out " +
                       path("t.json") + " --glb " + path("anim.glb") + " --blend linear");
    if (!skipped.empty()) GTEST_SKIP() << skipped;
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Every key of the reduced track is the name of a target of the merged file.
    const GltfDocument merged = loadGltfDocument(dir / "merged.glb");
    std::set<std::string> targetNames;
    for (std::size_t m = 0; m < merged.model.meshes.size(); ++m)
        for (const TargetName& t : meshTargetNames(merged, static_cast<int>(m))) targetNames.insert(t.name);
    const SpeechTrackFile track = loadTrackJson(dir / "t.json");
    ASSERT_FALSE(track.reducedCues.empty());
    std::set<std::string> spoken;
    for (const Cue& cue : track.reducedCues)
        if (cue.value != kRestCue) {
            EXPECT_TRUE(targetNames.count(cue.value)) << cue.value;
            spoken.insert(cue.value);
        }
    EXPECT_GE(spoken.size(), 2u);
    // The speaking avatar: the merged file with one more animation driving its four viseme meshes,
    // still read as VisemeLab's reduction.
    const GltfDocument anim = loadGltfDocument(dir / "anim.glb");
    ASSERT_EQ(anim.model.animations.size(), merged.model.animations.size() + 1);
    EXPECT_EQ(anim.model.animations.back().channels.size(), 4u);
    const AvatarScan scan = scanAvatar(anim, {});
    EXPECT_TRUE(scan.own.recognised);
    EXPECT_EQ(scan.visemes.size(), 4u);
}

} // namespace vl
