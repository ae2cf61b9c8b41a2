#pragma once
// Shape analysis for finding a face on an unknown mesh: the mesh welded into one surface (seams
// joined), which parts of it can be seen from outside (inner mouths, teeth and eyeballs cannot),
// nearest-point queries, and the bilateral symmetry plane.
#include "core/face/UvMesh.h"

#include <cstdint>
#include <vector>

namespace vl::face {

// The mesh with coincident positions merged: one point per position, triangles over them.
struct WeldedSurface {
    std::vector<Vec3> points;
    std::vector<std::uint32_t> pointOf; // mesh vertex -> point
    std::vector<Triangle> triangles;    // same order as UvMesh::triangles
    std::vector<Vec3> normals;          // per point, area-weighted, unit (or zero)
    std::vector<double> areas;          // per point: a third of the incident triangle areas
    double diagonal = 0.0;              // of the bounding box
};
WeldedSurface weldSurface(const UvMesh& mesh);

// Triangles seen from at least one of `directions` evenly spread around the mesh (orthographic
// z-buffers): the outside of a head, not its inner mouth, teeth or eyeballs behind the lids. The
// z-buffers have at least `minimumResolution` pixels per side and about as many pixels as the mesh
// has triangles (up to 1200 per side), so a finer cut of the same surface is seen the same way.
std::vector<bool> visibleTriangles(const WeldedSurface& surface, int directions = 48,
                                   int minimumResolution = 256);

// Nearest-neighbour and radius queries over a fixed point set (a uniform grid of buckets).
class PointIndex {
  public:
    PointIndex(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& subset, double cell);
    // The nearest indexed point to p within maxDistance, or -1.
    std::int64_t nearest(const Vec3& p, double maxDistance) const;
    // Indexed points within radius of p.
    void within(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const;

  private:
    std::int64_t key(int x, int y, int z) const;
    const std::vector<Vec3>* points_;
    double cell_;
    Vec3 lo_{0, 0, 0};
    int nx_ = 1, ny_ = 1, nz_ = 1;
    std::vector<std::uint32_t> start_, items_;
};

struct SymmetryPlane {
    Vec3 normal{1, 0, 0}; // unit
    double offset = 0.0;  // plane: dot(normal, x) = offset
    double error = 0.0;   // median mirror mismatch, relative to the bounding box diagonal
    double signedDistance(const Vec3& p) const { return OpenMesh::dot(normal, p) - offset; }
    Vec3 reflect(const Vec3& p) const { return p - normal * (2.0 * signedDistance(p)); }
};

// The plane the `subset` of points is most mirror-symmetric about: each principal axis as a start,
// refined by iterated closest points (symmetric pairs' midpoints lie on the plane, their difference
// is along its normal), the best kept.
SymmetryPlane findSymmetryPlane(const WeldedSurface& surface, const std::vector<std::uint32_t>& subset);

} // namespace vl::face
