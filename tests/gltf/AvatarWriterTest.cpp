// The same avatar out: reduced viseme targets, everything else kept byte for byte.
#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"
#include "core/reduce/Reduction.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;
using test::FixtureStorage;

std::string writerFixture(FixtureStorage storage) {
    test::AvatarFixtureOptions options;
    options.storage = storage;
    return test::rpmLikeAvatar(options);
}

struct Reduced {
    GltfDocument in, out;
    AvatarScan scanIn, scanOut;
    AvatarReduction reduction;
};

Reduced reduce(const std::string& glb, int m, AvatarNames names, bool normals = true,
               const std::string& pattern = "") {
    Reduced r{parseGltfDocument(glb, "in.glb", {}), {}, {}, {}, {}};
    r.scanIn = scanAvatar(r.in, {pattern});
    ReduceSettings settings;
    settings.target = m;
    AvatarWriteOptions write;
    write.names = names;
    write.targetNormals = normals;
    // Frequencies that differ per viseme, so that the means are weighted.
    FrequencySource frequencies;
    for (std::size_t i = 0; i < r.scanIn.visemes.size(); ++i)
        frequencies.visemeFrequencies.entries.emplace_back(r.scanIn.visemes[i],
                                                           1.0 + static_cast<double>(i % 4));
    r.reduction = reduceAvatar(r.in, r.scanIn, frequencies, settings, write);
    r.out = parseGltfDocument(r.reduction.glb, "out.glb", {});
    r.scanOut = scanAvatar(r.out, {pattern});
    return r;
}

// The decoded bytes of an accessor's elements (stride removed), so storage moves do not matter.
std::string accessorBytes(const GltfDocument& doc, int index) {
    const tinygltf::Accessor& a = doc.model.accessors[static_cast<std::size_t>(index)];
    if (a.bufferView < 0) return "no view";
    BufferViews views(doc);
    const ViewBytes view = views.view(a.bufferView, "test");
    const std::size_t element =
        static_cast<std::size_t>(componentsOf(a.type) * componentBytes(a.componentType));
    const std::size_t stride = view.stride ? view.stride : element;
    std::string out;
    for (std::size_t i = 0; i < a.count; ++i)
        out.append(reinterpret_cast<const char*>(view.data + a.byteOffset + i * stride), element);
    return out;
}

std::vector<float> floats(const GltfDocument& doc, int accessor, std::size_t count) {
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    return reader.floats(accessor, -1, "test", count);
}

const Json& meshJson(const GltfDocument& doc, const std::string& name) {
    for (const Json& m : doc.json["meshes"])
        if (m["name"] == name) return m;
    throw std::runtime_error("no mesh " + name);
}

// Key g's name as the output records it (its target's name with merged names; key table version 2
// leaves out a name that is the members joined with '+').
std::string writtenKeyName(const Reduced& r, std::size_t g) {
    const Json& key = r.out.json["extras"]["visemelab"]["keys"][g];
    return key.contains("name") ? key["name"].get<std::string>()
                                : mergedKeyName(key["members"].get<std::vector<std::string>>());
}

