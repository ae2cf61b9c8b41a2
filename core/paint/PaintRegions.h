#pragma once
// The paint tool's other ways to choose vertices than a brush dab: a connected region grown from a
// seed (the bucket fill), the vertices inside a screen rectangle (box selection), and what a
// value reads at a point of a triangle (the weight readout under the cursor).
#include "core/paint/PaintSurface.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vl {

// The vertices reachable from `seed` over mesh edges through vertices whose value differs from the
// seed's by at most `tolerance` (the seed included), increasing. tolerance >= 1 on weights in [0, 1]
// gives the seed's whole connected part of the mesh. Throws InputError for a seed out of range, a
// value count other than the vertex count, or a negative or NaN tolerance.
std::vector<std::uint32_t> connectedRegion(const PaintSurface& surface, std::span<const double> values,
                                           std::uint32_t seed, double tolerance);

// A rectangle in normalised device coordinates ([-1, 1]^2, y up), corners in any order.
struct NdcRectangle {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

// The vertices whose projection by `viewProjection` (4x4, column-major as OpenGL and glm store it)
// falls inside `rectangle` and lies in front of the camera (clip w > 0 and depth in [-1, 1]),
// increasing. With `eye` (the camera position) only the vertices facing it: n . (eye - p) > 0, or
// < 0 for every vertex when `flipped` (a mesh wound inside out), so a box over the face does not
// select the back of the head.
std::vector<std::uint32_t> verticesInRectangle(const PaintSurface& surface,
                                               const std::array<double, 16>& viewProjection,
                                               const NdcRectangle& rectangle,
                                               const std::optional<Vec3>& eye = std::nullopt,
                                               bool flipped = false);

// True when the triangles face away from `eye` at the vertex nearest to `point` (the surface under
// the cursor is wound inside out): pass it as verticesInRectangle's `flipped`.
bool facesAwayAt(const PaintSurface& surface, const Vec3& point, const Vec3& eye);

// The value at a point of triangle `triangle` given by its barycentric weights (one per corner,
// summing to 1): the linear interpolation the renderer shows. Throws InputError for a triangle or a
// vertex out of range.
double valueAt(const PaintSurface& surface, std::span<const double> values, std::size_t triangle,
               const Vec3& barycentric);

// `values` with every listed vertex set to `value` (the fill of a region or a selection).
std::vector<double> filled(std::vector<double> values, std::span<const std::uint32_t> vertices, double value);

} // namespace vl
