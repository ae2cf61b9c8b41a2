#pragma once
// Painting per-vertex weights with a brush (the editor's Weights panel): which vertices a dab
// touches and how much. A dab centred at c with radius r reaches the vertices within Euclidean
// distance r of c; each gets factor = strength * falloff(d / r). Add/subtract change the weight by
// the factor, smooth moves it towards the mean of its edge neighbours by the factor. Weights are
// kept in [0, 1]. Symmetric dabs also apply at c mirrored across the plane x = mirrorX (the face's
// left/right symmetry plane).
//
// Front faces only (brush.eye set, the camera position): of the vertices in reach, a dab paints
// those that face the eye on the same side as the surface under the brush (the vertex nearest to
// c; n . (eye - p) has its sign) and that are joined to that vertex by mesh edges without leaving
// the ball. So a dab never bleeds through a thin part to the back of the head, into the mouth or
// across the lip gap, whatever its radius. A mirrored dab sees the surface from the mirrored eye.
#include "core/deform/VectorField.h"
#include "core/mesh/Mesh.h"
#include "core/paint/PaintSurface.h"

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace vl {

enum class BrushMode { Add, Subtract, Smooth };

struct WeightBrush {
    double radius = 1.0;   // > 0, model units (BrushRadius.h converts screen pixels or % of the head)
    double strength = 0.5; // in [0, 1]
    Falloff falloff = Falloff::Smoothstep;
    BrushMode mode = BrushMode::Add;
    bool symmetric = false;
    double mirrorX = 0.0;
    std::optional<Vec3> eye; // set = front faces only, seen from this point
};

// (vertex, factor) pairs of a dab, vertex indices increasing; with symmetry a vertex reached by both
// dabs gets the larger factor. Throws InputError for a radius <= 0 or a strength outside [0, 1].
std::vector<std::pair<std::uint32_t, double>> brushFootprint(const PaintSurface& surface,
                                                             const WeightBrush& brush, const Vec3& centre);

// Applies one dab to `weights` (one per vertex). Smoothing reads the weights as they were before the
// dab, so the result does not depend on vertex order.
void applyBrushDab(const PaintSurface& surface, const WeightBrush& brush, const Vec3& centre,
                   std::vector<double>& weights);
// The same on plain arrays (builds the surface: O(V + F) per call).
void applyBrushDab(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                   const WeightBrush& brush, const Vec3& centre, std::vector<double>& weights);

} // namespace vl
