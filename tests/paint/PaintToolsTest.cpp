// The paint tool's core: front-faces-only dabs, region fill, box selection, the weight readout and
// brush radii in pixels or % of the head, each against a brute-force reading of its definition.
#include "PaintMeshes.h"
#include "core/common/Error.h"
#include "core/paint/BrushRadius.h"
#include "core/paint/PaintRegions.h"
#include "core/paint/WeightBrush.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <random>
#include <set>

namespace vl {
namespace {

using test::grid;
using test::sphere;
using test::twoSheets;

// Whether b is joined to a by triangle edges through vertices that all satisfy `allowed`: the
// closure computed by sweeping the triangle list until nothing changes (no neighbour lists).
template <class Allowed>
std::vector<char> reachableBySweeping(const MeshData& mesh, std::uint32_t seed, const Allowed& allowed) {
    std::vector<char> reached(mesh.positions.size(), 0);
    if (!allowed(seed)) return reached;
    reached[seed] = 1;
    for (bool changed = true; changed;) {
        changed = false;
        for (const Triangle& t : mesh.triangles)
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) {
                    const std::uint32_t from = t[static_cast<std::size_t>(a)],
                                        to = t[static_cast<std::size_t>(b)];
                    if (reached[from] && !reached[to] && allowed(to)) {
                        reached[to] = 1;
                        changed = true;
                    }
                }
    }
    return reached;
}

std::uint32_t nearestByScan(const MeshData& mesh, const Vec3& p) {
    std::uint32_t best = 0;
    for (std::uint32_t v = 1; v < mesh.positions.size(); ++v)
        if ((mesh.positions[v] - p).sqrnorm() < (mesh.positions[best] - p).sqrnorm()) best = v;
    return best;
}

TEST(PaintSurface, NeighboursAreTheEdgeNeighboursOnce) {
    const MeshData mesh = sphere(6, 9);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::set<std::uint32_t> expected;
        for (const Triangle& t : mesh.triangles)
            if (std::find(t.begin(), t.end(), v) != t.end())
                for (const std::uint32_t w : t)
                    if (w != v) expected.insert(w);
        const auto got = surface.neighbours(v);
        EXPECT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()),
                  std::vector<std::uint32_t>(expected.begin(), expected.end()))
            << "vertex " << v;
    }
    EXPECT_NEAR(surface.size(), 2.0, 0.05);
    EXPECT_EQ(surface.nearestVertex(Vec3(0, 5, 0)), 0u);
    EXPECT_THROW(PaintSurface(mesh.positions, std::vector<Triangle>{{0, 1, 999}}), InputError);
}

// Front faces only, against its definition: in the ball, facing the eye on the seed's side, joined
// to the seed through such vertices. Random dabs on a sphere seen from random eyes.
TEST(FrontFacesBrush, FootprintMatchesTheDefinitionOnASphere) {
    const MeshData mesh = sphere(14, 20);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    const auto normals = vertexNormals(mesh.positions, mesh.triangles);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int nonEmpty = 0;
    for (int trial = 0; trial < 60; ++trial) {
        WeightBrush brush;
        brush.radius = 0.2 + 1.6 * std::abs(u(rng)); // up to beyond the whole sphere
        brush.strength = 1.0;
        brush.falloff = Falloff::Linear;
        Vec3 eye(u(rng), u(rng), u(rng));
        eye = eye.normalized() * 4.0;
        brush.eye = eye;
        const Vec3 centre = mesh.positions[static_cast<std::size_t>(std::abs(u(rng)) * 200.0)];
        const auto footprint = brushFootprint(surface, brush, centre);
        const std::uint32_t seed = nearestByScan(mesh, centre);
        const double side = OpenMesh::dot(normals[seed], eye - mesh.positions[seed]) >= 0 ? 1.0 : -1.0;
        const auto reached = reachableBySweeping(mesh, seed, [&](std::uint32_t v) {
            return (mesh.positions[v] - centre).norm() < brush.radius &&
                   side * OpenMesh::dot(normals[v], eye - mesh.positions[v]) > 0.0;
        });
        std::vector<std::uint32_t> expected;
        for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
            if (reached[v] &&
                falloffWeight(Falloff::Linear, (mesh.positions[v] - centre).norm() / brush.radius) > 0)
                expected.push_back(v);
        std::vector<std::uint32_t> got;
        for (const auto& [v, factor] : footprint) {
            got.push_back(v);
            EXPECT_DOUBLE_EQ(
                factor, falloffWeight(Falloff::Linear, (mesh.positions[v] - centre).norm() / brush.radius));
        }
        EXPECT_EQ(got, expected) << "trial " << trial;
        nonEmpty += got.empty() ? 0 : 1;
        // Nothing on the far side of the sphere, whatever the radius.
        for (const std::uint32_t v : got)
            EXPECT_GT(side * OpenMesh::dot(normals[v], eye - mesh.positions[v]), 0.0);
    }
    EXPECT_GT(nonEmpty, 30);
}

