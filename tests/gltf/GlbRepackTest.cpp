// GlbRepack: a compressed vertex view shared by accessors that stay and accessors that go keeps
// only the elements that stay, losslessly.
#include "core/gltf/GlbRepack.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/GlbBuilder.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

std::vector<float> readAll(const GltfDocument& doc, int accessor, std::size_t count) {
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    return reader.floats(accessor, -1, "test", count);
}

TEST(GlbRepack, SharedMeshoptViewKeepsOnlyTheElementsOfAccessorsThatStay) {
    // Three VEC3 float blocks of 10 elements in one compressed view, as gltfpack stores morph targets.
    std::vector<float> values;
    for (int i = 0; i < 30 * 3; ++i) values.push_back(0.01f * static_cast<float>(i % 17) - 0.05f);
    test::GlbBuilder b;
    const int view = b.addMeshoptView(values.data(), 30, 12, "ATTRIBUTES", "NONE", test::kArrayBuffer);
    for (int k = 0; k < 3; ++k) {
        const int a = b.addAccessor(view, test::kFloat, "VEC3", 10, false);
        b.json["accessors"][static_cast<std::size_t>(a)]["byteOffset"] = 120 * k;
    }
    const GltfDocument in = parseGltfDocument(b.glb(), "in.glb", {});
    GlbRepack out(in);
    out.mayDrop(1);
    const GltfDocument result = parseGltfDocument(out.finish(), "out.glb", {});
    ASSERT_EQ(result.model.accessors.size(), 2u);
    const auto& ext = result.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
    EXPECT_EQ(ext["count"], 20);
    EXPECT_EQ(result.json["bufferViews"][0]["byteLength"], 240);
    EXPECT_EQ(result.json["accessors"][1]["byteOffset"], 120);
    EXPECT_EQ(readAll(result, 0, 10), std::vector<float>(values.begin(), values.begin() + 30));
    EXPECT_EQ(readAll(result, 1, 10), std::vector<float>(values.begin() + 60, values.end()));
    const auto& buffer = result.json["buffers"][result.json["bufferViews"][0]["buffer"].get<std::size_t>()];
    EXPECT_EQ(buffer["extensions"]["EXT_meshopt_compression"]["fallback"], true);
}

} // namespace
} // namespace vl
