#pragma once
// A user's mesh seen over its texture space, for building a deformable face from it (paper "Adaptive
// Deformable Models", section 6: any individual given on the (u,v) domain can be animated by the same
// cascade). Texture coordinates are kept per triangle corner, so UV seams stay seams; the mesh is cut
// into UV islands (triangles connected through edges whose two ends have the same (u,v) on both
// sides), and a locator finds the triangle under a texture-space point.
#include "core/io/MeshIO.h"
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vl::face {

struct UvMesh {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;    // position indices
    std::vector<Vec2> texCoords;        // texture-space points
    std::vector<Triangle> texTriangles; // texCoords indices, one per triangle
    std::vector<std::uint32_t> island;  // island index of each triangle
    std::size_t islandCount = 0;
    std::size_t droppedTriangles = 0; // triangles without texture coordinates (or degenerate in (u,v))
};

// The mesh with its per-corner texture coordinates (from readMesh(path, corners)). Triangles whose
// corners do not all have texture coordinates, or whose (u,v) triangle has no area, are dropped and
// counted. Throws InputError naming `source` when no triangle is left (no (u,v) on the mesh) or an
// index is out of range.
UvMesh makeUvMesh(const MeshData& mesh, const CornerTexCoords& corners, std::string_view source);
// The same for a mesh with one (u,v) per vertex (seams already split, as in glTF).
UvMesh makeUvMesh(const MeshData& mesh, std::string_view source);

struct UvIsland {
    std::size_t triangles = 0;
    double area = 0.0;   // 3D surface area
    double uvArea = 0.0; // texture-space area
    Vec2 uvMin{0, 0}, uvMax{0, 0};
};
std::vector<UvIsland> describeIslands(const UvMesh& mesh);

// A point of the mesh found from texture space: the triangle, its barycentric weights and the
// interpolated position.
struct UvHit {
    bool found = false;
    std::uint32_t triangle = 0;
    double b[3] = {0, 0, 0};
    Vec3 position{0, 0, 0};
};

// Point location in texture space over a chosen set of islands (a uniform grid of buckets over their
// (u,v) bounds). Where islands overlap in (u,v), the island listed first in `islands` wins; points
// that fall into a crack narrower than `tolerance` (in (u,v) units) snap to the nearest triangle.
class UvLocator {
  public:
    UvLocator(const UvMesh& mesh, std::span<const std::uint32_t> islands, double tolerance = 1e-6);
    UvHit locate(const Vec2& uv) const;

  private:
    const UvMesh* mesh_;
    std::vector<int> priority_; // per island: rank in `islands`, or -1 when not used
    Vec2 lo_{0, 0};
    double cell_ = 1.0;
    int nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> start_; // bucket b holds triangles_[start_[b] .. start_[b+1])
    std::vector<std::uint32_t> items_;
    double tolerance_;
};

// Barycentric weights of p in the (u,v) triangle (a, b, c); they sum to 1.
void barycentric(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, double out[3]);

// The closest point of the mesh to `p` (over the triangles `allowed` marks, or all when empty): its
// triangle, barycentric weights and position (brute force; called for a handful of landmarks).
UvHit closestSurfacePoint(const UvMesh& mesh, const Vec3& p, const std::vector<bool>& allowed = {});
// The (u,v) of a hit.
Vec2 uvOf(const UvMesh& mesh, const UvHit& hit);

} // namespace vl::face