TEST(FrontFacesBrush, ABigDabOnTheFrontLeavesTheBackAlone) {
    const MeshData mesh = sphere(16, 24);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    WeightBrush brush;
    brush.radius = 3.0; // the whole sphere is in reach
    brush.strength = 1.0;
    brush.falloff = Falloff::Linear;
    std::vector<double> everywhere(mesh.positions.size(), 0.0), front = everywhere;
    applyBrushDab(surface, brush, Vec3(0, 0, 1), everywhere);
    brush.eye = Vec3(0, 0, 5);
    applyBrushDab(surface, brush, Vec3(0, 0, 1), front);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (mesh.positions[v][2] < -0.05) {
            EXPECT_GT(everywhere[v], 0.0) << "without front faces only, the dab reaches the back";
            EXPECT_EQ(front[v], 0.0) << "vertex " << v << " on the back was painted";
        }
        if (mesh.positions[v][2] > 0.5) {
            EXPECT_GT(front[v], 0.0);
        }
    }
}

TEST(FrontFacesBrush, NoBleedAcrossAGapNorOnAnInsideOutMesh) {
    // Two sheets 0.2 apart: a dab of radius 1 on the upper one reaches the lower one in space only.
    const MeshData mesh = twoSheets(9);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    const std::size_t half = mesh.positions.size() / 2;
    WeightBrush brush;
    brush.radius = 1.0;
    brush.strength = 1.0;
    brush.eye = Vec3(0, 4, 5);
    std::vector<double> weights(mesh.positions.size(), 0.0);
    applyBrushDab(surface, brush, Vec3(0, 4, 0), weights);
    for (std::size_t v = half; v < weights.size(); ++v) EXPECT_EQ(weights[v], 0.0);
    EXPECT_GT(weights[4 * 9 + 4], 0.0);
    // The same mesh wound inside out paints the same vertices (the side under the brush decides).
    MeshData flipped = mesh;
    for (Triangle& t : flipped.triangles) std::swap(t[1], t[2]);
    std::vector<double> again(mesh.positions.size(), 0.0);
    applyBrushDab(PaintSurface(flipped.positions, flipped.triangles), brush, Vec3(0, 4, 0), again);
    EXPECT_EQ(again, weights);
}

TEST(FrontFacesBrush, SymmetricDabSeesFromTheMirroredEye) {
    const MeshData mesh = sphere(16, 24);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    WeightBrush brush;
    brush.radius = 0.6;
    brush.strength = 1.0;
    brush.symmetric = true;
    brush.eye = Vec3(3, 0, 3); // looking at the +x side
    std::vector<double> weights(mesh.positions.size(), 0.0);
    applyBrushDab(surface, brush, Vec3(0.7071, 0, 0.7071), weights);
    double left = 0.0, right = 0.0;
    for (std::size_t v = 0; v < weights.size(); ++v) (mesh.positions[v][0] < 0 ? left : right) += weights[v];
    EXPECT_GT(right, 0.0);
    EXPECT_NEAR(left, right, 1e-9 * right);
}