// Everything but viseme targets, compared accessor data by accessor data.
void expectUntouchedPartsIdentical(const Reduced& r) {
    const Json& a = r.in.json;
    const Json& b = r.out.json;
    for (const char* array : {"nodes", "materials", "textures", "samplers", "scenes", "cameras"})
        EXPECT_EQ(a.value(array, Json::array()), b.value(array, Json::array())) << array;
    EXPECT_EQ(a.value("extensionsRequired", Json::array()), b.value("extensionsRequired", Json::array()));
    EXPECT_EQ(a.value("extensions", Json::object()), b.value("extensions", Json::object()));
    EXPECT_EQ(a["asset"], b["asset"]);
    // Skins: joints as they were, inverse bind matrices byte for byte.
    ASSERT_EQ(a.value("skins", Json::array()).size(), b.value("skins", Json::array()).size());
    for (std::size_t s = 0; s < a.value("skins", Json::array()).size(); ++s) {
        EXPECT_EQ(a["skins"][s]["joints"], b["skins"][s]["joints"]);
        EXPECT_EQ(accessorBytes(r.in, a["skins"][s]["inverseBindMatrices"].get<int>()),
                  accessorBytes(r.out, b["skins"][s]["inverseBindMatrices"].get<int>()));
    }
    // Images byte for byte.
    ASSERT_EQ(a.value("images", Json::array()).size(), b.value("images", Json::array()).size());
    for (std::size_t i = 0; i < a.value("images", Json::array()).size(); ++i) {
        BufferViews va(r.in), vb(r.out);
        const ViewBytes x = va.view(a["images"][i]["bufferView"].get<int>(), "image");
        const ViewBytes y = vb.view(b["images"][i]["bufferView"].get<int>(), "image");
        EXPECT_EQ(std::string(reinterpret_cast<const char*>(x.data), x.size),
                  std::string(reinterpret_cast<const char*>(y.data), y.size));
    }
    // Meshes: every attribute, index list and non-viseme target byte for byte; same materials.
    ASSERT_EQ(a["meshes"].size(), b["meshes"].size());
    for (std::size_t m = 0; m < a["meshes"].size(); ++m) {
        const AvatarMesh& scanned = r.scanIn.meshes[m];
        EXPECT_EQ(a["meshes"][m]["name"], b["meshes"][m]["name"]);
        for (std::size_t p = 0; p < a["meshes"][m]["primitives"].size(); ++p) {
            const Json& pa = a["meshes"][m]["primitives"][p];
            const Json& pb = b["meshes"][m]["primitives"][p];
            EXPECT_EQ(pa.value("material", -1), pb.value("material", -1));
            EXPECT_EQ(pa.value("mode", 4), pb.value("mode", 4));
            EXPECT_EQ(pa.value("extensions", Json::object()).dump().size() > 2,
                      pb.value("extensions", Json::object()).dump().size() > 2);
            for (const auto& [name, index] : pa["attributes"].items())
                EXPECT_EQ(accessorBytes(r.in, index.get<int>()),
                          accessorBytes(r.out, pb["attributes"][name].get<int>()))
                    << name;
            if (pa.contains("indices")) {
                EXPECT_EQ(accessorBytes(r.in, pa["indices"].get<int>()),
                          accessorBytes(r.out, pb["indices"].get<int>()));
            }
            for (std::size_t k = 0; k < scanned.targets.size(); ++k) {
                if (scanned.targets[k].viseme >= 0) continue;
                const std::string& name = scanned.targets[k].name;
                const AvatarMesh& after = r.scanOut.meshes[m];
                const auto it = std::find_if(after.targets.begin(), after.targets.end(),
                                             [&](const AvatarTarget& t) { return t.name == name; });
                ASSERT_NE(it, after.targets.end()) << name;
                const Json& tb = pb["targets"][static_cast<std::size_t>(it - after.targets.begin())];
                for (const auto& [attr, index] : pa["targets"][k].items())
                    EXPECT_EQ(accessorBytes(r.in, index.get<int>()),
                              accessorBytes(r.out, tb[attr].get<int>()))
                        << name;
            }
        }
    }
    // Animation inputs byte for byte.
    for (std::size_t n = 0; n < a.value("animations", Json::array()).size(); ++n)
        for (std::size_t s = 0; s < a["animations"][n]["samplers"].size(); ++s)
            EXPECT_EQ(accessorBytes(r.in, a["animations"][n]["samplers"][s]["input"].get<int>()),
                      accessorBytes(r.out, b["animations"][n]["samplers"][s]["input"].get<int>()));
}

