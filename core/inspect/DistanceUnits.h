#pragma once
// The reduction cost in a unit a designer reads: rho_f (paper eq. 18-19) is a frequency- and
// weight-weighted sum of squared vertex distances in model units; its root mean square per unit
// of weight is a distance, shown in millimetres once the model's length unit is known.
#include "core/mesh/Mesh.h"

#include <span>

namespace vl {

enum class LengthUnit { Metre, Centimetre, Millimetre, Inch };

// sqrt(rho_f / (sum f * sum w)): the RMS distance between the original and the merged shapes
// over visemes (by frequency) and vertices (by weight). 0 when a sum is not positive.
double rmsDistance(double cost, double frequencySum, double weightSum);

// A face or head is 0.1 to 0.5 m across: the unit in which `extent` (the largest side of the
// neutral mesh's bounding box) falls in that range; Metre when nothing fits (e.g. extent 0).
LengthUnit guessLengthUnit(double extent);

double millimetresPer(LengthUnit unit);

// millimetresPer(guessLengthUnit(the largest side of the positions' bounding box)); metres when empty.
double guessMillimetresPerUnit(std::span<const Vec3> positions);
const char* lengthUnitName(LengthUnit unit); // "m", "cm", "mm", "in"

// Nice axis ticks covering [lo, hi] (1, 2, 5 x 10^k steps), at most about `count` of them;
// for a logarithmic axis (lo > 0) the powers of ten in [lo, hi] (every k-th one when there are
// more than about `count`), or 1-2-5 steps when there are fewer than two. Returns the number written to
// `ticks` (capacity `capacity`).
int axisTicks(double lo, double hi, int count, bool logarithmic, double* ticks, int capacity);

} // namespace vl