TEST(RegionFill, MatchesTheSweptClosure) {
    const MeshData mesh = grid(12);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<double> values(mesh.positions.size());
        for (double& v : values) v = std::round(u(rng) * 3.0) / 3.0; // plateaus of equal value
        const auto seed = static_cast<std::uint32_t>(u(rng) * static_cast<double>(values.size() - 1));
        const double tolerance = trial % 3 == 0 ? 0.0 : u(rng) * 0.5;
        const auto region = connectedRegion(surface, values, seed, tolerance);
        const auto reached = reachableBySweeping(
            mesh, seed, [&](std::uint32_t v) { return std::abs(values[v] - values[seed]) <= tolerance; });
        std::vector<std::uint32_t> expected;
        for (std::uint32_t v = 0; v < values.size(); ++v)
            if (reached[v]) expected.push_back(v);
        EXPECT_EQ(region, expected) << "trial " << trial;
    }
}

TEST(RegionFill, WholePartWithFullToleranceAndErrors) {
    const MeshData mesh = twoSheets(5);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    std::vector<double> values(mesh.positions.size(), 0.3);
    values[3] = 0.9;
    const auto region = connectedRegion(surface, values, 0, 1.0);
    EXPECT_EQ(region.size(), 25u); // the upper sheet only: the lower one is another part
    const auto filledValues = filled(values, region, 0.75);
    EXPECT_EQ(filledValues[3], 0.75);
    EXPECT_EQ(filledValues[30], 0.3);
    EXPECT_THROW(connectedRegion(surface, values, 999, 0.1), InputError);
    EXPECT_THROW(connectedRegion(surface, values, 0, -0.1), InputError);
    EXPECT_THROW(connectedRegion(surface, std::vector<double>(3, 0.0), 0, 0.1), InputError);
    EXPECT_THROW(filled(values, std::vector<std::uint32_t>{999}, 1.0), InputError);
}

std::array<double, 16> toArray(const glm::mat4& m) {
    std::array<double, 16> out{};
    const float* p = glm::value_ptr(m);
    for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(i)] = p[i];
    return out;
}

// Box selection against glm's own projection of each vertex.
TEST(BoxSelection, MatchesGlmProjectionAndSkipsTheBack) {
    const MeshData mesh = sphere(12, 18);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    const auto normals = vertexNormals(mesh.positions, mesh.triangles);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 30; ++trial) {
        const glm::vec3 eye = glm::normalize(glm::vec3(u(rng), u(rng), u(rng) + 0.01)) * 4.0f;
        const glm::mat4 vp =
            glm::perspective(0.6f, 1.5f, 0.1f, 100.0f) * glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
        const NdcRectangle box{u(rng), u(rng), u(rng), u(rng)};
        const Vec3 eyeV(eye.x, eye.y, eye.z);
        auto all = verticesInRectangle(surface, toArray(vp), box);
        auto front = verticesInRectangle(surface, toArray(vp), box, eyeV);
        std::vector<std::uint32_t> expectedAll, expectedFront;
        for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
            const Vec3& p = mesh.positions[v];
            const glm::vec4 clip = vp * glm::vec4(p[0], p[1], p[2], 1.0);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            const bool in = clip.w > 0 && ndc.x >= std::min(box.x0, box.x1) &&
                            ndc.x <= std::max(box.x0, box.x1) && ndc.y >= std::min(box.y0, box.y1) &&
                            ndc.y <= std::max(box.y0, box.y1);
            // Vertices on the box's edge may round either way in float: leave them out of the check.
            const double margin = 1e-4;
            const bool onEdge = std::abs(ndc.x - box.x0) < margin || std::abs(ndc.x - box.x1) < margin ||
                                std::abs(ndc.y - box.y0) < margin || std::abs(ndc.y - box.y1) < margin;
            if (onEdge) {
                std::erase(all, v);
                std::erase(front, v);
                continue;
            }
            if (!in) continue;
            expectedAll.push_back(v);
            if (OpenMesh::dot(normals[v], eyeV - p) > 0) expectedFront.push_back(v);
        }
        EXPECT_EQ(all, expectedAll) << "trial " << trial;
        EXPECT_EQ(front, expectedFront) << "trial " << trial;
    }
    // The whole screen from the front: the front half of the sphere, not the back.
    const glm::mat4 vp = glm::perspective(0.6f, 1.0f, 0.1f, 100.0f) *
                         glm::lookAt(glm::vec3(0, 0, 6), glm::vec3(0), glm::vec3(0, 1, 0));
    const auto front = verticesInRectangle(surface, toArray(vp), {-1, -1, 1, 1}, Vec3(0, 0, 6));
    for (const std::uint32_t v : front) EXPECT_GT(mesh.positions[v][2], -0.01);
    EXPECT_GT(front.size(), mesh.positions.size() / 3);
    // Inside out: the same front when told the mesh is flipped.
    MeshData flippedMesh = mesh;
    for (Triangle& t : flippedMesh.triangles) std::swap(t[1], t[2]);
    const PaintSurface flipped(flippedMesh.positions, flippedMesh.triangles);
    EXPECT_TRUE(facesAwayAt(flipped, Vec3(0, 0, 1), Vec3(0, 0, 6)));
    EXPECT_FALSE(facesAwayAt(surface, Vec3(0, 0, 1), Vec3(0, 0, 6)));
    EXPECT_EQ(verticesInRectangle(flipped, toArray(vp), {-1, -1, 1, 1}, Vec3(0, 0, 6), true), front);
}

