#include "core/paint/BrushRadius.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <cmath>
#include <numbers>
#include <string>

namespace vl {

double modelUnitsPerPixel(double depth, double fovY, double viewportHeight) {
    if (!(depth > 0.0) || !std::isfinite(depth))
        throwInputError("brush radius", "depth must be > 0, got " + formatDouble(depth));
    if (!(fovY > 0.0 && fovY < std::numbers::pi))
        throwInputError("brush radius", "field of view must be in (0, pi), got " + formatDouble(fovY));
    if (!(viewportHeight >= 1.0))
        throwInputError("brush radius",
                        "viewport height must be >= 1 pixel, got " + formatDouble(viewportHeight));
    return 2.0 * depth * std::tan(0.5 * fovY) / viewportHeight;
}

double modelRadius(const BrushRadius& radius, double headSize, double unitsPerPixel) {
    if (!(radius.value > 0.0) || !std::isfinite(radius.value))
        throwInputError("brush radius", "must be > 0, got " + formatDouble(radius.value));
    const bool pixels = radius.unit == RadiusUnit::ScreenPixels;
    const double scale = pixels ? unitsPerPixel : headSize;
    if (!(scale > 0.0) || !std::isfinite(scale))
        throwInputError("brush radius", std::string(pixels ? "model units per pixel" : "head size") +
                                            " must be > 0, got " + formatDouble(scale));
    return pixels ? radius.value * scale : radius.value / 100.0 * scale;
}

std::string_view radiusUnitName(RadiusUnit unit) {
    return unit == RadiusUnit::ScreenPixels ? "px" : "% of head";
}

} // namespace vl
