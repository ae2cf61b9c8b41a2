#pragma once
// How a mesh looks, for drawing it: base-colour materials (a colour factor and an optional texture),
// the decoded images, and which material each triangle takes with the texture coordinates of its
// corners. Read from glTF avatars (core/gltf/AvatarMaterials.h) and OBJ files with an .mtl
// (core/io/ObjMaterials.h); display data only, nothing of the reduction depends on it.
//
// Texture coordinates follow glTF's convention: (0,0) is the top left of the image, v grows
// downwards, rows of TextureImage::rgba run top to bottom (OBJ's v is flipped when read).
#include "core/mesh/Mesh.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vl {

struct TextureImage {
    std::string name; // for messages: "image 3 ('Wolf3D_Skin')" or the file name
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba; // width x height x 4, top row first
};

enum class AlphaMode { Opaque, Mask, Blend };     // glTF material.alphaMode
enum class TextureWrap { Repeat, Clamp, Mirror }; // glTF sampler wrapS/wrapT (10497, 33071, 33648)

struct SurfaceMaterial {
    std::string name;
    std::array<float, 4> baseColor{1.0f, 1.0f, 1.0f, 1.0f}; // linear RGBA factor (glTF baseColorFactor)
    int image = -1; // index into SurfaceMaterials::images; -1: the factor alone
    // KHR_texture_transform of the base-colour texture: uv' = offset + R(rotation) S(scale) uv.
    std::array<float, 2> uvOffset{0.0f, 0.0f}, uvScale{1.0f, 1.0f};
    float uvRotation = 0.0f; // radians, counter-clockwise in texture space as the extension defines
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat; // the texture's sampler
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

struct SurfaceMaterials {
    std::vector<SurfaceMaterial> materials;
    std::vector<TextureImage> images;
    // What is not drawn as the file says (a missing texture file, a KTX2/WebP image, a texture
    // coordinate set the primitive lacks), each naming the file and element.
    std::vector<std::string> warnings;

    bool empty() const { return materials.empty(); }
};

// The triangles [firstTriangle, firstTriangle + triangleCount) of a mesh take one material.
struct MaterialRange {
    std::size_t firstTriangle = 0, triangleCount = 0;
    int material = -1; // index into SurfaceMaterials::materials; -1: no material (drawn in white)
};

// One mesh's assignment of materials: `ranges` cover its triangles in order; cornerTexCoords has
// one entry per triangle (corner k's index into texCoords), or is empty when the mesh has none.
struct SurfaceLayout {
    std::vector<Vec2> texCoords;
    std::vector<Triangle> cornerTexCoords;
    std::vector<MaterialRange> ranges;

    bool empty() const { return ranges.empty(); }
};

// Images larger than this many pixels are refused before they are decoded (16384 x 16384 would be
// 1 GiB of RGBA); all images of one mesh together at most kMaxTextureBytes once decoded.
inline constexpr std::size_t kMaxTexturePixels = std::size_t{8192} * 8192;
inline constexpr std::size_t kMaxTextureBytes = std::size_t{512} << 20;

} // namespace vl
