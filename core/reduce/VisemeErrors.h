#pragma once
// How far each viseme moves from its own shape after a reduction, in model units: what a designer
// checks before shipping (`reduce` and `avatar reduce` reports, per viseme, in mm).
#include "core/reduce/ShapeView.h"

#include <span>
#include <vector>

namespace vl {

struct VisemeError {
    double max = 0;                 // largest vertex distance to the shape it is shown with
    double rms = 0;                 // root mean square of that distance over vertices, by weight
    double largestDisplacement = 0; // its own largest vertex distance from the rest pose (0 without one)
};

// Per viseme i: the distances between a_i and the shape it is shown with, B = the frequency-weighted
// mean of its key's members (eq. 19; the plain mean when their frequencies sum to 0), or the rest
// pose when groupOf[i] < 0. Only vertices with weight > 0 count. `rest` may be empty when no viseme
// rests. O(n |V|); the keys are merged one at a time (memory for one key, not m: a million-vertex set).
std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> frequencies, std::span<const double> weights,
                                      std::span<const int> groupOf);

// The same with the keys' shapes given (keyShapes[g] for groupOf[i] == g), e.g. a reduced model's
// key meshes, so they are not merged again.
std::vector<VisemeError> visemeErrors(const ShapeView& shapes, std::span<const Vec3> rest,
                                      std::span<const double> weights, std::span<const int> groupOf,
                                      const ShapeView& keyShapes);

} // namespace vl
