// An avatar whose visemes lack a rest viseme gaining one (core/gltf/AvatarRest.h, issue 29): the base
// mesh under the avatar's spelling, carried by no target; it rests in the rest-free reduction, the
// writer adds no target for it in either name mode, and speech shows the neutral in pauses.
#include "core/gltf/AvatarRest.h"
#include "core/common/Error.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "core/reduce/Reduction.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/AvatarFolderTest.h"
#include "tests/gltf/AvatarSpeechFixture.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

std::string noRestAvatarGlb() {
    test::AvatarFixtureOptions options;
    options.restTarget = false;
    return test::rpmLikeAvatar(options);
}

bool namesContain(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(AvatarRest, AddedRestIsTheBaseMeshUnderTheAvatarsSpellingOnNoTarget) {
    const GltfDocument doc = parseGltfDocument(noRestAvatarGlb(), "norest.glb", {});
    const AvatarScan plain = scanAvatar(doc, {});
    ASSERT_EQ(plain.visemes.size(), 14u);
    EXPECT_FALSE(avatarHasRest(plain));
    EXPECT_EQ(avatarRestName(plain), "viseme_sil");
    // Without sil the Oculus map does not fit: the avatar reduces with equal frequencies.
    EXPECT_FALSE(mapFitsAvatar(test::fixturePhonemeTable().map, plain));

    const AvatarScan scan = scanAvatar(doc, {"", false, "viseme_sil"});
    ASSERT_EQ(scan.visemes.size(), 15u);
    EXPECT_EQ(scan.visemes.back(), "viseme_sil");
    EXPECT_EQ(scan.addedRest, "viseme_sil");
    EXPECT_TRUE(avatarHasRest(scan));
    EXPECT_TRUE(scan.oculusNames);
    EXPECT_EQ(scan.set.visemes.back().name, "viseme_sil");
    EXPECT_EQ(scan.set.visemes.back().positions, scan.set.neutral.positions); // zero displacement
    for (const AvatarMesh& mesh : scan.meshes)
        for (const AvatarTarget& target : mesh.targets) EXPECT_NE(target.viseme, 14) << target.name;
    EXPECT_TRUE(mapFitsAvatar(test::fixturePhonemeTable().map, scan));

    // Refused: a second rest viseme, and a name that is not a rest viseme's.
    AvatarScan withRest = scanAvatar(parseGltfDocument(test::rpmLikeAvatar(), "rpm.glb", {}), {});
    EXPECT_THROW(addAvatarRest(withRest, "viseme_sil"), InputError);
    AvatarScan other = plain;
    EXPECT_THROW(addAvatarRest(other, "rest"), InputError);
    // Names without the "viseme_" prefix get "sil".
    const AvatarScan vroid =
        scanAvatar(parseGltfDocument(test::vroidLikeAvatar(), "vroid.vrm", {}), {"Fcl_MTH_[AIUEO]"});
    EXPECT_FALSE(avatarHasRest(vroid));
    EXPECT_EQ(avatarRestName(vroid), "sil");
}

TEST(AvatarRest, ItRestsAndTheReducedAvatarGainsNoTargetInEitherNameMode) {
    const GltfDocument doc = parseGltfDocument(noRestAvatarGlb(), "norest.glb", {});
    const AvatarScan scan = scanAvatar(doc, {"", false, "viseme_sil"});
    const FrequencySource frequencies = defaultAvatarFrequencies(scan, test::fixturePhonemeTable());
    ASSERT_TRUE(frequencies.isPhonemeBased()); // the Oculus table fits with the rest added
    for (const AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
        SCOPED_TRACE(toString(names));
        AvatarWriteOptions write;
        write.names = names;
        const AvatarReduction r = reduceAvatar(doc, scan, frequencies, avatarReduceSettings(5), write);
        const std::vector<int> groupOf = r.outcome.result.groupOf();
        EXPECT_EQ(groupOf.back(), kRestGroup);
        EXPECT_TRUE(namesContain(r.outcome.model.resting, "viseme_sil"));
        const auto silence =
            std::find_if(r.outcome.model.phonemeToKey.begin(), r.outcome.model.phonemeToKey.end(),
                         [](const auto& entry) { return entry.first == "sil"; });
        ASSERT_NE(silence, r.outcome.model.phonemeToKey.end());
        EXPECT_EQ(silence->second, kRestingKey);

        // The output: no target named viseme_sil anywhere, as many targets as before with original
        // names, recognised as VisemeLab's reduction with viseme_sil resting.
        const GltfDocument out = parseGltfDocument(r.glb, "out.glb", {});
        if (names == AvatarNames::Original) {
            for (const AvatarMeshChange& change : r.summary.meshes) {
                EXPECT_EQ(change.targetsAfter, change.targetsBefore) << change.name;
            }
        }
        for (const Json& mesh : out.json["meshes"]) {
            if (!mesh.contains("extras") || !mesh["extras"].contains("targetNames")) continue;
            const auto targetNames = mesh["extras"]["targetNames"].get<std::vector<std::string>>();
            EXPECT_FALSE(namesContain(targetNames, "viseme_sil")) << mesh["name"];
            for (const Json& primitive : mesh["primitives"])
                EXPECT_EQ(primitive["targets"].size(), targetNames.size());
        }
        // The key table (version 2, root only) lists it among the resting visemes, on no key.
        const Json& table = out.json.at("extras").at("visemelab");
        EXPECT_TRUE(namesContain(table.at("resting").get<std::vector<std::string>>(), "viseme_sil"));
        for (const Json& key : table.at("keys"))
            EXPECT_FALSE(namesContain(key.at("members").get<std::vector<std::string>>(), "viseme_sil"));
        const AvatarScan reread = scanAvatar(out, {});
        ASSERT_TRUE(reread.own.recognised) << (reread.own.notes.empty() ? "" : reread.own.notes.front());
        EXPECT_TRUE(reread.own.isResting("viseme_sil"));
        EXPECT_FALSE(avatarHasRest(reread));
    }
}

using AvatarRestSpeech = test::AvatarFolderTest;

// The key weights of a face track at time t, as the avatar's morph targets get them.
std::vector<float> pauseTargetWeights(const AvatarSpeech& speech, const ReducedModel& face, double t) {
    const FaceTrack track(face, test::fixtureUtterance(), PlaybackSettings{runtime::Interpolation::Linear},
                          "test");
    const std::vector<float> keys = track.keyWeights(t);
    std::vector<float> weights;
    for (const MeshDrive& drive : speech.drives)
        for (int key : drive.keyOfTarget)
            if (key >= 0) weights.push_back(keys[static_cast<std::size_t>(key)]);
    return weights;
}

TEST_F(AvatarRestSpeech, AnAvatarWithoutRestSpeaksWithThePausesAtAllWeightsZero) {
    writeFileAtomically(dir / "norest.glb", noRestAvatarGlb());
    for (const int m : {0, 4}) {
        SCOPED_TRACE("m " + std::to_string(m));
        AvatarSpeechOptions options;
        options.phonemeTable = test::fixturePhonemeTable();
        options.reduceTo = m;
        const AvatarSpeech speech = avatarSpeech(dir / "norest.glb", options); // the map fits: no error
        const ReducedModel& face = speech.reducedFace ? speech.faces.reduced : speech.faces.full;
        ASSERT_FALSE(speech.drives.empty());
        // The final pause ('sil', 1.2 .. 1.4 s) holds the neutral: every viseme target at 0; AA does not.
        for (float w : pauseTargetWeights(speech, face, 1.35)) EXPECT_NEAR(w, 0.0f, 1e-6);
        const std::vector<float> aa = pauseTargetWeights(speech, face, 0.35);
        EXPECT_GT(*std::max_element(aa.begin(), aa.end()), 0.5f);
    }
}

} // namespace
} // namespace vl
