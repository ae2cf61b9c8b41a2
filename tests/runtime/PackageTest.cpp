#include "core/runtime/Package.h"
#include "FuzzTarget.h"

#include "core/export/RuntimePackageWriter.h"
#include "core/runtime/Crc32.h"
#include "core/runtime/PackageFormat.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

namespace vl {
namespace {

using runtime::Package;

const std::uint8_t* bytesOf(const std::string& s) {
    return reinterpret_cast<const std::uint8_t*>(s.data());
}

Package loadOrFail(const std::string& bytes) {
    Package package;
    std::string error;
    EXPECT_TRUE(package.load(bytesOf(bytes), bytes.size(), error)) << error;
    return package;
}

double maxError(const std::vector<float>& decoded, const std::vector<Vec3>& expected) {
    double worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
        for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(decoded[3 * i + a] - expected[i][a]));
    return worst;
}

TEST(RuntimePackage, FloatRoundTripKeepsEverything) {
    const ReducedModel model = test::randomModel(7, 5, 3, true, 1);
    const Package package = loadOrFail(encodeRuntimePackage(model));
    ASSERT_EQ(package.vertexCount(), model.neutral.positions.size());
    ASSERT_EQ(package.triangleCount(), model.neutral.triangles.size());
    ASSERT_EQ(package.keyCount(), 3u);
    ASSERT_EQ(package.phonemeCount(), model.phonemeToKey.size());
    EXPECT_FALSE(package.quantised());
    EXPECT_FALSE(package.indices32());
    for (std::size_t t = 0; t < model.neutral.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(package.index(3 * t + c), model.neutral.triangles[t][c]);
    ASSERT_TRUE(package.hasUVs());
    for (std::size_t i = 0; i < model.neutral.uvs.size(); ++i) {
        EXPECT_EQ(package.uvs()[2 * i], static_cast<float>(model.neutral.uvs[i][0]));
        EXPECT_EQ(package.uvs()[2 * i + 1], static_cast<float>(model.neutral.uvs[i][1]));
    }
    std::vector<float> positions(3 * package.vertexCount());
    package.neutralPositions(positions.data());
    for (std::size_t i = 0; i < model.neutral.positions.size(); ++i)
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(positions[3 * i + a], static_cast<float>(model.neutral.positions[i][a]));
    for (std::uint32_t k = 0; k < package.keyCount(); ++k) {
        EXPECT_EQ(package.keyName(k), model.keys[k].name);
        package.keyPositions(k, positions.data());
        EXPECT_LT(maxError(positions, model.keys[k].positions), 1e-6);
    }
    for (std::uint32_t p = 0; p < package.phonemeCount(); ++p) {
        EXPECT_EQ(package.phonemeName(p), model.phonemeToKey[p].first);
        EXPECT_EQ(package.keyOfPhoneme(p), static_cast<std::uint32_t>(model.phonemeToKey[p].second));
    }
    EXPECT_EQ(package.findPhoneme("p3"), 3u);
    EXPECT_EQ(package.findPhoneme("nope"), runtime::kNotFound);
    EXPECT_EQ(package.findKey(model.keys[2].name), 2u);
    // By a key's name, an original viseme merged into it, or a phoneme (model keys: key0, key1+m1, ...).
    EXPECT_EQ(package.findKey("key1+m1"), 1u);
    EXPECT_EQ(package.findKey("m1"), 1u);
    EXPECT_EQ(package.findKey("key1"), 1u);
    EXPECT_EQ(package.findKey("key2"), 2u);
    EXPECT_EQ(package.findKey("p5"), 2u); // phoneme p5 plays key 2
    EXPECT_EQ(package.findKey("p0"), 0u);
    EXPECT_EQ(package.findKey("m"), runtime::kNotFound);
    EXPECT_EQ(package.findKey(""), runtime::kNotFound);
    EXPECT_EQ(package.findKey("key1+"), runtime::kNotFound);
}

TEST(RuntimePackage, QuantisedErrorIsWithinHalfAStep) {
    const ReducedModel model = test::randomModel(30, 30, 4, false, 2, 0.2);
    const std::string floatBytes = encodeRuntimePackage(model);
    const std::string quantisedBytes = encodeRuntimePackage(model, {.quantise = true});
    EXPECT_LT(quantisedBytes.size(), floatBytes.size() * 0.6);
    const Package package = loadOrFail(quantisedBytes);
    EXPECT_TRUE(package.quantised());
    EXPECT_FALSE(package.hasUVs());
    // The grid spans [-1,1] and displacements [-0.2,0.2]: half a step is range / 131070.
    const double neutralStep = 2.0 / 131070, displacementStep = 0.4 / 131070;
    std::vector<float> positions(3 * package.vertexCount());
    package.neutralPositions(positions.data());
    EXPECT_LT(maxError(positions, model.neutral.positions), neutralStep * 1.01 + 1e-6);
    for (std::uint32_t k = 0; k < package.keyCount(); ++k) {
        package.keyPositions(k, positions.data());
        EXPECT_LT(maxError(positions, model.keys[k].positions),
                  (neutralStep + displacementStep) * 1.01 + 1e-6);
    }
}

TEST(RuntimePackage, LargeMeshesUse32BitIndices) {
    const ReducedModel model = test::randomModel(300, 220, 1, false, 3); // 66,000 vertices
    const Package package = loadOrFail(encodeRuntimePackage(model));
    EXPECT_TRUE(package.indices32());
    const std::size_t last = 3 * model.neutral.triangles.size() - 1;
    EXPECT_EQ(package.index(last), model.neutral.triangles.back()[2]);
    EXPECT_GE(package.index(last), 65536u);
}

TEST(RuntimePackage, BlendMatchesSlowReference) {
    for (bool quantise : {false, true}) {
        const ReducedModel model = test::randomModel(5, 7, 5, true, 4); // 105 floats: blocks of 12 and a rest
        const Package package = loadOrFail(encodeRuntimePackage(model, {.quantise = quantise}));
        const std::size_t n = 3 * package.vertexCount();
        std::vector<std::vector<float>> keys(package.keyCount(), std::vector<float>(n));
        std::vector<float> neutral(n), blended(n);
        package.neutralPositions(neutral.data());
        for (std::uint32_t k = 0; k < package.keyCount(); ++k) package.keyPositions(k, keys[k].data());
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> w(-0.5f, 1.5f);
        for (int trial = 0; trial < 20; ++trial) {
            runtime::KeyWeight weights[4];
            for (auto& kw : weights)
                kw = {rng() % 6 == 0 ? runtime::kRestKey
                                     : static_cast<std::uint32_t>(rng() % package.keyCount()),
                      w(rng)};
            package.blend(weights, 4, blended.data());
            for (std::size_t i = 0; i < n; ++i) {
                double expected = neutral[i];
                for (const auto& kw : weights)
                    if (kw.key != runtime::kRestKey)
                        expected += kw.weight * (double(keys[kw.key][i]) - neutral[i]);
                ASSERT_NEAR(blended[i], expected, 1e-5) << "trial " << trial << " component " << i;
            }
        }
    }
}

TEST(RuntimePackage, RejectsEveryTruncation) {
    const std::string bytes = encodeRuntimePackage(test::randomModel(4, 3, 2, true, 6));
    for (std::size_t size = 0; size < bytes.size(); ++size) {
        Package package;
        std::string error;
        ASSERT_FALSE(package.load(bytesOf(bytes), size, error)) << size;
        EXPECT_FALSE(error.empty());
        EXPECT_TRUE(package.empty());
    }
    Package package;
    std::string error;
    EXPECT_FALSE(package.load(bytesOf(bytes), 50, error));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
    EXPECT_FALSE(package.load(bytesOf(bytes), bytes.size() - 4, error));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
}

TEST(RuntimePackage, RejectsEverySingleByteChange) {
    for (bool quantise : {false, true}) {
        const std::string bytes =
            encodeRuntimePackage(test::randomModel(4, 3, 2, true, 7), {.quantise = quantise});
        for (std::size_t at = 0; at < bytes.size(); ++at)
            for (std::uint8_t mask : {0x01, 0x10, 0x80, 0xFF}) {
                std::string corrupted = bytes;
                corrupted[at] = static_cast<char>(corrupted[at] ^ mask);
                Package package;
                std::string error;
                ASSERT_FALSE(package.load(bytesOf(corrupted), corrupted.size(), error))
                    << "byte " << at << " mask " << int(mask);
            }
    }
}

std::string withFixedCrc(std::string bytes) {
    test::repairPayloadCrc(bytes);
    return bytes;
}

std::string loadError(const std::string& bytes) {
    Package package;
    std::string error;
    EXPECT_FALSE(package.load(bytesOf(bytes), bytes.size(), error));
    return error;
}

TEST(RuntimePackage, StructuralErrorsAreNamed) {
    const ReducedModel model = test::randomModel(4, 3, 2, false, 8);
    const std::string good = encodeRuntimePackage(model);
    std::uint32_t indicesOffset;
    std::memcpy(&indicesOffset, good.data() + runtime::header::kSections + 8 * runtime::kSectionIndices, 4);
    std::string badIndex = good;
    badIndex[indicesOffset] = static_cast<char>(200); // vertex 200 of 12
    EXPECT_NE(loadError(withFixedCrc(badIndex)).find("out of range"), std::string::npos);

    std::uint32_t mapOffset;
    std::memcpy(&mapOffset, good.data() + runtime::header::kSections + 8 * runtime::kSectionPhonemeMap, 4);
    std::string badMap = good;
    badMap[mapOffset] = 9;
    EXPECT_NE(loadError(withFixedCrc(badMap)).find("maps to key 9"), std::string::npos);

    std::uint32_t neutralOffset;
    std::memcpy(&neutralOffset, good.data() + runtime::header::kSections, 4);
    std::string nan = good;
    const float notANumber = std::nanf("");
    std::memcpy(nan.data() + neutralOffset + 4, &notANumber, 4);
    EXPECT_NE(loadError(withFixedCrc(nan)).find("non-finite"), std::string::npos);

    std::string newer = good;
    newer[runtime::header::kVersion] = 2;
    EXPECT_NE(loadError(newer).find("unsupported format version 2"), std::string::npos);
    std::string notOurs = good;
    notOurs[0] = 'X';
    EXPECT_NE(loadError(notOurs).find("magic"), std::string::npos);
    EXPECT_NE(loadError(good + "pad!").find("size mismatch"), std::string::npos);
}

TEST(RuntimePackage, LoadFileNamesTheFile) {
    const ReducedModel model = test::randomModel(4, 3, 2, false, 9);
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_runtime_test";
    std::filesystem::create_directories(dir);
    writeRuntimePackage(dir / "face.vlrt", model);
    Package package;
    std::string error;
    ASSERT_TRUE(package.loadFile((dir / "face.vlrt").c_str(), error)) << error;
    EXPECT_EQ(package.keyCount(), 2u);
    EXPECT_GT(package.memoryBytes(), 12u * package.vertexCount() * 3);
    EXPECT_FALSE(package.loadFile((dir / "missing.vlrt").c_str(), error));
    EXPECT_NE(error.find("missing.vlrt"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(RuntimePackage, Crc32MatchesTheStandardCheckValue) {
    const char* text = "123456789";
    EXPECT_EQ(runtime::crc32(reinterpret_cast<const std::uint8_t*>(text), 9), 0xCBF43926u);
    EXPECT_EQ(runtime::crc32(reinterpret_cast<const std::uint8_t*>(text) + 4, 5,
                             runtime::crc32(reinterpret_cast<const std::uint8_t*>(text), 4)),
              0xCBF43926u);
}

} // namespace
} // namespace vl
