#pragma once
// A headless software renderer for previews and documentation pictures (no GL): z-buffered,
// Lambert-shaded triangles with an optional wireframe overlay and per-vertex colours.
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vl::preview {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // row-major from the top row, 4 bytes per pixel
};

struct RenderOptions {
    int width = 512;
    int height = 512;
    // Camera orbit around the mesh centre, in degrees: yaw turns it to the mesh's right (+x),
    // pitch raises it. 0/0 looks at the mesh along -z (the face front).
    double yawDegrees = 0.0;
    double pitchDegrees = 0.0;
    double fovDegrees = 30.0;
    // Frame this sphere (centre, radius in mesh units) instead of the whole mesh: a close-up, e.g. of
    // the mouth; the same focus on several meshes keeps one scale. A radius <= 0 frames the whole mesh.
    Vec3 focusCentre{0, 0, 0};
    double focusRadius = 0.0;
    bool wireframe = false;
    std::vector<Vec3> vertexColours; // empty (uniform grey-beige) or one RGB in [0,1] per vertex
    Vec3 background{0.13, 0.14, 0.17};
    Vec3 wireColour{0.1, 0.1, 0.1};
};

// Renders `mesh` framed to fit the image. Throws InputError for an empty mesh, a size outside
// 1..8192, or a colour list of the wrong length.
Image render(const MeshData& mesh, const RenderOptions& options);

// Places images side by side in rows of `columns` (all must have the same size); each gets its
// label (if any) in its top-left corner.
Image contactSheet(const std::vector<Image>& images, int columns,
                   const std::vector<std::string>& labels = {});

// Writes `text` (ASCII) with its top-left corner at (x, y), `scale` image pixels per font pixel.
void drawLabel(Image& image, int x, int y, std::string_view text, int scale, const Vec3& colour);

// Writes a PNG atomically (stb_image_write).
void writePng(const std::filesystem::path& path, const Image& image);

} // namespace vl::preview
