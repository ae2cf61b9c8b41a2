// The vertices GpuSurface draws (ui/render/SeamSplit.h) against the definition: every corner draws
// its own (mesh vertex, texture coordinate) pair, and no pair is drawn twice (a std::set counts them).
#include "ui/render/SeamSplit.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

namespace vl::ui {
namespace {

void expectDefinition(const std::vector<Triangle>& triangles, const SurfaceLayout& layout,
                      const SeamSplit& split) {
    ASSERT_EQ(split.indices.size(), 3 * triangles.size());
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t drawn = split.indices[3 * t + k];
            const std::uint32_t c = layout.cornerTexCoords.empty() ? 0 : layout.cornerTexCoords[t][k];
            EXPECT_EQ(split.source.at(drawn), triangles[t][k]) << "triangle " << t << " corner " << k;
            EXPECT_EQ(split.texCoord.at(drawn), c) << "triangle " << t << " corner " << k;
            pairs.emplace(triangles[t][k], c);
        }
    EXPECT_EQ(split.source.size(), pairs.size());
}

TEST(SeamSplit, OneTexCoordPerVertexDrawsEachVertexOnce) {
    const std::vector<Triangle> triangles = {{0, 1, 2}, {2, 1, 3}};
    SurfaceLayout layout;
    layout.texCoords = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)};
    layout.cornerTexCoords = triangles; // glTF: the triangles index both
    const SeamSplit split = splitAtSeams(triangles, 4, layout);
    expectDefinition(triangles, layout, split);
    EXPECT_EQ(split.source, (std::vector<std::uint32_t>{0, 1, 2, 3}));
}

TEST(SeamSplit, AVertexOnASeamIsDrawnOncePerTexCoord) {
    // Vertices 1 and 2 lie on a seam: the second triangle gives them other texture coordinates.
    const std::vector<Triangle> triangles = {{0, 1, 2}, {2, 1, 3}, {3, 1, 0}};
    SurfaceLayout layout;
    layout.texCoords = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(0.5, 0.5), Vec2(0.25, 0.25), Vec2(1, 1)};
    layout.cornerTexCoords = {{0, 1, 2}, {3, 4, 5}, {5, 1, 0}};
    const SeamSplit split = splitAtSeams(triangles, 4, layout);
    expectDefinition(triangles, layout, split);
    EXPECT_EQ(split.source.size(), 6u); // 0, 1, 2, then 2 and 1 again, 3
}

TEST(SeamSplit, WithoutTexCoordsEachVertexOnceAndBadInputRefused) {
    const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}};
    SurfaceLayout layout;
    expectDefinition(triangles, layout, splitAtSeams(triangles, 4, layout));
    EXPECT_THROW(splitAtSeams(triangles, 3, layout), std::invalid_argument); // vertex 3 of 3
    layout.texCoords = {Vec2(0, 0)};
    layout.cornerTexCoords = {{0, 0, 0}};
    EXPECT_THROW(splitAtSeams(triangles, 4, layout), std::invalid_argument); // one triangle's worth
    layout.cornerTexCoords = {{0, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(splitAtSeams(triangles, 4, layout), std::invalid_argument); // texture coordinate 1 of 1
}

} // namespace
} // namespace vl::ui
