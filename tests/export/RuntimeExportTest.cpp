#include "core/common/Error.h"
#include "core/export/KeyMeshFiles.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/io/MeshIO.h"
#include "tests/export/TestModels.h"
#include "tests/io/MeshIOTestUtil.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

TEST(RuntimeExport, RefusesModelsTheFormatCannotHold) {
    ReducedModel model = test::randomModel(3, 3, 2, false, 61);
    model.keys[1].name = model.keys[0].name;
    EXPECT_THROW(encodeRuntimePackage(model), InputError);
    model = test::randomModel(3, 3, 2, false, 61);
    model.keys[0].name = std::string(70000, 'x');
    EXPECT_THROW(encodeRuntimePackage(model), InputError);
    model = test::randomModel(3, 3, 2, false, 61);
    model.phonemeToKey.emplace_back("extra", 5);
    EXPECT_THROW(encodeRuntimePackage(model), InputError);
}

TEST(RuntimeExport, EncodingIsDeterministic) {
    const ReducedModel model = test::randomModel(6, 5, 3, true, 62);
    EXPECT_EQ(encodeRuntimePackage(model), encodeRuntimePackage(model));
    EXPECT_EQ(encodeRuntimePackage(model, {.quantise = true}),
              encodeRuntimePackage(model, {.quantise = true}));
}

TEST(KeyMeshFiles, OneObjPerKeyReadsBackAsTheSameFloat32Numbers) {
    const ReducedModel model = test::randomModel(6, 5, 3, true, 63);
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_obj_export_test";
    std::filesystem::remove_all(dir);
    const std::vector<std::string> files = writeKeyMeshFiles(dir, model, ".obj");
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[0], "neutral.obj");
    EXPECT_EQ(files[2], "reduced_1_key1+m1.obj");
    // Key meshes are written as float32 (docs/export.md); (u,v) and faces exactly.
    const MeshData neutral = readMesh(dir / files[0]);
    test::expectSameFloat32Positions(model.neutral.positions, neutral.positions);
    EXPECT_EQ(neutral.triangles, model.neutral.triangles);
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        SCOPED_TRACE(files[k + 1]);
        const MeshData key = readMesh(dir / files[k + 1]);
        test::expectSameFloat32Positions(model.keys[k].positions, key.positions);
        EXPECT_EQ(key.uvs, model.neutral.uvs);
    }
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl
