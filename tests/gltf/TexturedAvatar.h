#pragma once
// A small textured avatar for the material tests (core/gltf/AvatarMaterials.h) and the editor's
// real-click material test: a "Face" grid facing +z (1 x 1 m, centred on the origin) carrying
// viseme_sil, viseme_aa and viseme_O, whose material's base colour texture is a solid `faceColour`
// PNG read through TEXCOORD_1 with KHR_texture_transform, clamped to its edges; an "Eye" quad in
// front of it with a translucent (BLEND) red base colour factor and no texture, carrying viseme_aa;
// and a "Body" quad without targets (context) in a material whose only image is KTX2
// (KHR_texture_basisu).
#include <array>
#include <cstdint>
#include <string>

namespace vl::test {

struct TexturedAvatarOptions {
    std::array<std::uint8_t, 3> faceColour{220, 40, 40};
    // Non-zero: the face texture's PNG header claims this width and height instead.
    std::uint32_t claimedSize = 0;
    bool externalImage = false; // the face texture as uri "face.png" (not written) instead of a view
};

std::string texturedAvatar(const TexturedAvatarOptions& options = {});

} // namespace vl::test
