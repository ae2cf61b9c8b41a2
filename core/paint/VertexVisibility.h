#pragma once
// Which vertices of a surface the camera sees (the box selection's "front faces only"): facing the
// camera is not enough, a vertex can be hidden behind another part of the mesh (the far lip behind
// the near one, the inside of the mouth, an ear behind the head, a cheek behind the nose from the
// side). A vertex is seen when no triangle that does not contain it crosses the segment from the
// eye to the vertex short of it.
//
// Testing every vertex against every triangle is O(V F) (the tests keep that as the reference).
// Here the triangles are binned once by the bounding boxes of their projections on a grid over the
// screen, and a vertex is tested only against the triangles of its cell: the same ray test on a
// superset of the triangles that can hide it, hence the same answer.
#include "core/paint/PaintSurface.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace vl {

class VertexVisibility {
  public:
    // `viewProjection`: 4x4, column-major as OpenGL and glm store it, a perspective projection whose
    // centre is `eye` (the camera position): the segment from the eye to a point then projects onto
    // that point's pixel. The surface must outlive this object.
    VertexVisibility(const PaintSurface& surface, const std::array<double, 16>& viewProjection,
                     const Vec3& eye);

    // True when no triangle without vertex `v` crosses the segment eye -> v before v (a relative
    // tolerance of 1e-6 of the distance keeps triangles through v itself from hiding it). Vertices
    // off the screen or behind the eye are tested against every triangle. Throws InputError
    // for a vertex out of range.
    bool visible(std::uint32_t v) const;

  private:
    bool hiddenBy(std::uint32_t v, std::uint32_t triangle) const;
    // The grid cell of a point of the screen, or -1 off the screen.
    int cellAt(double ndcX, double ndcY) const;

    const PaintSurface* surface_;
    std::array<double, 16> viewProjection_;
    Vec3 eye_;
    int cells_ = 1;                      // per side
    std::vector<std::uint32_t> offsets_; // CSR: triangles of cell c are [offsets_[c], offsets_[c + 1])
    std::vector<std::uint32_t> binned_;
    std::vector<std::uint32_t> everywhere_; // triangles crossing the eye's plane or covering most cells
};

// The vertices of `vertices` the eye sees, in their order (see VertexVisibility).
std::vector<std::uint32_t> visibleVertices(const PaintSurface& surface,
                                           std::span<const std::uint32_t> vertices,
                                           const std::array<double, 16>& viewProjection, const Vec3& eye);

} // namespace vl
