// The box selection's occlusion test (core/paint/VertexVisibility.h) against its definition tested
// the slow obvious way: every vertex against every triangle.
#include "core/paint/VertexVisibility.h"
#include "PaintMeshes.h"
#include "core/common/Error.h"
#include "core/paint/PaintRegions.h"
#include "core/paint/RayPick.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <numeric>
#include <random>

namespace vl {
namespace {

using test::grid;
using test::sphere;

template <class Matrix> std::array<double, 16> toArray(const Matrix& m) {
    std::array<double, 16> out{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[static_cast<std::size_t>(4 * c + r)] = static_cast<double>(m[c][r]);
    return out;
}

std::array<double, 16> camera(const glm::dvec3& eye, const glm::dvec3& target, double fov, double aspect) {
    return toArray(glm::perspective(fov, aspect, 0.01, 100.0) *
                   glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
}

// The definition: hidden when a triangle without the vertex crosses the segment eye -> vertex short of it.
std::vector<std::uint32_t> seenByBruteForce(const MeshData& mesh, const Vec3& eye) {
    std::vector<std::uint32_t> seen;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3 towards = mesh.positions[v] - eye;
        const double distance = towards.norm();
        bool hidden = false;
        for (const Triangle& t : mesh.triangles) {
            if (t[0] == v || t[1] == v || t[2] == v) continue;
            const auto hit = intersectTriangle(mesh.positions[t[0]], mesh.positions[t[1]],
                                               mesh.positions[t[2]], eye, towards / distance);
            hidden = hidden || (hit && hit->distance > 0.0 && hit->distance < distance * (1.0 - 1e-6));
        }
        if (!hidden) seen.push_back(v);
    }
    return seen;
}

std::vector<std::uint32_t> everyVertex(const MeshData& mesh) {
    std::vector<std::uint32_t> all(mesh.positions.size());
    std::iota(all.begin(), all.end(), 0u);
    return all;
}

// A sheet facing the camera hides a second one behind it that faces the camera too: the facing
// test alone would select both.
TEST(VertexVisibility, ASheetHidesTheSheetBehindIt) {
    MeshData mesh = grid(9);
    const MeshData lower = grid(9);
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    for (const Vec3& p : lower.positions) mesh.positions.emplace_back(p[0], p[1], -0.5);
    for (const Triangle& t : lower.triangles)
        mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const PaintSurface surface(mesh.positions, mesh.triangles);
    const glm::dvec3 eye(0.0, 4.0, 12.0);
    const auto vp = camera(eye, glm::dvec3(0.0, 4.0, 0.0), 0.9, 1.0);
    const Vec3 eyeV(eye.x, eye.y, eye.z);
    const auto facing = verticesInRectangle(surface, vp, {-1, -1, 1, 1}, eyeV);
    EXPECT_EQ(facing.size(), mesh.positions.size()) << "both sheets face the camera";
    const auto seen = visibleVertices(surface, facing, vp, eyeV);
    ASSERT_EQ(seen.size(), static_cast<std::size_t>(offset));
    for (std::uint32_t v = 0; v < offset; ++v) EXPECT_EQ(seen[v], v);
    // Seen from below the lower sheet's plane... from the side, past the sheets' edge, both show.
    const glm::dvec3 side(20.0, 4.0, -0.25);
    const auto fromSide =
        visibleVertices(surface, everyVertex(mesh), camera(side, glm::dvec3(0, 4, -0.25), 0.9, 1.0),
                        Vec3(side.x, side.y, side.z));
    EXPECT_EQ(fromSide, seenByBruteForce(mesh, Vec3(side.x, side.y, side.z)));
    EXPECT_THROW(
        VertexVisibility(surface, vp, eyeV).visible(static_cast<std::uint32_t>(mesh.positions.size())),
        InputError);
}

// On a closed convex surface the eye sees exactly the vertices facing it (away from the silhouette).
TEST(VertexVisibility, ASphereShowsItsFacingHalf) {
    const MeshData mesh = sphere(24, 32);
    const PaintSurface surface(mesh.positions, mesh.triangles);
    const glm::dvec3 eye(1.5, 2.0, 5.0);
    const Vec3 eyeV(eye.x, eye.y, eye.z);
    const auto vp = camera(eye, glm::dvec3(0.0), 0.8, 1.3);
    const auto seen = visibleVertices(surface, everyVertex(mesh), vp, eyeV);
    std::vector<char> isSeen(mesh.positions.size(), 0);
    for (const std::uint32_t v : seen) isSeen[v] = 1;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3& p = mesh.positions[v];
        const double facing = OpenMesh::dot(surface.normals()[v], (eyeV - p).normalized());
        if (facing > 0.1) {
            EXPECT_TRUE(isSeen[v]) << "vertex " << v;
        }
        if (facing < -0.1) {
            EXPECT_FALSE(isSeen[v]) << "vertex " << v;
        }
    }
}

// Random meshes (spheres, triangle soups around and through the eye) seen from random cameras, in
// double and in float matrices (the editor's): the binned test agrees with the brute force exactly.
TEST(VertexVisibility, AgreesWithBruteForceOnRandomScenes) {
    std::mt19937 random(14);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        MeshData mesh;
        if (trial % 2 == 0) {
            mesh = sphere(6 + trial % 7, 8 + trial % 5);
            for (Vec3& p : mesh.positions) p = p * (0.5 + 0.5 * (unit(random) + 1.0)); // bumpy
        } else {
            const int triangles = 30 + trial * 5;
            for (int f = 0; f < triangles; ++f) {
                const Vec3 centre(2.0 * unit(random), 2.0 * unit(random), 2.0 * unit(random));
                for (int k = 0; k < 3; ++k)
                    mesh.positions.push_back(centre + Vec3(unit(random), unit(random), unit(random)) * 0.7);
                const auto base = static_cast<std::uint32_t>(3 * f);
                mesh.triangles.push_back({base, base + 1, base + 2});
            }
        }
        const PaintSurface surface(mesh.positions, mesh.triangles);
        const double radius =
            trial % 4 == 1 ? 0.5 : 2.0 + 4.0 * (unit(random) + 1.0); // some eyes inside the soup
        glm::dvec3 direction(unit(random), unit(random), unit(random));
        direction = glm::normalize(direction + glm::dvec3(0.0, 0.0, 0.01));
        const glm::dvec3 eye = direction * radius;
        const glm::dvec3 target(0.3 * unit(random), 0.3 * unit(random), 0.3 * unit(random));
        const double fov = 0.4 + 0.5 * (unit(random) + 1.0), aspect = 1.0 + 0.5 * unit(random);
        const Vec3 eyeV(eye.x, eye.y, eye.z);
        const auto expected = seenByBruteForce(mesh, eyeV);
        EXPECT_EQ(visibleVertices(surface, everyVertex(mesh), camera(eye, target, fov, aspect), eyeV),
                  expected)
            << "trial " << trial;
        const glm::mat4 single =
            glm::perspective(static_cast<float>(fov), static_cast<float>(aspect), 0.01f, 100.0f) *
            glm::lookAt(glm::vec3(eye), glm::vec3(target), glm::vec3(0, 1, 0));
        EXPECT_EQ(visibleVertices(surface, everyVertex(mesh), toArray(single), eyeV), expected)
            << "trial " << trial << " (float matrix)";
    }
}

} // namespace
} // namespace vl
