#pragma once
// The brush radius as a designer sets it: in screen pixels (the circle keeps its size on screen
// whatever the zoom) or in % of the head size (it keeps its size on the face), converted to the
// model units a dab works in (WeightBrush::radius).
#include <string_view>

namespace vl {

enum class RadiusUnit { ScreenPixels, PercentOfHead };

struct BrushRadius {
    double value = 40.0; // pixels, or percent
    RadiusUnit unit = RadiusUnit::ScreenPixels;
};

// Model units covered by one screen pixel at `depth` (distance along the view axis) in a perspective
// view of vertical field of view `fovY` (radians) that is `viewportHeight` pixels tall:
// 2 depth tan(fovY / 2) / height. Throws InputError for a depth, angle or height out of range.
double modelUnitsPerPixel(double depth, double fovY, double viewportHeight);

// The radius in model units: value * unitsPerPixel, or value / 100 * headSize. Throws InputError
// for a value <= 0 or a scale (unitsPerPixel or headSize, whichever the unit uses) <= 0.
double modelRadius(const BrushRadius& radius, double headSize, double unitsPerPixel);

std::string_view radiusUnitName(RadiusUnit unit); // "px" or "% of head"

} // namespace vl
