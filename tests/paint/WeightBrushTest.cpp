#include "core/paint/WeightBrush.h"
#include "PaintMeshes.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

using test::grid;

TEST(WeightBrush, FootprintMatchesTheDefinitionVertexByVertex) {
    const MeshData mesh = grid(15);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-7.0, 7.0);
    for (int trial = 0; trial < 50; ++trial) {
        WeightBrush brush;
        brush.radius = 0.5 + std::abs(coordinate(rng)) / 2.0;
        brush.strength = 0.7;
        brush.falloff = static_cast<Falloff>(trial % 4);
        const Vec3 centre(coordinate(rng), coordinate(rng) + 7.0, 0.0);
        const auto footprint = brushFootprint(PaintSurface(mesh.positions, mesh.triangles), brush, centre);
        std::size_t next = 0;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const double d = (mesh.positions[v] - centre).norm();
            const double expected =
                d < brush.radius ? 0.7 * falloffWeight(brush.falloff, d / brush.radius) : 0.0;
            if (expected > 0.0) {
                ASSERT_LT(next, footprint.size());
                EXPECT_EQ(footprint[next].first, v);
                EXPECT_DOUBLE_EQ(footprint[next].second, expected);
                ++next;
            }
        }
        EXPECT_EQ(next, footprint.size());
    }
}

TEST(WeightBrush, SymmetricDabMirrorsAcrossThePlane) {
    const MeshData mesh = grid(11); // x in [-5, 5]
    WeightBrush brush;
    brush.radius = 1.5;
    brush.symmetric = true;
    std::vector<double> weights(mesh.positions.size(), 0.0);
    applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(-3.0, 5.0, 0.0), weights);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3& p = mesh.positions[v];
        for (std::size_t w = 0; w < mesh.positions.size(); ++w)
            if (mesh.positions[w][0] == -p[0] && mesh.positions[w][1] == p[1]) {
                EXPECT_DOUBLE_EQ(weights[v], weights[w]);
            }
    }
    EXPECT_GT(weights[5 * 11 + 2], 0.0); // (-3, 5)
    EXPECT_GT(weights[5 * 11 + 8], 0.0); // (3, 5)
}

TEST(WeightBrush, AddAndSubtractStayInUnitRange) {
    const MeshData mesh = grid(7);
    WeightBrush brush;
    brush.radius = 2.0;
    brush.strength = 1.0;
    std::vector<double> weights(mesh.positions.size(), 0.9);
    for (int i = 0; i < 3; ++i) applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(0, 3, 0), weights);
    for (double w : weights) EXPECT_LE(w, 1.0);
    EXPECT_DOUBLE_EQ(weights[3 * 7 + 3], 1.0);
    brush.mode = BrushMode::Subtract;
    for (int i = 0; i < 3; ++i) applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(0, 3, 0), weights);
    for (double w : weights) EXPECT_GE(w, 0.0);
    EXPECT_DOUBLE_EQ(weights[3 * 7 + 3], 0.0);
    EXPECT_DOUBLE_EQ(weights[0], 0.9); // outside the brush
}

TEST(WeightBrush, SmoothMovesTowardsTheNeighbourMean) {
    const MeshData mesh = grid(5);
    std::vector<double> weights(mesh.positions.size(), 0.0);
    weights[2 * 5 + 2] = 1.0; // a spike in the middle
    WeightBrush brush;
    brush.radius = 0.5;
    brush.strength = 1.0;
    brush.falloff = Falloff::Linear;
    brush.mode = BrushMode::Smooth;
    applyBrushDab(mesh.positions, mesh.triangles, brush, mesh.positions[12], weights);
    EXPECT_DOUBLE_EQ(weights[12], 0.0); // full strength at the centre: the neighbours' mean
    EXPECT_DOUBLE_EQ(weights[11], 0.0); // outside the radius: untouched
}

TEST(WeightBrush, BadBrushOrSizeIsAnInputError) {
    const MeshData mesh = grid(3);
    std::vector<double> weights(mesh.positions.size(), 0.0);
    WeightBrush brush;
    brush.radius = 0.0;
    EXPECT_THROW(applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(0, 0, 0), weights), InputError);
    brush.radius = 1.0;
    brush.strength = 2.0;
    EXPECT_THROW(applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(0, 0, 0), weights), InputError);
    brush.strength = 0.5;
    std::vector<double> wrongSize(2, 0.0);
    EXPECT_THROW(applyBrushDab(mesh.positions, mesh.triangles, brush, Vec3(0, 0, 0), wrongSize), InputError);
}

} // namespace
} // namespace vl
