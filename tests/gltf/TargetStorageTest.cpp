// The storage of new key targets (core/gltf/TargetStorage.h): written into a GLB by GlbRepack, read
// back by the reader, each storage and layout checked against what it promises.
#include "core/gltf/TargetStorage.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GlbRepack.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/GlbBuilder.h"

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <random>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

struct WrittenAccessor {
    GltfDocument doc;
    int accessor = -1;
    StorageTally tally;
};

WrittenAccessor write(const std::vector<double>& values, const TargetStorage& storage) {
    test::GlbBuilder b;
    b.addView("data", 4); // a BIN chunk, as every avatar has
    const GltfDocument empty = parseGltfDocument(b.glb(), "empty.glb", {});
    GlbRepack out(empty);
    WrittenAccessor w{{}, -1, {}};
    w.accessor = addVec3Target(out, values, storage, true, &w.tally);
    w.doc = parseGltfDocument(out.finish(), "out.glb", {});
    return w;
}

std::vector<float> readBack(const WrittenAccessor& w) {
    BufferViews views(w.doc);
    AccessorReader reader(w.doc, views);
    const std::size_t count = w.doc.model.accessors[static_cast<std::size_t>(w.accessor)].count;
    return reader.floats(w.accessor, -1, "test", count);
}

const Json& accessorJson(const WrittenAccessor& w) {
    return w.doc.json["accessors"][static_cast<std::size_t>(w.accessor)];
}

// Displacements of `count` vertices, every vertex moving (dense is the smallest plain layout).
std::vector<double> moving(std::size_t count, double scale) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> v(3 * count);
    for (double& x : v) x = scale * u(rng);
    return v;
}

TEST(TargetStorage, QuantisedShortsKeepTheGridTheAlignmentAndIntegerBounds) {
    TargetStorage shorts;
    shorts.componentType = 5122;
    shorts.normalized = true;
    // 300 vertices, all moving: sparse (2-byte index + 6 bytes) ties with dense (8): dense.
    std::vector<double> values = moving(300, 0.5);
    values[0] = 2.0; // outside [-1, 1]: clamped
    const WrittenAccessor w = write(values, shorts);
    const Json& a = accessorJson(w);
    EXPECT_EQ(a["componentType"], 5122);
    EXPECT_EQ(a["normalized"], true);
    const Json& view = w.doc.json["bufferViews"][a["bufferView"].get<std::size_t>()];
    EXPECT_EQ(view["byteStride"], 8);
    EXPECT_EQ(view["byteLength"], 300 * 8);
    EXPECT_EQ(a["max"][0], 32767); // the stored integer, clamped
    const auto used = w.doc.model.extensionsRequired;
    EXPECT_NE(std::find(used.begin(), used.end(), "KHR_mesh_quantization"), used.end());
    const std::vector<float> got = readBack(w);
    for (std::size_t i = 1; i < values.size(); ++i) ASSERT_NEAR(got[i], values[i], 0.5 / 32767.0 + 1e-7) << i;
    EXPECT_FLOAT_EQ(got[0], 1.0f);
    EXPECT_EQ(w.tally.at("SHORT normalised, dense"), 1u);
}

TEST(TargetStorage, UnnormalisedBytesRoundToIntegersWithStrideFour) {
    TargetStorage bytes;
    bytes.componentType = 5120;
    const WrittenAccessor w = write(moving(20, 100.0), bytes);
    const Json& a = accessorJson(w);
    EXPECT_FALSE(a.contains("normalized"));
    EXPECT_EQ(w.doc.json["bufferViews"][a["bufferView"].get<std::size_t>()]["byteStride"], 4);
    const std::vector<float> got = readBack(w);
    const std::vector<double> want = moving(20, 100.0);
    for (std::size_t i = 0; i < want.size(); ++i) ASSERT_EQ(got[i], std::round(want[i])) << i;
}

TEST(TargetStorage, FewMovingVerticesAreSparseAndZerosHaveNoBytes) {
    std::vector<double> values(3 * 300, 0.0);
    values[3 * 7 + 1] = 0.25;
    values[3 * 299] = -0.5;
    TargetStorage shorts;
    shorts.componentType = 5122;
    shorts.normalized = true;
    const WrittenAccessor w = write(values, shorts);
    const Json& a = accessorJson(w);
    EXPECT_FALSE(a.contains("bufferView"));
    EXPECT_EQ(a["sparse"]["count"], 2);
    EXPECT_EQ(a["sparse"]["indices"]["componentType"], 5123); // 300 vertices: unsigned short
    const std::vector<float> got = readBack(w);
    EXPECT_NEAR(got[3 * 7 + 1], 0.25, 1e-4);
    EXPECT_NEAR(got[3 * 299], -0.5, 1e-4);
    EXPECT_EQ(got[3 * 100], 0.0f);

    const WrittenAccessor zero = write(std::vector<double>(30, 0.0), shorts);
    EXPECT_FALSE(accessorJson(zero).contains("bufferView"));
    EXPECT_FALSE(accessorJson(zero).contains("sparse"));
    EXPECT_EQ(zero.tally.at("no bytes (all zero)"), 1u);
}

