// An avatar speaking without a project (core/project/AvatarSpeech.h, AvatarSpeechGlb.h) and maps of
// other namings used on its names (core/gltf/VisemeMapNames.h).
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/TargetNames.h"
#include "core/gltf/VisemeMapNames.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/AvatarFolderTest.h"
#include "tests/gltf/AvatarSpeechFixture.h"
#include "tests/gltf/GltfTestSupport.h"
#include "tests/gltf/KeyTableVersion1.h"

#include <gtest/gtest.h>

#include <set>

namespace vl {
namespace {

using AvatarSpeechTest = test::AvatarFolderTest;

std::set<int> nodesOfVisemeMeshes(const GltfDocument& doc) {
    const AvatarScan scan = scanAvatar(doc, {});
    std::set<int> nodes;
    for (const AvatarMesh& mesh : scan.meshes)
        for (std::size_t n = 0; n < doc.model.nodes.size(); ++n)
            if (mesh.carriesVisemes && doc.model.nodes[n].mesh == mesh.index)
                nodes.insert(static_cast<int>(n));
    return nodes;
}

// What `avatar reduce AVATAR -m 4 [--names merged]` writes with the fixture's phoneme table (uniform
// weights, the rest free).
std::string reducedFixture(const std::filesystem::path& avatar, AvatarNames names) {
    const GltfDocument doc = loadGltfDocument(avatar);
    const AvatarScan scan = scanAvatar(doc, {});
    const ReduceSettings settings = avatarReduceSettings(4);
    AvatarWriteOptions write;
    write.names = names;
    return reduceAvatar(doc, scan, defaultAvatarFrequencies(scan, test::fixturePhonemeTable()), settings,
                        write)
        .glb;
}

struct TwoReductions {
    AvatarSpeech inMemory, fromFile;
};

// rpm.glb in `dir` speaking reduced to 4 keys in memory, and from the file `avatar reduce` wrote.
TwoReductions reducedTwice(const std::filesystem::path& dir, AvatarNames names) {
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    options.reduceTo = 4;
    TwoReductions r{avatarSpeech(dir / "rpm.glb", options), {}};
    const std::filesystem::path file = dir / (std::string("reduced_") + toString(names) + ".glb");
    writeFileAtomically(file, reducedFixture(dir / "rpm.glb", names));
    options.reduceTo = 0;
    options.reduced = file;
    r.fromFile = avatarSpeech(dir / "rpm.glb", options);
    return r;
}

// The same keys (members and geometry), resting visemes and phoneme map.
void expectSameReducedFace(const ReducedModel& a, const ReducedModel& b) {
    ASSERT_EQ(a.keys.size(), b.keys.size());
    for (std::size_t k = 0; k < a.keys.size(); ++k) {
        EXPECT_EQ(a.keys[k].members, b.keys[k].members);
        for (std::size_t v = 0; v < a.keys[k].positions.size(); ++v)
            ASSERT_NEAR((a.keys[k].positions[v] - b.keys[k].positions[v]).norm(), 0.0, 1e-5) << k << " " << v;
    }
    EXPECT_EQ(a.resting, b.resting);
    EXPECT_EQ(a.phonemeToKey, b.phonemeToKey);
}

} // namespace

TEST_F(AvatarSpeechTest, ReducedAvatarSpeaksWithEveryMeshSkinAndMaterialKept) {
    const GltfDocument input = loadGltfDocument(dir / "rpm.glb");
    const GltfDocument out = parseGltfDocument(
        test::speakingFixtureGlb(dir / "rpm.glb", 4, runtime::Interpolation::Linear), "anim", {});
    EXPECT_EQ(out.model.meshes.size(), input.model.meshes.size());
    EXPECT_EQ(out.model.skins.size(), input.model.skins.size());
    EXPECT_EQ(out.model.materials.size(), input.model.materials.size());
    EXPECT_EQ(out.model.nodes.size(), input.model.nodes.size());
    ASSERT_EQ(out.model.animations.size(), input.model.animations.size() + 1);
    const tinygltf::Animation& speech = out.model.animations.back();
    EXPECT_EQ(speech.name, "speech");
    std::set<int> animated;
    for (const auto& channel : speech.channels) {
        EXPECT_EQ(channel.target_path, "weights");
        animated.insert(channel.target_node);
    }
    EXPECT_EQ(animated, nodesOfVisemeMeshes(out));
    EXPECT_EQ(animated.size(), 4u); // head, teeth, two eyes

    // The head at a keyframe inside AA (0.2 .. 0.5 s): the target AA drives holds all the weight.
    const int headNode = *std::find_if(animated.begin(), animated.end(), [&](int n) {
        return out.model.meshes[static_cast<std::size_t>(out.model.nodes[static_cast<std::size_t>(n)].mesh)]
                   .name == "Wolf3D_Head";
    });
    const auto channel = std::find_if(speech.channels.begin(), speech.channels.end(),
                                      [&](const auto& c) { return c.target_node == headNode; });
    const tinygltf::AnimationSampler& sampler = speech.samplers[static_cast<std::size_t>(channel->sampler)];
    EXPECT_EQ(sampler.interpolation, "LINEAR");
    BufferViews views(out);
    AccessorReader reader(out, views);
    const std::vector<float> times = reader.floats(sampler.input, TINYGLTF_TYPE_SCALAR, "input");
    const std::vector<float> weights = reader.floats(sampler.output, TINYGLTF_TYPE_SCALAR, "output");
    const auto& headMesh =
        out.json["meshes"]
                [static_cast<std::size_t>(out.model.nodes[static_cast<std::size_t>(headNode)].mesh)];
    const std::size_t targets = headMesh["extras"]["targetNames"].size();
    ASSERT_EQ(weights.size(), times.size() * targets);
    // AA's key (root table) is driven by its first target on the head (the mesh's visemeKeys).
    const auto aaKey = out.json["extras"]["visemelab"]["phonemeToKey"]["AA"].get<std::size_t>();
    const int aaTarget = headMesh["extras"]["visemeKeys"][aaKey][0].get<int>();
    std::set<int> visemeTargets;
    for (const auto& keyTargets : headMesh["extras"]["visemeKeys"])
        for (const auto& t : keyTargets) visemeTargets.insert(t.get<int>());
    bool sawAa = false;
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (!(times[i] > 0.2f && times[i] < 0.5f)) continue;
        sawAa = true;
        EXPECT_FLOAT_EQ(weights[i * targets + static_cast<std::size_t>(aaTarget)], 1.0f) << times[i];
        double sum = 0;
        for (int t : visemeTargets) sum += weights[i * targets + static_cast<std::size_t>(t)];
        EXPECT_NEAR(sum, 1.0, 1e-6);
    }
    EXPECT_TRUE(sawAa);
    // Non-viseme targets (ARKit blinks) keep the mesh's default weight, 0 here, throughout.
    for (std::size_t t = 0; t < targets; ++t)
        if (!visemeTargets.count(static_cast<int>(t))) {
            for (std::size_t i = 0; i < times.size(); ++i) ASSERT_EQ(weights[i * targets + t], 0.0f);
        }
}

