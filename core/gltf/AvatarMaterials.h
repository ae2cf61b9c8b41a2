#pragma once
// How an avatar looks, for the editor's views: the base colour of each primitive's material
// (baseColorFactor, baseColorTexture with its texCoord set and KHR_texture_transform, alphaMode
// MASK/BLEND with alphaCutoff, doubleSided), the PNG/JPEG images it uses decoded, and per-vertex
// texture coordinates laid out like the scan's world-space geometry: the viseme set (the meshes
// carrying visemes, concatenated in file order) and the context (the other meshes, when the scan read
// them), each with one material range per primitive.
//
// Not drawn, with a warning naming the file and element: a texture whose image is KTX2
// (KHR_texture_basisu) or WebP (EXT_texture_webp) without a PNG/JPEG fallback, a missing or corrupt
// image, a texCoord set the primitive lacks; the material then shows its base colour factor. An
// image declaring more than kMaxTexturePixels (or the decoded images more than kMaxTextureBytes) is
// an InputError naming the file and image index.
#include "core/mesh/SurfaceMaterials.h"

namespace vl {

class GltfDocument;
struct AvatarScan;

struct AvatarSurfaces {
    SurfaceMaterials materials; // the materials the primitives use, in order of first use
    SurfaceLayout visemes;      // over AvatarScan::set.neutral
    SurfaceLayout context;      // over AvatarScan::context (empty when the scan read no context)
};

// `scan` must be scanAvatar(doc, ...): the layouts follow its primitives' vertex and triangle counts.
AvatarSurfaces readAvatarSurfaces(const GltfDocument& doc, const AvatarScan& scan);

} // namespace vl
