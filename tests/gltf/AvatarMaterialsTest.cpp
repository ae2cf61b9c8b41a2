// An avatar's materials for display: base colour factor and texture per primitive (texCoord set
// and KHR_texture_transform), alpha modes, layouts that fit the scan's viseme set and context
// vertex for vertex, warnings for images not drawn, errors for absurd image sizes.
#include "core/gltf/AvatarMaterials.h"
#include "core/common/Error.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/TexturedAvatar.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

struct Read {
    GltfDocument doc;
    AvatarScan scan;
    AvatarSurfaces surfaces;
};

Read readTextured(const test::TexturedAvatarOptions& options = {}, const std::filesystem::path& folder = {}) {
    Read r{parseGltfDocument(test::texturedAvatar(options), "textured.glb", folder), {}, {}};
    r.scan = scanAvatar(r.doc, {"", true});
    r.surfaces = readAvatarSurfaces(r.doc, r.scan);
    return r;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& line : lines) out += line + "\n";
    return out;
}

TEST(AvatarMaterials, FaceTextureEyeBlendAndBodyFallbackPerPrimitive) {
    const Read r = readTextured();
    const SurfaceMaterials& m = r.surfaces.materials;
    ASSERT_EQ(m.materials.size(), 3u);
    const SurfaceMaterial& face = m.materials[0];
    EXPECT_EQ(face.name, "Face");
    ASSERT_EQ(face.image, 0);
    EXPECT_EQ(face.uvOffset[0], 0.5f);
    EXPECT_EQ(face.uvScale[0], 0.5f);
    EXPECT_EQ(face.wrapU, TextureWrap::Clamp);
    EXPECT_EQ(face.wrapV, TextureWrap::Clamp);
    EXPECT_EQ(face.alphaMode, AlphaMode::Opaque);
    ASSERT_EQ(m.images.size(), 1u);
    EXPECT_EQ(m.images[0].width, 4);
    EXPECT_EQ(m.images[0].name, "image 0 ('face_baseColor')");
    EXPECT_EQ(m.images[0].rgba[0], 220);
    EXPECT_EQ(m.images[0].rgba[1], 40);
    const SurfaceMaterial& eye = m.materials[1];
    EXPECT_EQ(eye.alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(eye.doubleSided);
    EXPECT_EQ(eye.baseColor[3], 0.5f);
    EXPECT_EQ(eye.image, -1);
    const SurfaceMaterial& body = m.materials[2];
    EXPECT_EQ(body.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(body.alphaCutoff, 0.25f);
    EXPECT_EQ(body.image, -1); // KTX2 only: its factor instead
    EXPECT_FLOAT_EQ(body.baseColor[2], 0.6f);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(
        m.warnings[0].find("textured.glb: textures/1: not drawn, its image is only in KHR_texture_basisu"),
        std::string::npos)
        << m.warnings[0];

    // The viseme set: Face (81 vertices, 128 triangles) then Eye (4, 2); the context: Body.
    const SurfaceLayout& set = r.surfaces.visemes;
    ASSERT_EQ(set.texCoords.size(), r.scan.set.neutral.positions.size());
    ASSERT_EQ(set.ranges.size(), 2u);
    EXPECT_EQ(set.ranges[0].triangleCount, 128u);
    EXPECT_EQ(set.ranges[0].material, 0);
    EXPECT_EQ(set.ranges[1].firstTriangle, 128u);
    EXPECT_EQ(set.ranges[1].triangleCount, 2u);
    EXPECT_EQ(set.ranges[1].material, 1);
    EXPECT_EQ(set.cornerTexCoords, r.scan.set.neutral.triangles);
    // The face reads TEXCOORD_1 (KHR_texture_transform's texCoord): v = 1 - row / 8, so 1 on row 0.
    EXPECT_FLOAT_EQ(static_cast<float>(set.texCoords[0][1]), 1.0f);
    EXPECT_FLOAT_EQ(static_cast<float>(set.texCoords[80][1]), 0.0f);
    const SurfaceLayout& context = r.surfaces.context;
    ASSERT_EQ(context.texCoords.size(), r.scan.context.positions.size());
    ASSERT_EQ(context.ranges.size(), 1u);
    EXPECT_EQ(context.ranges[0].material, 2);
}

TEST(AvatarMaterials, AbsurdImageSizeIsAnErrorNamingFileAndImage) {
    test::TexturedAvatarOptions options;
    options.claimedSize = 60000;
    try {
        readTextured(options);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("textured.glb: images/0: declares 60000 x 60000 pixels"),
                  std::string::npos)
            << e.what();
    }
}

TEST(AvatarMaterials, MissingExternalImageIsAWarning) {
    test::TexturedAvatarOptions options;
    options.externalImage = true;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "visemelab_materials_missing";
    std::filesystem::create_directories(folder);
    const Read r = readTextured(options, folder);
    EXPECT_EQ(r.surfaces.materials.materials[0].image, -1);
    const std::string warnings = joined(r.surfaces.materials.warnings);
    EXPECT_NE(warnings.find("textured.glb: images/0/uri: file 'face.png' not found"), std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("material 'Face' shows its base colour factor"), std::string::npos) << warnings;
    std::filesystem::remove_all(folder);
}

TEST(AvatarMaterials, ReadyPlayerMeLikeLayoutsFitEveryStorage) {
    for (const auto storage : {test::FixtureStorage::Plain, test::FixtureStorage::Quantised,
                               test::FixtureStorage::Meshopt, test::FixtureStorage::Draco}) {
        test::AvatarFixtureOptions options;
        options.storage = storage;
        const GltfDocument doc = parseGltfDocument(test::rpmLikeAvatar(options), "rpm.glb", {});
        const AvatarScan scan = scanAvatar(doc, {"", true});
        const AvatarSurfaces surfaces = readAvatarSurfaces(doc, scan);
        EXPECT_EQ(surfaces.visemes.texCoords.size(), scan.set.neutral.positions.size());
        EXPECT_EQ(surfaces.context.texCoords.size(), scan.context.positions.size());
        // The head's skin texture (the fixture's 2x2 PNG) is decoded, sampled as its sampler says
        // (wrapS repeat, wrapT mirrored).
        ASSERT_FALSE(surfaces.materials.images.empty()) << static_cast<int>(storage);
        for (const SurfaceMaterial& m : surfaces.materials.materials)
            if (m.image >= 0) {
                EXPECT_EQ(m.wrapU, TextureWrap::Repeat);
                EXPECT_EQ(m.wrapV, TextureWrap::Mirror);
            }
        EXPECT_EQ(surfaces.materials.images[0].width, 2);
        EXPECT_EQ(surfaces.materials.images[0].rgba[0], 200);
    }
}

TEST(AvatarMaterials, VRoidLikeLayoutsFitItsTwoFacePrimitives) {
    for (const bool vrm1 : {false, true}) {
        const GltfDocument doc = parseGltfDocument(test::vroidLikeAvatar(vrm1), "vroid.vrm", {});
        const AvatarScan scan = scanAvatar(doc, {"Fcl_MTH_*", true});
        const AvatarSurfaces surfaces = readAvatarSurfaces(doc, scan);
        EXPECT_EQ(surfaces.visemes.texCoords.size(), scan.set.neutral.positions.size());
        EXPECT_EQ(surfaces.context.texCoords.size(), scan.context.positions.size());
        std::size_t triangles = 0;
        for (const MaterialRange& r : surfaces.visemes.ranges) triangles += r.triangleCount;
        EXPECT_EQ(triangles, scan.set.neutral.triangles.size());
    }
}

} // namespace
} // namespace vl