TEST_F(AvatarSpeechTest, ReducedFileGivesTheSameFaceAsReducingInMemory) {
    const auto [inMemory, fromFile] = reducedTwice(dir, AvatarNames::Original);
    ASSERT_TRUE(fromFile.reducedFace);
    ASSERT_EQ(fromFile.faces.reduced.keys.size(), 4u);
    expectSameReducedFace(fromFile.faces.reduced, inMemory.faces.reduced);
    EXPECT_FALSE(fromFile.faces.reduced.resting.empty()); // viseme_sil at least
    ASSERT_EQ(fromFile.drives.size(), inMemory.drives.size());
    for (std::size_t d = 0; d < fromFile.drives.size(); ++d)
        EXPECT_EQ(fromFile.drives[d].keyOfTarget, inMemory.drives[d].keyOfTarget);
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    // Written before the resting visemes were listed: those in no key rest all the same.
    writeFileAtomically(dir / "older.glb",
                        test::editGlb(reducedFixture(dir / "rpm.glb", AvatarNames::Original),
                                      [](auto& j) { j["extras"]["visemelab"].erase("resting"); }));
    options.reduced = dir / "older.glb";
    EXPECT_EQ(avatarSpeech(dir / "rpm.glb", options).faces.reduced.resting, inMemory.faces.reduced.resting);
    EXPECT_EQ(scanAvatar(loadGltfDocument(dir / "older.glb"), {}).own.resting,
              inMemory.faces.reduced.resting);
    // The avatar itself is not a reduction.
    options.reduced = dir / "rpm.glb";
    test::expectInputError([&] { avatarSpeech(dir / "rpm.glb", options); }, {"rpm.glb", "extras/visemelab"});
}

