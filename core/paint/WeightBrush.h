#pragma once
// Painting per-vertex weights with a brush (the editor's Weights panel): which vertices a dab
// touches and how much. A dab centred at c with radius r reaches the vertices within Euclidean
// distance r of c; each gets factor = strength * falloff(d / r). Add/subtract change the weight by
// the factor, smooth moves it towards the mean of its edge neighbours by the factor. Weights are
// kept in [0, 1]. Symmetric dabs also apply at c mirrored across the plane x = mirrorX (the face's
// left/right symmetry plane).
#include "core/deform/VectorField.h"
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace vl {

enum class BrushMode { Add, Subtract, Smooth };

struct WeightBrush {
    double radius = 1.0;   // > 0, model units
    double strength = 0.5; // in [0, 1]
    Falloff falloff = Falloff::Smoothstep;
    BrushMode mode = BrushMode::Add;
    bool symmetric = false;
    double mirrorX = 0.0;
};

// (vertex, factor) pairs of a dab, vertex indices increasing; with symmetry a vertex reached by both
// dabs gets the larger factor. Throws InputError for a radius <= 0 or a strength outside [0, 1].
std::vector<std::pair<std::uint32_t, double>> brushFootprint(std::span<const Vec3> positions,
                                                             const WeightBrush& brush, const Vec3& centre);

// Applies one dab to `weights` (one per vertex). Smoothing reads the weights as they were before the
// dab, so the result does not depend on vertex order.
void applyBrushDab(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                   const WeightBrush& brush, const Vec3& centre, std::vector<double>& weights);

} // namespace vl
