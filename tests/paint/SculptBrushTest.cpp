// The sculpt brushes against their definitions (core/paint/SculptBrush.h), vertex by vertex.
#include "core/paint/SculptBrush.h"
#include "PaintMeshes.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

using test::grid;

struct Sculpted {
    MeshData neutral = grid(11); // x in [-5, 5], y in [0, 10], z = 0: normals along z
    std::vector<Vec3> shape = neutral.positions;
    PaintSurface surface() const { return PaintSurface(shape, neutral.triangles); }
    void dab(const SculptDab& dab, const Vec3& centre) {
        applySculptDab(surface(), neutral.positions, dab, centre, shape);
    }
};

SculptDab dabOf(SculptTool tool, double radius = 2.0, double strength = 0.5) {
    SculptDab dab;
    dab.tool = tool;
    dab.brush.radius = radius;
    dab.brush.strength = strength;
    return dab;
}

TEST(SculptBrush, GrabMovesEveryVertexInReachByItsFactorTimesTheMotion) {
    Sculpted s;
    SculptDab dab = dabOf(SculptTool::Grab);
    dab.grab = Vec3(0.0, 0.0, 1.0);
    const Vec3 centre(-2.0, 5.0, 0.0);
    const auto footprint = brushFootprint(s.surface(), dab.brush, centre);
    s.dab(dab, centre);
    std::vector<double> factor(s.shape.size(), 0.0);
    for (const auto& [v, f] : footprint) factor[v] = f;
    for (std::size_t v = 0; v < s.shape.size(); ++v)
        EXPECT_DOUBLE_EQ((s.shape[v] - s.neutral.positions[v])[2], factor[v]) << v;
    const std::uint32_t middle = PaintSurface(s.neutral.positions, s.neutral.triangles).nearestVertex(centre);
    EXPECT_DOUBLE_EQ(s.shape[middle][2], 0.5); // the centre vertex: strength x falloff(0)
}

TEST(SculptBrush, AMirroredGrabIsTheMirrorImage) {
    Sculpted s;
    SculptDab dab = dabOf(SculptTool::Grab);
    dab.brush.symmetric = true; // mirror plane x = 0 (the grid's middle)
    dab.grab = Vec3(0.7, 0.2, 1.0);
    s.dab(dab, Vec3(-3.0, 4.0, 0.0));
    for (std::size_t v = 0; v < s.shape.size(); ++v) {
        const Vec3& p = s.neutral.positions[v];
        const std::uint32_t w = s.surface().nearestVertex(Vec3(-p[0], p[1], p[2]));
        const Vec3 d = s.shape[v] - p, e = s.shape[w] - s.neutral.positions[w];
        EXPECT_NEAR(d[0], -e[0], 1e-12) << v;
        EXPECT_NEAR(d[1], e[1], 1e-12) << v;
        EXPECT_NEAR(d[2], e[2], 1e-12) << v;
    }
    EXPECT_GT((s.shape[s.surface().nearestVertex(Vec3(3.0, 4.0, 0.0))] - Vec3(3.0, 4.0, 0.0)).norm(), 0.4);
}

TEST(SculptBrush, InflateAndDeflateMoveAlongTheNormalByATenthOfTheRadius) {
    for (const SculptTool tool : {SculptTool::Inflate, SculptTool::Deflate}) {
        Sculpted s;
        const Vec3 centre(0.0, 5.0, 0.0);
        const std::uint32_t middle = s.surface().nearestVertex(centre);
        const Vec3 normal = s.surface().normals()[middle];
        s.dab(dabOf(tool, 2.0, 1.0), centre);
        const double sign = tool == SculptTool::Inflate ? 1.0 : -1.0;
        EXPECT_NEAR(OpenMesh::dot(s.shape[middle] - s.neutral.positions[middle], normal), sign * 0.2, 1e-12);
        EXPECT_EQ(s.shape[s.surface().nearestVertex(Vec3(4.0, 9.0, 0.0))],
                  Vec3(4.0, 9.0, 0.0)); // out of reach
    }
}

TEST(SculptBrush, SmoothMovesTheDisplacementTowardsItsNeighboursMean) {
    Sculpted s;
    const std::uint32_t spike = s.surface().nearestVertex(Vec3(0.0, 5.0, 0.0));
    s.shape[spike][2] = 1.0; // one vertex raised: a spike in the displacement
    const double before = s.shape[spike][2];
    s.dab(dabOf(SculptTool::Smooth, 2.0, 1.0), s.shape[spike]); // the brush on the spike's tip
    EXPECT_NEAR(s.shape[spike][2], 0.0, 1e-12); // full strength at the centre: the neighbours' mean, 0
    EXPECT_LT(s.shape[spike][2], before);
    // Its neighbours rose towards the spike's old displacement (read before the dab).
    const PaintSurface after = s.surface(); // kept alive: neighbours() is a view into it
    for (const std::uint32_t w : after.neighbours(spike)) EXPECT_GT(s.shape[w][2], 0.0);
}

TEST(SculptBrush, SmoothingKeepsADisplacementThatIsAlreadySmooth) {
    Sculpted s;
    for (auto& p : s.shape) p[2] += 0.3; // the whole face moved out: smooth displacement
    const auto before = s.shape;
    s.dab(dabOf(SculptTool::Smooth, 3.0, 1.0), Vec3(0.0, 5.0, 0.3));
    for (std::size_t v = 0; v < before.size(); ++v) EXPECT_NEAR((s.shape[v] - before[v]).norm(), 0.0, 1e-12);
}

TEST(SculptBrush, MismatchedSizesAndBadBrushesAreRefused) {
    Sculpted s;
    std::vector<Vec3> shorter(s.shape.begin(), s.shape.end() - 1);
    EXPECT_THROW(
        applySculptDab(s.surface(), s.neutral.positions, dabOf(SculptTool::Grab), Vec3(0, 5, 0), shorter),
        InputError);
    EXPECT_THROW(s.dab(dabOf(SculptTool::Grab, 0.0), Vec3(0, 5, 0)), InputError);
    EXPECT_THROW(s.dab(dabOf(SculptTool::Grab, 1.0, 1.5), Vec3(0, 5, 0)), InputError);
}

} // namespace
} // namespace vl