TEST_F(AvatarSpeechTest, ReducedFileWithMergedNamesDrivesItsKeyTargetsByTheirNames) {
    const auto [inMemory, speech] = reducedTwice(dir, AvatarNames::Merged);
    ASSERT_TRUE(speech.reducedFace);
    const auto& keys = speech.faces.reduced.keys;
    ASSERT_EQ(keys.size(), 4u);
    expectSameReducedFace(speech.faces.reduced, inMemory.faces.reduced);
    // Each key drives the one target of its name on every mesh carrying it.
    ASSERT_EQ(speech.drives.size(), 4u); // head, teeth, two eyes
    for (const MeshDrive& drive : speech.drives) {
        const auto names = meshTargetNames(*speech.animated, drive.mesh);
        std::set<int> driven;
        for (std::size_t t = 0; t < names.size(); ++t) {
            const int key = drive.keyOfTarget[t];
            EXPECT_NE(key, MeshDrive::kZeroWeight) << names[t].name; // merged: one target per key
            if (key < 0) continue;
            EXPECT_EQ(names[t].name, keys[static_cast<std::size_t>(key)].name);
            EXPECT_TRUE(driven.insert(key).second);
        }
        EXPECT_FALSE(driven.empty());
    }
    // The speaking avatar: readable, still VisemeLab's reduction, AA's key target at 1 inside AA.
    const GltfDocument out =
        parseGltfDocument(test::speakingReducedFixtureGlb(dir / "rpm.glb", dir / "reduced_merged.glb",
                                                          runtime::Interpolation::Linear),
                          "anim", {});
    const AvatarScan outScan = scanAvatar(out, {});
    EXPECT_TRUE(outScan.own.recognised);
    EXPECT_EQ(outScan.visemes.size(), 4u);
    const tinygltf::Animation& animation = out.model.animations.back();
    ASSERT_EQ(animation.name, "speech");
    const auto aa =
        std::find_if(speech.faces.reduced.phonemeToKey.begin(), speech.faces.reduced.phonemeToKey.end(),
                     [](const auto& p) { return p.first == "AA"; });
    ASSERT_NE(aa, speech.faces.reduced.phonemeToKey.end());
    ASSERT_GE(aa->second, 0);
    const std::string aaName = keys[static_cast<std::size_t>(aa->second)].name;
    BufferViews views(out);
    AccessorReader reader(out, views);
    int checked = 0;
    for (const auto& channel : animation.channels) {
        const int mesh = out.model.nodes[static_cast<std::size_t>(channel.target_node)].mesh;
        const auto names = meshTargetNames(out, mesh);
        const auto at =
            std::find_if(names.begin(), names.end(), [&](const TargetName& t) { return t.name == aaName; });
        if (at == names.end()) continue;
        const auto& sampler = animation.samplers[static_cast<std::size_t>(channel.sampler)];
        const std::vector<float> times = reader.floats(sampler.input, TINYGLTF_TYPE_SCALAR, "input");
        const std::vector<float> weights = reader.floats(sampler.output, TINYGLTF_TYPE_SCALAR, "output");
        ASSERT_EQ(weights.size(), times.size() * names.size());
        for (std::size_t i = 0; i < times.size(); ++i)
            if (times[i] > 0.2f && times[i] < 0.5f) {
                EXPECT_FLOAT_EQ(weights[i * names.size() + static_cast<std::size_t>(at - names.begin())],
                                1.0f);
                ++checked;
            }
    }
    EXPECT_GT(checked, 0);
}