// How far a stored key may be from the float mean of its members: the quantisation step of the
// input's storage. Quantised: normalised shorts, 1/32767 (half of it, rounded). Meshopt: the fixtures'
// exponential filter, 15 mantissa bits and the vector's exponent, where meshoptimizer 0.18 counts a
// zero component as exponent 0 (frexp): a step of 2^(e - 14).
double storageStep(FixtureStorage storage, const std::vector<float>& values, std::size_t c) {
    if (storage == FixtureStorage::Quantised) return 0.5 / 32767.0 + 1e-7;
    if (storage != FixtureStorage::Meshopt) return 1e-7;
    int exponent = -1000;
    for (std::size_t k = c / 3 * 3; k < c / 3 * 3 + 3; ++k) {
        int e = 0;
        std::frexp(values[k], &e);
        exponent = std::max(exponent, e);
    }
    return std::ldexp(1.0, exponent - 14) + 1e-9;
}

// Key g's POSITION displacement on a primitive equals the frequency-weighted mean of its members'
// (members the mesh lacks count as zero), computed here from the input file directly, within the
// input's quantisation step.
void expectKeysAreWeightedMeans(const Reduced& r, AvatarNames names,
                                FixtureStorage storage = FixtureStorage::Plain) {
    const auto groupOf = r.reduction.outcome.result.groupOf();
    const auto& f = r.reduction.outcome.frequencies;
    for (const AvatarMesh& mesh : r.scanIn.meshes) {
        if (!mesh.carriesVisemes) continue;
        const Json& pin = r.in.json["meshes"][static_cast<std::size_t>(mesh.index)]["primitives"][0];
        const Json& pout = r.out.json["meshes"][static_cast<std::size_t>(mesh.index)]["primitives"][0];
        const std::size_t vertices = mesh.primitives[0].vertices;
        const auto& outNames =
            r.out.json["meshes"][static_cast<std::size_t>(mesh.index)]["extras"]["targetNames"];
        for (std::size_t g = 0; g < r.reduction.outcome.model.keys.size(); ++g) {
            std::vector<double> expected(3 * vertices, 0.0);
            double total = 0;
            for (std::size_t i = 0; i < groupOf.size(); ++i)
                if (groupOf[i] == static_cast<int>(g)) total += f[i];
            int someTarget = -1;
            for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
                const int i = mesh.targets[k].viseme;
                if (i < 0 || groupOf[static_cast<std::size_t>(i)] != static_cast<int>(g)) continue;
                const auto d = floats(r.in, pin["targets"][k]["POSITION"].get<int>(), vertices);
                for (std::size_t c = 0; c < expected.size(); ++c)
                    expected[c] += f[static_cast<std::size_t>(i)] / total * d[c];
                if (someTarget < 0) someTarget = static_cast<int>(k);
            }
            if (someTarget < 0) continue;
            std::size_t at = static_cast<std::size_t>(someTarget);
            if (names == AvatarNames::Merged) {
                const auto it = std::find(outNames.begin(), outNames.end(), writtenKeyName(r, g));
                ASSERT_NE(it, outNames.end()) << writtenKeyName(r, g);
                at = static_cast<std::size_t>(it - outNames.begin());
            }
            const auto got = floats(r.out, pout["targets"][at]["POSITION"].get<int>(), vertices);
            std::vector<float> rounded(expected.begin(), expected.end());
            for (std::size_t c = 0; c < expected.size(); ++c)
                ASSERT_NEAR(got[c], expected[c], storageStep(storage, rounded, c))
                    << mesh.name << " key " << g << " component " << c;
        }
    }
}

