#include "core/common/Error.h"
#include "core/export/GltfExport.h"
#include "core/import/GltfImport.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <filesystem>

namespace vl {
namespace {

void expectSameModel(const ReducedModel& got, const ReducedModel& expected, double tolerance) {
    ASSERT_EQ(got.neutral.positions.size(), expected.neutral.positions.size());
    EXPECT_EQ(got.neutral.triangles, expected.neutral.triangles);
    ASSERT_EQ(got.neutral.uvs.size(), expected.neutral.uvs.size());
    for (std::size_t i = 0; i < expected.neutral.positions.size(); ++i) {
        EXPECT_LT((got.neutral.positions[i] - expected.neutral.positions[i]).norm(), tolerance);
        if (!expected.neutral.uvs.empty()) {
            EXPECT_LT((got.neutral.uvs[i] - expected.neutral.uvs[i]).norm(), tolerance);
        }
    }
    ASSERT_EQ(got.keys.size(), expected.keys.size());
    for (std::size_t k = 0; k < expected.keys.size(); ++k) {
        EXPECT_EQ(got.keys[k].name, expected.keys[k].name);
        EXPECT_EQ(got.keys[k].members, expected.keys[k].members);
        EXPECT_DOUBLE_EQ(got.keys[k].frequency, expected.keys[k].frequency);
        for (std::size_t i = 0; i < expected.keys[k].positions.size(); ++i)
            ASSERT_LT((got.keys[k].positions[i] - expected.keys[k].positions[i]).norm(), tolerance);
    }
    auto sorted = [](auto v) {
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_EQ(sorted(got.phonemeToKey), sorted(expected.phonemeToKey));
    EXPECT_EQ(sorted(got.phonemeFrequencies), sorted(expected.phonemeFrequencies));
}

TEST(Gltf, GlbRoundTripThroughOwnReader) {
    const ReducedModel model = test::randomModel(9, 7, 4, true, 51);
    const std::string glb = formatGlb(model);
    ASSERT_GE(glb.size(), 12u);
    EXPECT_EQ(glb.substr(0, 4), "glTF");
    expectSameModel(parseGltf(glb, "mem.glb", true), model, 1e-6);
}

TEST(Gltf, WrittenFileReadsBackAndHasValidatorRequirements) {
    const ReducedModel model = test::randomModel(5, 4, 3, true, 52);
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_gltf_test";
    std::filesystem::create_directories(dir);
    writeGlb(dir / "face.glb", model);
    expectSameModel(readGltf(dir / "face.glb"), model, 1e-6);

    tinygltf::TinyGLTF loader;
    tinygltf::Model gltf;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&gltf, &error, &warning, (dir / "face.glb").string())) << error;
    ASSERT_EQ(gltf.meshes.size(), 1u);
    const tinygltf::Primitive& p = gltf.meshes[0].primitives[0];
    ASSERT_EQ(p.targets.size(), 3u);
    EXPECT_EQ(gltf.meshes[0].weights.size(), 3u);
    EXPECT_FALSE(gltf.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))].minValues.empty());
    for (const auto& target : p.targets) {
        const auto& a = gltf.accessors[static_cast<std::size_t>(target.at("POSITION"))];
        EXPECT_EQ(a.minValues.size(), 3u);
        EXPECT_EQ(a.maxValues.size(), 3u);
        EXPECT_TRUE(target.count("NORMAL"));
    }
    EXPECT_EQ(gltf.accessors[static_cast<std::size_t>(p.indices)].componentType,
              TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    for (const auto& view : gltf.bufferViews) EXPECT_EQ(view.byteOffset % 4, 0u);
    const tinygltf::Value& names = gltf.meshes[0].extras.Get("targetNames");
    ASSERT_EQ(names.ArrayLen(), 3u);
    EXPECT_EQ(names.Get(1).Get<std::string>(), model.keys[1].name);
    // glTF's v runs downwards: the stored v is 1 - v.
    const auto& uvAccessor = gltf.accessors[static_cast<std::size_t>(p.attributes.at("TEXCOORD_0"))];
    const auto& uvView = gltf.bufferViews[static_cast<std::size_t>(uvAccessor.bufferView)];
    float storedV;
    std::memcpy(&storedV, gltf.buffers[0].data.data() + uvView.byteOffset + 4, 4);
    EXPECT_FLOAT_EQ(storedV, static_cast<float>(1.0 - model.neutral.uvs[0][1]));
    std::filesystem::remove_all(dir);
}

TEST(Gltf, TruncatedOrGarbageFilesAreInputErrors) {
    const std::string glb = formatGlb(test::randomModel(4, 4, 2, false, 53));
    for (std::size_t size : {0ul, 11ul, 20ul, glb.size() / 2, glb.size() - 1})
        EXPECT_THROW(parseGltf(std::string_view(glb).substr(0, size), "cut.glb", true), InputError) << size;
    EXPECT_THROW(parseGltf("{\"asset\":{\"version\":\"2.0\"}}", "empty.gltf", false), InputError);
    try {
        parseGltf("not json", "junk.gltf", false);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("junk.gltf"), std::string::npos);
    }
}

std::string toBase64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    unsigned value = 0;
    int bits = -6;
    for (unsigned char c : bytes) {
        value = (value << 8) + c;
        for (bits += 8; bits >= 0; bits -= 6) out.push_back(alphabet[(value >> bits) & 63]);
    }
    if (bits > -6) out.push_back(alphabet[((value << 8) >> (bits + 8)) & 63]);
    while (out.size() % 4) out.push_back('=');
    return out;
}

// A hand-written glTF as other tools write it: JSON with a data URI, a sparse morph target, no
// VisemeLab extras, no indices.
TEST(Gltf, ReadsSparseTargetsAndUnnamedTargets) {
    // Buffer: 3 positions (36 bytes), sparse index uint16 [1] + 2 pad (4 bytes), sparse value (12 bytes).
    std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string buffer(reinterpret_cast<const char*>(positions.data()), 36);
    const std::uint16_t index = 1;
    buffer.append(reinterpret_cast<const char*>(&index), 2);
    buffer.append(2, '\0');
    const float delta[3] = {0, 0.5f, 0.25f};
    buffer.append(reinterpret_cast<const char*>(delta), 12);
    const std::string base64 = toBase64(buffer);
    const std::string json = R"({"asset":{"version":"2.0"},
      "buffers":[{"byteLength":52,"uri":"data:application/octet-stream;base64,)" +
                             base64 + R"("}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":4},
                     {"buffer":0,"byteOffset":40,"byteLength":12}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0.5,0.25],
                    "sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":2}}}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"targets":[{"POSITION":1}]}]}]})";
    const ReducedModel model = parseGltf(json, "hand.gltf", false);
    ASSERT_EQ(model.neutral.positions.size(), 3u);
    ASSERT_EQ(model.neutral.triangles.size(), 1u);
    ASSERT_EQ(model.keys.size(), 1u);
    EXPECT_EQ(model.keys[0].name, "target0");
    EXPECT_EQ(model.keys[0].positions[0], Vec3(0, 0, 0));
    EXPECT_EQ(model.keys[0].positions[1], Vec3(1, 0.5, 0.25));
    EXPECT_EQ(model.keys[0].positions[2], Vec3(0, 1, 0));
    EXPECT_TRUE(model.phonemeToKey.empty());
}

} // namespace
} // namespace vl