// A reduced avatar VisemeLab wrote before key table version 2 (core/gltf/KeyTable.h) speaks as the
// same reduction does now, in both name modes.
TEST_F(AvatarSpeechTest, ReducedFileOfKeyTableVersion1GivesTheSameFace) {
    for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
        const auto [inMemory, fromFile] = reducedTwice(dir, names);
        writeFileAtomically(dir / "version1.glb",
                            test::withKeyTableVersion1(reducedFixture(dir / "rpm.glb", names)));
        AvatarSpeechOptions options;
        options.phonemeTable = test::fixturePhonemeTable();
        options.reduced = dir / "version1.glb";
        const AvatarSpeech older = avatarSpeech(dir / "rpm.glb", options);
        ASSERT_TRUE(older.reducedFace);
        expectSameReducedFace(older.faces.reduced, fromFile.faces.reduced);
        for (std::size_t k = 0; k < older.faces.reduced.keys.size(); ++k)
            EXPECT_EQ(older.faces.reduced.keys[k].name, fromFile.faces.reduced.keys[k].name) << k;
        ASSERT_EQ(older.drives.size(), fromFile.drives.size());
        for (std::size_t d = 0; d < older.drives.size(); ++d)
            EXPECT_EQ(older.drives[d].keyOfTarget, fromFile.drives[d].keyOfTarget) << toString(names);
    }
}

TEST_F(AvatarSpeechTest, AReducedFileWithHostileExtrasIsAClearError) {
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    const std::string glb = reducedFixture(dir / "rpm.glb", AvatarNames::Merged);
    const auto expectError = [&](const std::function<void(nlohmann::ordered_json&)>& edit,
                                 const std::vector<std::string>& parts) {
        writeFileAtomically(dir / "hostile.glb", test::editGlb(glb, edit));
        options.reduced = dir / "hostile.glb";
        test::expectInputError([&] { avatarSpeech(dir / "rpm.glb", options); }, parts);
    };
    expectError([](auto& j) { j["extras"]["visemelab"]["keys"][0]["members"] = 3; },
                {"hostile.glb", "/extras/visemelab/keys/0/members"});
    expectError([](auto& j) { j["extras"]["visemelab"]["keys"][0]["members"] = {"nothing"}; },
                {"hostile.glb", "not a reduction of"});
    // A key whose target entries all point nowhere is carried by no target.
    expectError(
        [](auto& j) {
            for (auto& m : j["meshes"])
                if (m.contains("extras") && m["extras"].contains("visemeKeys"))
                    m["extras"]["visemeKeys"][0] = {12345};
        },
        {"hostile.glb", "/extras/visemelab/keys/0", "carried by no target"});
}

TEST_F(AvatarSpeechTest, ReducedInMemoryDrivesItsKeysWhateverTheRootExtrasHold) {
    // Root extras that are not an object: the writer cannot add extras.visemelab, the meshes still
    // carry their key tables, and speech reduced in memory drives them.
    writeFileAtomically(dir / "odd.glb", test::editGlb(test::rpmLikeAvatar(), [](auto& j) {
                            j["extras"] = {1, 2};
                        }));
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    options.reduceTo = 4;
    const AvatarSpeech speech = avatarSpeech(dir / "odd.glb", options);
    EXPECT_FALSE(speech.animated->json["extras"].is_object());
    ASSERT_EQ(speech.drives.size(), 4u);
    for (const MeshDrive& drive : speech.drives) {
        std::set<int> keys(drive.keyOfTarget.begin(), drive.keyOfTarget.end());
        EXPECT_TRUE(keys.count(0) && keys.count(3)) << drive.mesh;
    }
}

