#pragma once
// Shaping a viseme with brushes (the editor's Sculpt tool), on its displacement from the neutral,
// d(v) = shape(v) - neutral(v). A dab reaches the vertices WeightBrush.h's footprint gives (radius,
// falloff, front faces only, X-mirror), each with factor f = strength * falloff(distance / radius):
//   grab:     d(v) += f * g, g the cursor's motion in model units since the last dab (the mirrored
//             side moves by g with its x negated, so a symmetric pull stays symmetric);
//   smooth:   d(v) += f * (mean of d over v's edge neighbours - d(v)) (the displacement is smoothed,
//             not the face: the neutral's features stay);
//   inflate:  d(v) += f * step * n(v), n the unit normal of the shape as shown, step = radius / 10;
//   deflate:  the same with -step.
// Reading the shape as it was before the dab, so the result does not depend on vertex order.
#include "core/paint/PaintSurface.h"
#include "core/paint/WeightBrush.h"

#include <span>
#include <string_view>

namespace vl {

enum class SculptTool { Grab, Smooth, Inflate, Deflate };

std::string_view sculptToolName(SculptTool tool); // "grab", "smooth", "inflate", "deflate"

struct SculptDab {
    SculptTool tool = SculptTool::Grab;
    WeightBrush brush;  // radius, strength, falloff, symmetric + mirrorX, front faces only (its mode unused)
    Vec3 grab{0, 0, 0}; // grab only: the cursor's motion in model units
};

// Applies one dab centred at `centre` to `shape` (one position per vertex of `surface`, which is
// the shape as shown: distances and normals are measured on it). `neutral` has the same vertex
// count. Throws InputError for sizes that differ and what brushFootprint refuses.
void applySculptDab(const PaintSurface& surface, std::span<const Vec3> neutral, const SculptDab& dab,
                    const Vec3& centre, std::span<Vec3> shape);

} // namespace vl
