#include "core/preview/Renderer.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace vl::preview {

void drawLabel(Image& image, int x, int y, std::string_view text, int scale, const Vec3& colour) {
    // stb_easy_font builds the glyphs from axis-aligned quads: 4 vertices of 16 bytes
    // (x, y, z as float, then RGBA), in font pixels from (0,0).
    std::string buffer(text);
    std::vector<char> vertices(static_cast<std::size_t>(std::max<std::size_t>(buffer.size(), 1)) * 1200);
    const int quads = stb_easy_font_print(0.0f, 0.0f, buffer.data(), nullptr, vertices.data(),
                                          static_cast<int>(vertices.size()));
    const auto corner = [&](int q, int k, int axis) {
        float v = 0.0f;
        std::memcpy(&v, vertices.data() + (static_cast<std::size_t>(q) * 4 + k) * 16 + axis * 4, sizeof v);
        return v;
    };
    const std::uint8_t rgb[3] = {
        static_cast<std::uint8_t>(std::lround(std::clamp(colour[0], 0.0, 1.0) * 255)),
        static_cast<std::uint8_t>(std::lround(std::clamp(colour[1], 0.0, 1.0) * 255)),
        static_cast<std::uint8_t>(std::lround(std::clamp(colour[2], 0.0, 1.0) * 255))};
    for (int q = 0; q < quads; ++q) {
        const int x0 = x + static_cast<int>(std::lround(corner(q, 0, 0) * scale));
        const int y0 = y + static_cast<int>(std::lround(corner(q, 0, 1) * scale));
        const int x1 = x + static_cast<int>(std::lround(corner(q, 2, 0) * scale));
        const int y1 = y + static_cast<int>(std::lround(corner(q, 2, 1) * scale));
        for (int py = std::max(0, std::min(y0, y1)); py < std::min(image.height, std::max(y0, y1)); ++py)
            for (int px = std::max(0, std::min(x0, x1)); px < std::min(image.width, std::max(x0, x1)); ++px) {
                std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(py) * image.width + px) * 4];
                std::copy_n(rgb, 3, p);
                p[3] = 255;
            }
    }
}

} // namespace vl::preview
