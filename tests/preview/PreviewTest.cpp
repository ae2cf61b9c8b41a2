#include "core/common/Error.h"
#include "core/preview/Renderer.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace vl {
namespace {

const std::uint8_t* pixel(const preview::Image& im, int x, int y) {
    return &im.rgba[(static_cast<std::size_t>(y) * im.width + x) * 4];
}

MeshData square(double z, double size) {
    MeshData m;
    m.positions = {Vec3(-size, -size, z), Vec3(size, -size, z), Vec3(size, size, z), Vec3(-size, size, z)};
    m.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
    return m;
}

// A red square (half-size 1 at z = 0) and a blue one of half-size `size` moved by `offset`, with the
// options of a 64 x 64 render of them.
MeshData redAndBlue(const Vec3& offset, double size, preview::RenderOptions& o) {
    MeshData m = square(0.0, 1.0);
    for (const auto& p : square(0.0, size).positions) m.positions.push_back(p + offset);
    m.triangles.push_back({4, 5, 6});
    m.triangles.push_back({4, 6, 7});
    o.width = o.height = 64;
    o.vertexColours = {Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0),
                       Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    return m;
}

TEST(Preview, FillsTheMeshAndLeavesTheBackground) {
    MeshData m = square(0.0, 1.0);
    m.positions.push_back(Vec3(-3, -3, 0)); // unused vertices widen the framing
    m.positions.push_back(Vec3(3, 3, 0));
    preview::RenderOptions o;
    o.width = o.height = 64;
    o.vertexColours.assign(m.positions.size(), Vec3(1, 0, 0));
    const auto im = preview::render(m, o);
    ASSERT_EQ(im.rgba.size(), 64u * 64u * 4u);
    const auto* centre = pixel(im, 32, 32);
    EXPECT_GT(centre[0], 100);
    EXPECT_EQ(centre[1], 0);
    const auto* corner = pixel(im, 1, 1);
    EXPECT_EQ(corner[0], static_cast<std::uint8_t>(std::lround(o.background[0] * 255)));
}

TEST(Preview, NearerSurfaceHidesFartherOne) {
    preview::RenderOptions o;
    MeshData m = redAndBlue(Vec3(0, 0, 0.5), 0.5, o);
    // Draw order must not matter: try both.
    for (int order = 0; order < 2; ++order) {
        if (order == 1) std::swap(m.triangles[0], m.triangles[2]), std::swap(m.triangles[1], m.triangles[3]);
        const auto im = preview::render(m, o);
        EXPECT_GT(pixel(im, 32, 32)[2], 100) << order;
        EXPECT_EQ(pixel(im, 32, 32)[0], 0) << order;
        EXPECT_GT(pixel(im, 4, 32)[0], 100) << order; // the back square around it
    }
}

TEST(Preview, WireframeDrawsEdges) {
    const MeshData m = square(0.0, 1.0);
    preview::RenderOptions o;
    o.width = o.height = 65;
    o.wireframe = true;
    o.wireColour = Vec3(0, 1, 0);
    const auto im = preview::render(m, o);
    // The diagonal from (-1,-1) to (1,1) crosses the image centre.
    EXPECT_GT(pixel(im, 32, 32)[1], 200);
    o.wireframe = false;
    EXPECT_LT(preview::render(m, o).rgba[(32 * 65 + 32) * 4 + 1], 230);
}

TEST(Preview, ContactSheetLabelsEachCell) {
    preview::RenderOptions o;
    o.width = o.height = 50;
    const auto im = preview::render(square(0, 1), o);
    const auto plain = preview::contactSheet({im, im}, 2);
    const auto labelled = preview::contactSheet({im, im}, 2, {"aa", "PP"});
    // The label pixels are in the top-left corner of each cell; the rest is unchanged.
    int changedLeft = 0, changedRight = 0;
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 100; ++x)
            if (std::memcmp(pixel(plain, x, y), pixel(labelled, x, y), 4) != 0) {
                EXPECT_LT(y, 20);
                EXPECT_LT(x % 50, 30);
                ++(x < 50 ? changedLeft : changedRight);
            }
    EXPECT_GT(changedLeft, 5);
    EXPECT_GT(changedRight, 5);
    EXPECT_THROW(preview::contactSheet({im, im}, 2, {"one"}), InputError);
}

TEST(Preview, FocusFramesASphereInsteadOfTheMesh) {
    // A red square at the origin and a blue one far to its right: the whole mesh shows both small;
    // a focus on the blue one fills the image with it and leaves the red one out.
    preview::RenderOptions o;
    const MeshData m = redAndBlue(Vec3(20, 0, 0), 1.0, o);
    const auto count = [](const preview::Image& im, int channel) {
        int n = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) n += pixel(im, x, y)[channel] > 100 ? 1 : 0;
        return n;
    };
    const auto whole = preview::render(m, o);
    EXPECT_GT(count(whole, 0), 0);
    EXPECT_LT(count(whole, 2), 64 * 64 / 10);
    o.focusCentre = Vec3(20, 0, 0);
    o.focusRadius = 1.0;
    const auto close = preview::render(m, o);
    EXPECT_EQ(count(close, 0), 0);
    // The square's half side is the focus radius: it covers nearly all of the image.
    EXPECT_GT(count(close, 2), 64 * 64 / 2);
    EXPECT_GT(pixel(close, 32, 32)[2], 100);
}

TEST(Preview, RejectsBadInput) {
    preview::RenderOptions o;
    EXPECT_THROW(preview::render(MeshData{}, o), InputError);
    o.width = 0;
    EXPECT_THROW(preview::render(square(0, 1), o), InputError);
    o.width = 10;
    o.vertexColours.resize(3);
    EXPECT_THROW(preview::render(square(0, 1), o), InputError);
}

TEST(Preview, WritesAPngThatReadsBack) {
    preview::RenderOptions o;
    o.width = 40;
    o.height = 30;
    const auto im = preview::render(square(0, 1), o);
    const auto sheet = preview::contactSheet({im, im, im}, 2);
    EXPECT_EQ(sheet.width, 80);
    EXPECT_EQ(sheet.height, 60);
    const auto path = std::filesystem::temp_directory_path() /
                      ("visemelab_preview_test_" + std::to_string(::getpid()) + ".png");
    preview::writePng(path, sheet);
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(w, 80);
    EXPECT_EQ(h, 60);
    EXPECT_EQ(std::memcmp(data, sheet.rgba.data(), sheet.rgba.size()), 0);
    stbi_image_free(data);
    std::filesystem::remove(path);
}

} // namespace
} // namespace vl