TEST(AvatarWriter, OriginalNamesKeepEveryViseme_MembersShareOneAccessor_RestByteIdentical) {
    const Reduced r = reduce(writerFixture(FixtureStorage::Plain), 6, AvatarNames::Original);
    ASSERT_EQ(r.reduction.outcome.model.keys.size(), 6u);
    EXPECT_EQ(r.scanOut.visemes, r.scanIn.visemes);
    expectUntouchedPartsIdentical(r);
    expectKeysAreWeightedMeans(r, AvatarNames::Original);
    const auto groupOf = r.reduction.outcome.result.groupOf();
    const Json& head = meshJson(r.out, "Wolf3D_Head");
    EXPECT_EQ(head["extras"]["targetNames"], meshJson(r.in, "Wolf3D_Head")["extras"]["targetNames"]);
    EXPECT_EQ(head["weights"], meshJson(r.in, "Wolf3D_Head")["weights"]);
    const Json& targets = head["primitives"][0]["targets"];
    for (std::size_t i = 0; i < 15; ++i)
        for (std::size_t j = 0; j < 15; ++j) // viseme i is head target 2 + i
            EXPECT_EQ(targets[2 + i]["POSITION"] == targets[2 + j]["POSITION"], groupOf[i] == groupOf[j])
                << i << " " << j;
    // Fewer accessors, less data.
    EXPECT_LT(r.reduction.summary.accessorsAfter, r.reduction.summary.accessorsBefore);
    EXPECT_LT(r.reduction.summary.binaryBytesAfter, r.reduction.summary.binaryBytesBefore);
    // The phoneme map and the keys, per mesh and for the whole file.
    const Json& root = r.out.json["extras"]["visemelab"];
    EXPECT_EQ(root["version"], 2);
    EXPECT_EQ(root["names"], "original");
    EXPECT_EQ(root["keys"].size(), 6u);
    EXPECT_EQ(head["extras"]["visemeKeys"].size(), 6u); // per key, its targets on the head
    // viseme frequencies: names map to themselves; viseme_aa's key is driven by its first target
    const auto aaKey = root["phonemeToKey"]["viseme_aa"].get<std::size_t>();
    EXPECT_EQ(head["extras"]["visemeKeys"][aaKey][0], 12);
    // Nothing the root table and targetNames give is repeated on the mesh.
    EXPECT_FALSE(head["extras"].contains("phonemeToTarget"));
    EXPECT_FALSE(head["extras"].contains("targetAliases"));
    EXPECT_EQ(meshJson(r.out, "Wolf3D_Head")["extras"]["fixture"], "head"); // other extras kept
    EXPECT_EQ(r.out.json["asset"]["extras"]["fixture"], "rpm-like");
}

TEST(AvatarWriter, MergedNamesGiveOneTargetPerKeyAndRemapWeightsAnimationsAndNames) {
    const Reduced r = reduce(writerFixture(FixtureStorage::Plain), 5, AvatarNames::Merged);
    expectUntouchedPartsIdentical(r);
    expectKeysAreWeightedMeans(r, AvatarNames::Merged);
    const Json& head = meshJson(r.out, "Wolf3D_Head");
    const auto names = head["extras"]["targetNames"].get<std::vector<std::string>>();
    ASSERT_EQ(names.size(), 6u + 5u); // 6 ARKit-like targets kept + 5 keys
    EXPECT_EQ(names[0], "browInnerUp");
    EXPECT_EQ(names[1], "jawOpen");
    EXPECT_EQ(names.back(), "eyeBlinkRight");
    for (std::size_t g = 0; g < r.reduction.outcome.model.keys.size(); ++g)
        EXPECT_NE(std::find(names.begin(), names.end(), writtenKeyName(r, g)), names.end())
            << writtenKeyName(r, g);
    EXPECT_EQ(head["primitives"][0]["targets"].size(), names.size());
    EXPECT_EQ(head["weights"].size(), names.size());
    // The head's weights animation: 3 keyframes x 11 targets, jawOpen's 0.8 kept, viseme_aa's 0.8 on its key.
    const Json& animation = r.out.json["animations"][0];
    const int output = animation["samplers"][1]["output"].get<int>();
    const auto weights = floats(r.out, output, 3 * names.size());
    EXPECT_FLOAT_EQ(weights[names.size() + 1], 0.8f);
    const std::string aaKey =
        writtenKeyName(r, static_cast<std::size_t>(r.reduction.outcome.result.groupOf()[10]));
    const auto aaAt = static_cast<std::size_t>(std::find(names.begin(), names.end(), aaKey) - names.begin());
    EXPECT_FLOAT_EQ(weights[names.size() + aaAt], 0.8f);
    // The output reads back as its five keys (VisemeLab recognises its own output).
    EXPECT_TRUE(r.scanOut.own.recognised);
    EXPECT_EQ(r.scanOut.visemes.size(), 5u);
}

