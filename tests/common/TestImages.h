#pragma once
// Tiny images encoded in memory for texture tests (stb_image_write from Debian's libstb: link
// PkgConfig::STB), and a PNG whose header claims a size its data does not hold.
#include <stb_image_write.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vl::test {

inline void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

// width x height RGBA pixels, top row first.
inline std::string pngBytes(int width, int height, const std::vector<std::uint8_t>& rgba) {
    std::string bytes;
    stbi_write_png_to_func(&appendBytes, &bytes, width, height, 4, rgba.data(), width * 4);
    return bytes;
}

inline std::string jpegBytes(int width, int height, const std::vector<std::uint8_t>& rgb) {
    std::string bytes;
    stbi_write_jpg_to_func(&appendBytes, &bytes, width, height, 3, rgb.data(), 95);
    return bytes;
}

// A solid colour, width x height RGBA.
inline std::vector<std::uint8_t> solidRgba(int width, int height, std::uint8_t r, std::uint8_t g,
                                           std::uint8_t b, std::uint8_t a = 255) {
    std::vector<std::uint8_t> out(4 * static_cast<std::size_t>(width * height));
    for (std::size_t i = 0; i < out.size(); i += 4) {
        out[i] = r;
        out[i + 1] = g;
        out[i + 2] = b;
        out[i + 3] = a;
    }
    return out;
}

// A valid 2x2 PNG whose IHDR then claims width x height (the header is all a size check reads).
inline std::string pngClaiming(std::uint32_t width, std::uint32_t height) {
    std::string png = pngBytes(2, 2, solidRgba(2, 2, 1, 2, 3));
    for (int k = 0; k < 4; ++k) {
        png[16 + static_cast<std::size_t>(k)] = static_cast<char>(width >> (24 - 8 * k));
        png[20 + static_cast<std::size_t>(k)] = static_cast<char>(height >> (24 - 8 * k));
    }
    return png;
}

} // namespace vl::test