TEST(WeightReadout, InterpolatesTheCornersAndChecksItsInput) {
    const MeshData mesh = grid(3);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    std::vector<double> values(9, 0.0);
    const Triangle& t = mesh.triangles[0];
    values[t[0]] = 0.2;
    values[t[1]] = 0.6;
    values[t[2]] = 1.0;
    EXPECT_DOUBLE_EQ(valueAt(surface, values, 0, Vec3(1, 0, 0)), 0.2);
    EXPECT_NEAR(valueAt(surface, values, 0, Vec3(0.5, 0.25, 0.25)), 0.1 + 0.15 + 0.25, 1e-12);
    EXPECT_THROW(valueAt(surface, values, 99, Vec3(1, 0, 0)), InputError);
    EXPECT_THROW(valueAt(surface, std::vector<double>(2, 0.0), 0, Vec3(1, 0, 0)), InputError);
}

TEST(BrushRadius, PixelsFollowTheZoomPercentFollowsTheHead) {
    // 600 px tall view, 90 degrees: the visible height at depth 3 is 6 units, so 1 px = 0.01.
    const double perPixel = modelUnitsPerPixel(3.0, std::numbers::pi / 2.0, 600.0);
    EXPECT_NEAR(perPixel, 0.01, 1e-12);
    EXPECT_NEAR(modelRadius({40.0, RadiusUnit::ScreenPixels}, 0.25, perPixel), 0.4, 1e-12);
    EXPECT_NEAR(modelRadius({40.0, RadiusUnit::ScreenPixels}, 0.25, 2.0 * perPixel), 0.8, 1e-12);
    EXPECT_NEAR(modelRadius({10.0, RadiusUnit::PercentOfHead}, 0.25, perPixel), 0.025, 1e-12);
    EXPECT_NEAR(modelRadius({10.0, RadiusUnit::PercentOfHead}, 0.25, 5.0 * perPixel), 0.025, 1e-12);
    EXPECT_THROW(modelUnitsPerPixel(0.0, 1.0, 600.0), InputError);
    EXPECT_THROW(modelUnitsPerPixel(1.0, 4.0, 600.0), InputError);
    EXPECT_THROW(modelUnitsPerPixel(1.0, 1.0, 0.0), InputError);
    EXPECT_THROW(modelRadius({0.0, RadiusUnit::ScreenPixels}, 1.0, 1.0), InputError);
    EXPECT_THROW(modelRadius({5.0, RadiusUnit::PercentOfHead}, 0.0, 1.0), InputError);
    EXPECT_EQ(radiusUnitName(RadiusUnit::PercentOfHead), "% of head");
}

} // namespace
} // namespace vl
