#include "core/io/ImageDecode.h"

#include "core/common/Error.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

namespace vl {

ImageFormat imageFormatOf(std::string_view bytes) {
    if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return ImageFormat::Png;
    if (bytes.starts_with("\xFF\xD8\xFF")) return ImageFormat::Jpeg;
    if (bytes.starts_with("\xABKTX 20\xBB\r\n\x1a\n")) return ImageFormat::Ktx2;
    if (bytes.size() >= 12 && bytes.starts_with("RIFF") && bytes.substr(8, 4) == "WEBP")
        return ImageFormat::WebP;
    return ImageFormat::Unknown;
}

const char* imageFormatName(ImageFormat format) {
    switch (format) {
    case ImageFormat::Png:
        return "PNG";
    case ImageFormat::Jpeg:
        return "JPEG";
    case ImageFormat::Ktx2:
        return "KTX2";
    case ImageFormat::WebP:
        return "WebP";
    case ImageFormat::Unknown:
        break;
    }
    return "unknown";
}

namespace {

std::uint32_t bigEndian(std::string_view bytes, std::size_t at, int count) {
    std::uint32_t value = 0;
    for (int k = 0; k < count; ++k)
        value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
    return value;
}

// The size the header declares (PNG IHDR, JPEG start of frame), read here because stb_image turns
// a large claim into "too large" without saying how large; false when the header is not found.
bool declaredSize(std::string_view bytes, ImageFormat format, std::uint32_t& width, std::uint32_t& height) {
    if (format == ImageFormat::Png) {
        if (bytes.size() < 24 || bytes.substr(12, 4) != "IHDR") return false;
        width = bigEndian(bytes, 16, 4);
        height = bigEndian(bytes, 20, 4);
        return true;
    }
    // JPEG: markers FF xx, each but SOI/EOI/RSTn followed by a 2-byte length; SOF0..SOF15 (not
    // DHT C4, JPG C8, DAC CC) hold precision, height, width.
    std::size_t at = 2;
    while (at + 9 <= bytes.size()) {
        if (static_cast<unsigned char>(bytes[at]) != 0xFF) return false;
        const auto marker = static_cast<unsigned char>(bytes[at + 1]);
        if (marker == 0xFF) {
            ++at;
            continue;
        }
        if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
            height = bigEndian(bytes, at + 5, 2);
            width = bigEndian(bytes, at + 7, 2);
            return true;
        }
        at += 2 + bigEndian(bytes, at + 2, 2);
    }
    return false;
}

} // namespace

DecodedImage decodeImage(std::string_view bytes, std::string_view where, std::size_t maxBytes) {
    const ImageFormat format = imageFormatOf(bytes);
    if (format == ImageFormat::Ktx2 || format == ImageFormat::WebP)
        return {std::nullopt, std::string(imageFormatName(format)) + " images are not drawn"};
    if (format == ImageFormat::Unknown) return {std::nullopt, "neither PNG nor JPEG"};
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return {std::nullopt, "larger than 2 GiB"};
    std::uint32_t declaredWidth = 0, declaredHeight = 0;
    if (declaredSize(bytes, format, declaredWidth, declaredHeight)) {
        // The header's claim is checked before anything is allocated for it (a 60-byte PNG can
        // declare 65535 x 65535 pixels).
        const auto pixels = std::size_t{declaredWidth} * declaredHeight;
        if (pixels > kMaxTexturePixels)
            throwInputError(where, "declares " + std::to_string(declaredWidth) + " x " +
                                       std::to_string(declaredHeight) + " pixels; at most " +
                                       std::to_string(kMaxTexturePixels) + " pixels per texture are read");
        if (4 * pixels > maxBytes)
            throwInputError(where, std::to_string(declaredWidth) + " x " + std::to_string(declaredHeight) +
                                       " pixels exceed what is left of the " +
                                       std::to_string(kMaxTextureBytes >> 20) +
                                       " MiB of decoded textures per mesh");
    }
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels) ||
        static_cast<std::uint32_t>(width) != declaredWidth ||
        static_cast<std::uint32_t>(height) != declaredHeight)
        return {std::nullopt, std::string("corrupt ") + imageFormatName(format) + " (" +
                                  (stbi_failure_reason() ? stbi_failure_reason() : "no size in its header") +
                                  ")"};
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const std::unique_ptr<stbi_uc, void (*)(void*)> decoded(
        stbi_load_from_memory(data, length, &width, &height, &channels, 4), &stbi_image_free);
    if (!decoded)
        return {std::nullopt, std::string("corrupt ") + imageFormatName(format) + " (" +
                                  (stbi_failure_reason() ? stbi_failure_reason() : "unreadable") + ")"};
    TextureImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(4 * pixels);
    std::memcpy(image.rgba.data(), decoded.get(), image.rgba.size());
    return {std::move(image), ""};
}

} // namespace vl
