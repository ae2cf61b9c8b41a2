#pragma once
// Texture images decoded for display: PNG and JPEG through Debian's libstb (stb_image), with the
// declared size checked before any pixel is decoded. Other formats glTF files carry (KTX2 of
// KHR_texture_basisu, WebP of EXT_texture_webp) are recognised and reported, not decoded.
#include "core/mesh/SurfaceMaterials.h"

#include <optional>
#include <string>
#include <string_view>

namespace vl {

enum class ImageFormat { Png, Jpeg, Ktx2, WebP, Unknown };

// By the magic bytes.
ImageFormat imageFormatOf(std::string_view bytes);
const char* imageFormatName(ImageFormat format);

struct DecodedImage {
    std::optional<TextureImage> image; // RGBA, top row first
    std::string problem;               // why there is no image (unsupported format, corrupt data)
};

// Decodes `bytes`. A declared size above kMaxTexturePixels, or RGBA bytes above `maxBytes` (what is
// left of a mesh's kMaxTextureBytes), throws InputError "<where>: ..." before decoding; a format
// that is not drawn or data stb_image rejects gives a problem instead (a texture is not worth
// refusing the mesh for).
DecodedImage decodeImage(std::string_view bytes, std::string_view where, std::size_t maxBytes);

} // namespace vl