TEST(AvatarWriter, ByteWeightsAnimationsStayBytesOnTheSameGrid) {
    test::AvatarFixtureOptions options;
    options.byteWeights = true; // gltfpack's layout: normalised unsigned bytes
    const std::string input = test::rpmLikeAvatar(options);
    const Reduced bytes = reduce(input, 5, AvatarNames::Merged);
    const Reduced floatsIn = reduce(writerFixture(FixtureStorage::Plain), 5, AvatarNames::Merged);
    const auto outputOf = [](const Reduced& r) {
        return r.out.json["animations"][0]["samplers"][1]["output"].get<int>();
    };
    const Json& accessor = bytes.out.json["accessors"][static_cast<std::size_t>(outputOf(bytes))];
    EXPECT_EQ(accessor["componentType"], 5121);
    EXPECT_TRUE(accessor.value("normalized", false));
    // The same weights as the float animation gives, to the byte grid (0.8 -> 204/255).
    const std::size_t count = accessor["count"].get<std::size_t>();
    const auto got = floats(bytes.out, outputOf(bytes), count);
    const auto want = floats(floatsIn.out, outputOf(floatsIn), count);
    for (std::size_t i = 0; i < count; ++i) EXPECT_NEAR(got[i], want[i], 0.5 / 255) << i;
}

TEST(AvatarWriter, KeysOfOneMemberReuseTheirAccessorsUnchanged) {
    const Reduced r = reduce(writerFixture(FixtureStorage::Sparse), 15, AvatarNames::Original);
    for (const AvatarMesh& mesh : r.scanIn.meshes) {
        if (!mesh.carriesVisemes) continue;
        const Json& a = r.in.json["meshes"][static_cast<std::size_t>(mesh.index)]["primitives"][0]["targets"];
        const Json& b =
            r.out.json["meshes"][static_cast<std::size_t>(mesh.index)]["primitives"][0]["targets"];
        for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
            const auto& ia = r.in.model.accessors[a[k]["POSITION"].get<std::size_t>()];
            const auto& ib = r.out.model.accessors[b[k]["POSITION"].get<std::size_t>()];
            EXPECT_EQ(ia.sparse.isSparse, ib.sparse.isSparse);
            EXPECT_EQ(floats(r.in, a[k]["POSITION"].get<int>(), mesh.primitives[0].vertices),
                      floats(r.out, b[k]["POSITION"].get<int>(), mesh.primitives[0].vertices));
        }
    }
    EXPECT_EQ(r.reduction.summary.accessorsAfter, r.reduction.summary.accessorsBefore);
}

TEST(AvatarWriter, WithoutTargetNormalsTheKeysCarryOnlyPositions) {
    const Reduced r = reduce(writerFixture(FixtureStorage::Plain), 4, AvatarNames::Original, false);
    const Json& head = meshJson(r.out, "Wolf3D_Head")["primitives"][0]["targets"];
    for (std::size_t k = 0; k < head.size(); ++k) {
        const bool viseme = k >= 2 && k < 17;
        EXPECT_EQ(head[k].contains("NORMAL"), !viseme) << k;
        EXPECT_TRUE(head[k].contains("POSITION"));
    }
    const Reduced withNormals = reduce(writerFixture(FixtureStorage::Plain), 4, AvatarNames::Original, true);
    EXPECT_TRUE(meshJson(withNormals.out, "Wolf3D_Head")["primitives"][0]["targets"][5].contains("NORMAL"));
    EXPECT_LT(r.reduction.glb.size(), withNormals.reduction.glb.size());
}