TEST_F(AvatarSpeechTest, RhubarbMapSpeaksOnOculusNames) {
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    options.map =
        loadPhonemeMapFile(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "phonemes" / "map_rhubarb.csv");
    const AvatarSpeech speech = avatarSpeech(dir / "rpm.glb", options);
    const ReducedModel& full = speech.faces.full;
    const auto keyOf = [&](const std::string& phoneme) {
        for (const auto& [p, key] : full.phonemeToKey)
            if (p == phoneme) return full.keys[static_cast<std::size_t>(key)].name;
        return std::string("none");
    };
    EXPECT_EQ(keyOf("M"), "viseme_PP");  // Rhubarb A: closed lips
    EXPECT_EQ(keyOf("AA"), "viseme_aa"); // D: wide open
    EXPECT_EQ(keyOf("F"), "viseme_FF");  // G: teeth on lip
    EXPECT_EQ(keyOf("UW"), "viseme_U");  // F: puckered, RPM's spelling of ou
    EXPECT_EQ(keyOf("sil"), "viseme_sil");
    const FaceTrack track(full, test::fixtureUtterance(), {}, "rpm");
    EXPECT_EQ(track.keyCount(), 15u);
}

TEST_F(AvatarSpeechTest, NamesOtherThanOculusNeedAMap) {
    writeFileAtomically(dir / "vroid.vrm", test::vroidLikeAvatar());
    AvatarSpeechOptions options;
    options.phonemeTable = test::fixturePhonemeTable();
    options.targets = "Fcl_MTH_[AIUEO]";
    test::expectInputError([&] { avatarSpeech(dir / "vroid.vrm", options); }, {"vroid.vrm", "--map"});
}

TEST(VisemeMapNames, BundledMapsMatchAnyOculusSpellingAndRhubarbOrMpeg4ByMeaning) {
    const std::vector<std::string> rpm = test::rpmVisemeNames();
    PhonemeVisemeMap oculus;
    oculus.entries = {{"AA", "aa"}, {"IY", "ih"}, {"OW", "oh"}, {"UW", "ou"}, {"M", "PP"}};
    EXPECT_EQ(mapOntoVisemes(oculus, rpm).entries,
              (std::vector<std::pair<std::string, std::string>>{{"AA", "viseme_aa"},
                                                                {"IY", "viseme_I"},
                                                                {"OW", "viseme_O"},
                                                                {"UW", "viseme_U"},
                                                                {"M", "viseme_PP"}}));
    PhonemeVisemeMap rhubarb;
    rhubarb.entries = {{"M", "A"},  {"S", "B"}, {"EH", "C"}, {"AA", "D"}, {"AO", "E"},
                       {"UW", "F"}, {"F", "G"}, {"L", "H"},  {"sil", "X"}};
    const std::vector<std::string> plain = oculusVisemeNames();
    EXPECT_EQ(mapOntoVisemes(rhubarb, plain).entries,
              (std::vector<std::pair<std::string, std::string>>{{"M", "PP"},
                                                                {"S", "SS"},
                                                                {"EH", "E"},
                                                                {"AA", "aa"},
                                                                {"AO", "oh"},
                                                                {"UW", "ou"},
                                                                {"F", "FF"},
                                                                {"L", "nn"},
                                                                {"sil", "sil"}}));
    // On a set named by Rhubarb's shapes the map stays as it is (its "E" is not Oculus's E).
    EXPECT_EQ(mapOntoVisemes(rhubarb, {"A", "B", "C", "D", "E", "F", "G", "H", "X"}).entries,
              rhubarb.entries);
    PhonemeVisemeMap mpeg4;
    mpeg4.entries = {{"P", "p_b_m"}, {"AA", "A"}, {"IY", "I"}, {"sil", "none"}};
    EXPECT_EQ(mapOntoVisemes(mpeg4, rpm).entries,
              (std::vector<std::pair<std::string, std::string>>{
                  {"P", "viseme_PP"}, {"AA", "viseme_aa"}, {"IY", "viseme_I"}, {"sil", "viseme_sil"}}));
    // Names of no convention stay, for the usual "visemes the set lacks" error.
    PhonemeVisemeMap other;
    other.entries = {{"AA", "jawOpen"}};
    EXPECT_EQ(mapOntoVisemes(other, rpm).entries, other.entries);
}

} // namespace vl
