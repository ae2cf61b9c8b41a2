// OBJ materials: mtllib / usemtl / Kd / d / map_Kd, per-corner texture coordinates flipped into
// glTF's convention, warnings for what is missing and an error for an absurd texture.
#include "core/io/ObjMaterials.h"
#include "core/common/Error.h"
#include "tests/common/TestImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace vl {
namespace {

// Two quads (four triangles): the first in material "skin" (textured), the second in "lips".
const char* kObj = "mtllib head.mtl\n"
                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.75\n"
                   "usemtl skin\n"
                   "f 1/1 2/2 3/3 4/4\n"
                   "usemtl lips # a comment\n"
                   "f 2/5 5/5 6/5 3/5\n";

// A scratch folder of this test (names distinct from other tests of the unity batch).
struct MaterialsFolder {
    std::filesystem::path path;
    MaterialsFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path =
            std::filesystem::temp_directory_path() / ("visemelab_objmaterials_" + std::string(info->name()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~MaterialsFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

void putFile(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& line : lines) out += line + "\n";
    return out;
}

TEST(ObjMaterials, MaterialsRangesTexturesAndCornerTexCoords) {
    MaterialsFolder dir;
    putFile(dir / "skin.png", test::pngBytes(2, 1, {10, 20, 30, 255, 40, 50, 60, 255}));
    putFile(dir / "head.mtl", "newmtl skin\nKd 0.8 0.8 0.8\nmap_Kd -s 1 1 1 -clamp on skin.png\n"
                              "newmtl lips\nKd 0.5 0.25 1\nd 0.5\n");
    putFile(dir / "head.obj", kObj);
    const ObjSurface surface = readObjSurface(dir / "head.obj");
    EXPECT_TRUE(surface.materials.warnings.empty()) << joined(surface.materials.warnings);
    ASSERT_EQ(surface.materials.materials.size(), 2u);
    const SurfaceMaterial& skin = surface.materials.materials[0];
    const SurfaceMaterial& lips = surface.materials.materials[1];
    EXPECT_EQ(skin.name, "skin");
    ASSERT_EQ(skin.image, 0);
    EXPECT_EQ(skin.baseColor[0], 1.0f); // the texture is the colour
    EXPECT_EQ(skin.wrapU, TextureWrap::Clamp);
    ASSERT_EQ(surface.materials.images.size(), 1u);
    EXPECT_EQ(surface.materials.images[0].width, 2);
    EXPECT_EQ(surface.materials.images[0].rgba[4], 40);
    EXPECT_EQ(lips.image, -1);
    EXPECT_NEAR(lips.baseColor[0], std::pow(0.5f, 2.2f), 1e-6); // Kd as a linear factor
    EXPECT_NEAR(lips.baseColor[2], 1.0f, 1e-6);
    EXPECT_EQ(lips.baseColor[3], 0.5f);
    EXPECT_EQ(lips.alphaMode, AlphaMode::Blend);

    ASSERT_EQ(surface.layout.ranges.size(), 2u);
    EXPECT_EQ(surface.layout.ranges[0].firstTriangle, 0u);
    EXPECT_EQ(surface.layout.ranges[0].triangleCount, 2u);
    EXPECT_EQ(surface.layout.ranges[0].material, 0);
    EXPECT_EQ(surface.layout.ranges[1].firstTriangle, 2u);
    EXPECT_EQ(surface.layout.ranges[1].material, 1);
    // Per corner (vertices 2 and 3 take other coordinates in the second quad: the seam is kept),
    // v flipped: vt 0.25 0.75 -> (0.25, 0.25).
    ASSERT_EQ(surface.layout.cornerTexCoords.size(), 4u);
    const Vec2 corner = surface.layout.texCoords[surface.layout.cornerTexCoords[2][0]];
    EXPECT_DOUBLE_EQ(corner[0], 0.25);
    EXPECT_DOUBLE_EQ(corner[1], 0.25);
    const Vec2 first = surface.layout.texCoords[surface.layout.cornerTexCoords[0][2]]; // vt 1 1
    EXPECT_DOUBLE_EQ(first[0], 1.0);
    EXPECT_DOUBLE_EQ(first[1], 0.0);
}

TEST(ObjMaterials, MissingTextureLibraryAndMaterialAreWarnings) {
    MaterialsFolder dir;
    putFile(dir / "head.mtl", "newmtl skin\nKd 1 0 0\nmap_Kd textures/missing.png\n");
    putFile(dir / "head.obj", std::string(kObj) + "mtllib other.mtl\n");
    const ObjSurface surface = readObjSurface(dir / "head.obj");
    const std::string warnings = joined(surface.materials.warnings);
    EXPECT_NE(warnings.find("head.mtl:3: texture '"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("missing.png' not found"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("head.obj:17: material library '"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("head.obj:15: usemtl 'lips' names no material"), std::string::npos) << warnings;
    ASSERT_EQ(surface.materials.materials.size(), 1u);
    EXPECT_EQ(surface.materials.materials[0].image, -1);
    EXPECT_NEAR(surface.materials.materials[0].baseColor[0], 1.0f, 1e-6); // its Kd instead
    EXPECT_EQ(surface.layout.ranges[1].material, -1);
}

TEST(ObjMaterials, AbsurdTextureSizeIsAnErrorNamingTheFile) {
    MaterialsFolder dir;
    putFile(dir / "huge.png", test::pngClaiming(100000, 100000));
    putFile(dir / "head.mtl", "newmtl skin\nmap_Kd huge.png\n");
    putFile(dir / "head.obj", kObj);
    try {
        readObjSurface(dir / "head.obj");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("head.mtl:2: texture '"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("huge.png': declares 100000 x 100000 pixels"), std::string::npos)
            << e.what();
    }
}

TEST(ObjMaterials, NoMaterialStatementsGiveNoLayout) {
    const ObjSurface surface = parseObjSurface("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.obj", ".");
    EXPECT_TRUE(surface.layout.empty());
    EXPECT_TRUE(surface.materials.empty());
}

} // namespace
} // namespace vl