TEST(AvatarWriter, MaxTargetsRefusesClearly) {
    const GltfDocument in = parseGltfDocument(writerFixture(FixtureStorage::Plain), "in.glb", {});
    const AvatarScan scan = scanAvatar(in, {});
    ReduceSettings settings;
    settings.target = 4;
    AvatarWriteOptions write;
    write.maxTargets = 8;
    test::expectInputError([&] { reduceAvatar(in, scan, uniformFrequencies(scan), settings, write); },
                           {"--max-targets 8", "Wolf3D_Head", "21 morph targets", "--names merged"});
    write.names = AvatarNames::Merged;
    test::expectInputError([&] { reduceAvatar(in, scan, uniformFrequencies(scan), settings, write); },
                           {"--max-targets 8", "Wolf3D_Head", "10 morph targets", "6 kept + 4 reduced keys"});
    write.maxTargets = 10;
    EXPECT_NO_THROW(reduceAvatar(in, scan, uniformFrequencies(scan), settings, write));
    // Resting visemes keep zero targets (their names still resolve): counted and said.
    settings.rest = RestChoice::Free;
    settings.restViseme = "viseme_sil";
    test::expectInputError(
        [&] { reduceAvatar(in, scan, uniformFrequencies(scan), settings, write); },
        {"--max-targets 10", "14 morph targets", "6 kept + 4 reduced keys + 4 resting visemes"});
}

TEST(AvatarWriter, CompressedInputsKeepTheirCompressedPartsAndReadBack) {
    for (FixtureStorage storage :
         {FixtureStorage::Meshopt, FixtureStorage::Draco, FixtureStorage::Quantised}) {
        for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
            const Reduced r = reduce(writerFixture(storage), 6, names);
            expectUntouchedPartsIdentical(r);
            expectKeysAreWeightedMeans(r, names, storage);
            const auto used = r.out.model.extensionsRequired;
            if (storage == FixtureStorage::Meshopt) {
                EXPECT_NE(std::find(used.begin(), used.end(), "EXT_meshopt_compression"), used.end());
            }
            if (storage == FixtureStorage::Draco) {
                EXPECT_NE(std::find(used.begin(), used.end(), "KHR_draco_mesh_compression"), used.end());
            }
            EXPECT_FALSE(r.reduction.summary.notes.empty());
            // Measured again, the output's neutral geometry is the input's.
            EXPECT_EQ(r.scanOut.set.neutral.positions, r.scanIn.set.neutral.positions);
        }
    }
}

TEST(AvatarWriter, VrmExpressionBindsFollowMergedTargets) {
    for (bool vrm1 : {false, true}) {
        const Reduced r =
            reduce(test::vroidLikeAvatar(vrm1), 3, AvatarNames::Merged, true, "Fcl_MTH_[AIUEO]");
        const auto names =
            r.out.json["meshes"][0]["primitives"][0]["extras"]["targetNames"].get<std::vector<std::string>>();
        ASSERT_EQ(names.size(), 5u + 3u); // Neutral, Angry, Joy, EYE_Close, MTH_Close kept; 3 keys
        const auto groupOf = r.reduction.outcome.result.groupOf();
        const auto keyTarget = [&](std::size_t viseme) {
            const std::string key = writtenKeyName(r, static_cast<std::size_t>(groupOf[viseme]));
            return static_cast<int>(std::find(names.begin(), names.end(), key) - names.begin());
        };
        const int joy =
            static_cast<int>(std::find(names.begin(), names.end(), "Fcl_ALL_Joy") - names.begin());
        if (!vrm1) {
            const Json& groups = r.out.json["extensions"]["VRM"]["blendShapeMaster"]["blendShapeGroups"];
            for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(groups[v]["binds"][0]["index"], keyTarget(v)) << v;
            EXPECT_EQ(groups[5]["binds"][0]["index"], joy);
        } else {
            const Json& preset = r.out.json["extensions"]["VRMC_vrm"]["expressions"]["preset"];
            EXPECT_EQ(preset["aa"]["morphTargetBinds"][0]["index"], keyTarget(0));
            EXPECT_EQ(preset["oh"]["morphTargetBinds"][0]["index"], keyTarget(4));
            EXPECT_EQ(preset["happy"]["morphTargetBinds"][0]["index"], joy);
        }
        // Both primitives of the face carry the same targets.
        EXPECT_EQ(r.out.json["meshes"][0]["primitives"][1]["targets"].size(), names.size());
    }
}

} // namespace
} // namespace vl