TEST(TargetStorage, MeshoptExponentialIsCompressedWithAFallbackBufferAndReadsBack) {
    // Smooth data compresses well: a ramp.
    std::vector<double> values;
    for (int i = 0; i < 500; ++i) values.insert(values.end(), {0.001 * i, -0.0005 * i, 0.0});
    TargetStorage exp;
    exp.meshopt = true;
    exp.filter = MeshoptFilter::Exponential;
    exp.exponentBits = 15;
    const WrittenAccessor w = write(values, exp);
    const Json& a = accessorJson(w);
    const Json& view = w.doc.json["bufferViews"][a["bufferView"].get<std::size_t>()];
    const Json& ext = view["extensions"]["EXT_meshopt_compression"];
    EXPECT_EQ(ext["mode"], "ATTRIBUTES");
    EXPECT_EQ(ext["filter"], "EXPONENTIAL");
    EXPECT_LT(ext["byteLength"].get<std::size_t>(), 500u * 12u / 2);
    const Json& fallback = w.doc.json["buffers"][view["buffer"].get<std::size_t>()];
    EXPECT_EQ(fallback["extensions"]["EXT_meshopt_compression"]["fallback"], true);
    EXPECT_GE(fallback["byteLength"].get<std::size_t>(), view.value("byteOffset", std::size_t{0}) + 500 * 12);
    const auto used = w.doc.model.extensionsRequired;
    EXPECT_NE(std::find(used.begin(), used.end(), "EXT_meshopt_compression"), used.end());
    const std::vector<float> got = readBack(w);
    for (std::size_t i = 0; i < values.size(); ++i) ASSERT_NEAR(got[i], values[i], std::ldexp(1.0, -14)) << i;
    // min/max are those of the decoded values.
    EXPECT_EQ(a["max"][0].get<double>(), *std::max_element(got.begin(), got.end()));
}

TEST(TargetStorage, ExponentBitsAreInferredFromTheDecodedData) {
    std::vector<float> values;
    for (int i = 0; i < 64; ++i)
        values.insert(values.end(),
                      {0.37f * std::sin(0.1f * i) + 0.5f, 1.3f * std::cos(0.2f * i) + 2.0f, 0.9f});
    for (int bits : {6, 10, 15, 20}) {
        std::vector<unsigned char> encoded(values.size() * 4);
        meshopt_encodeFilterExp(encoded.data(), 64, 12, bits, values.data());
        meshopt_decodeFilterExp(encoded.data(), 64, 12);
        EXPECT_EQ(inferExponentBits(encoded.data(), 64, 12), bits);
    }
    // Plain floats of full precision: no K reproduces them.
    EXPECT_EQ(inferExponentBits(reinterpret_cast<const unsigned char*>(values.data()), 64, 12),
              kDefaultExponentBits);
}

TEST(TargetStorage, MostPreciseMemberWins) {
    TargetStorage plain, shorts, bytes, exp10, exp15;
    shorts.componentType = 5122;
    shorts.normalized = true;
    bytes.componentType = 5120;
    bytes.normalized = true;
    exp10.meshopt = exp15.meshopt = true;
    exp10.filter = exp15.filter = MeshoptFilter::Exponential;
    exp10.exponentBits = 10;
    exp15.exponentBits = 15;
    EXPECT_EQ(morePrecise(shorts, plain).componentType, 5126);
    EXPECT_EQ(morePrecise(bytes, shorts).componentType, 5122);
    EXPECT_EQ(morePrecise(exp10, exp15).exponentBits, 15);
    EXPECT_EQ(morePrecise(exp15, plain).filter, MeshoptFilter::None);
    EXPECT_EQ(morePrecise(shorts, exp10).filter, MeshoptFilter::Exponential);
    TargetStorage compressedShorts = shorts;
    compressedShorts.meshopt = true;
    EXPECT_TRUE(morePrecise(shorts, compressedShorts).meshopt); // equal precision: the smaller
}

} // namespace
} // namespace vl
