#include "core/deform/VectorField.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vl {

Vec3 SampledField::at(double u, double v) const {
    if (samples.empty()) return Vec3(0.0, 0.0, 0.0);
    const double x = std::clamp(u, 0.0, 1.0) * (width - 1);
    const double y = std::clamp(v, 0.0, 1.0) * (height - 1);
    const int i0 = std::min(static_cast<int>(x), std::max(width - 2, 0));
    const int j0 = std::min(static_cast<int>(y), std::max(height - 2, 0));
    const int i1 = std::min(i0 + 1, width - 1);
    const int j1 = std::min(j0 + 1, height - 1);
    const double fx = x - i0;
    const double fy = y - j0;
    const Vec3 bottom = sample(i0, j0) * (1.0 - fx) + sample(i1, j0) * fx;
    const Vec3 top = sample(i0, j1) * (1.0 - fx) + sample(i1, j1) * fx;
    return bottom * (1.0 - fy) + top * fy;
}

double falloffWeight(Falloff kind, double t) {
    if (t <= 0.0) return 1.0;
    if (t >= 1.0) return 0.0;
    switch (kind) {
    case Falloff::Linear:
        return 1.0 - t;
    case Falloff::Smoothstep:
        return 1.0 - t * t * (3.0 - 2.0 * t);
    case Falloff::Cosine:
        return 0.5 * (1.0 + std::cos(M_PI * t));
    case Falloff::Gaussian: {
        // exp(-k t^2) shifted and rescaled so it reaches exactly 0 at t = 1.
        constexpr double k = 4.0;
        const double floor = std::exp(-k);
        return (std::exp(-k * t * t) - floor) / (1.0 - floor);
    }
    }
    return 0.0;
}

double InfluenceField::weight(double u, double v) const {
    // Local coordinates (a,b) along the rotated ellipse axes. This is the inner loop of every cascade
    // evaluation; most regions are not rotated, and then need no sine and cosine (cos 0 = 1 and
    // sin 0 = 0 exactly: the same result to the bit).
    const double du = u - centre[0];
    const double dv = v - centre[1];
    double a = du, b = dv;
    if (rotation == 0.0) {
        // Outside the ellipse's bounding box: |du| >= ru gives |du| / ru >= 1 after rounding too, so
        // this returns exactly where the test below would.
        if (std::abs(du) >= radii[0] || std::abs(dv) >= radii[1]) return 0.0;
    } else {
        const double c = std::cos(rotation);
        const double s = std::sin(rotation);
        a = c * du + s * dv;
        b = -s * du + c * dv;
    }
    // Outside the outer ellipse (most points, for a local region) without a square root.
    const double outerSquared = (a / radii[0]) * (a / radii[0]) + (b / radii[1]) * (b / radii[1]);
    if (outerSquared >= 1.0) return 0.0;
    const double outer = std::sqrt(outerSquared);
    if (plateau[0] <= 0.0 || plateau[1] <= 0.0) return falloffWeight(falloff, outer);
    // Along the ray from the centre through (a,b): distance rho, inner border at rho / inner, outer
    // border at rho / outer. t runs from 0 on the plateau border to 1 on the outer border.
    const double inner = std::sqrt((a / plateau[0]) * (a / plateau[0]) + (b / plateau[1]) * (b / plateau[1]));
    if (inner <= 1.0) return 1.0;
    const double t = (1.0 - 1.0 / inner) / (1.0 / outer - 1.0 / inner);
    return falloffWeight(falloff, t);
}

Vec3 InfluenceField::at(double u, double v) const {
    const double w = weight(u, v);
    if (w == 0.0) return Vec3(0.0, 0.0, 0.0);
    return direction * (w * magnitude / direction.norm());
}

Vec3 VectorField::at(double u, double v) const {
    Vec3 sum = sampled.at(u, v);
    for (const auto& region : influences) sum += region.at(u, v);
    return sum;
}

namespace {

bool finite(const Vec3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
bool finite(const Vec2& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]);
}

} // namespace

void validateField(const VectorField& field, std::string_view where) {
    const auto& grid = field.sampled;
    if (!grid.samples.empty() || grid.width != 0 || grid.height != 0) {
        if (grid.width < 1 || grid.height < 1)
            throwInputError(where, "sampled grid size " + std::to_string(grid.width) + " x " +
                                       std::to_string(grid.height) + " must be at least 1 x 1");
        const auto expected = static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
        if (grid.samples.size() != expected)
            throwInputError(where, "sampled grid has " + std::to_string(grid.samples.size()) +
                                       " samples, expected " + std::to_string(expected));
        for (std::size_t k = 0; k < grid.samples.size(); ++k)
            if (!finite(grid.samples[k]))
                throwInputError(where, "sampled grid value " + std::to_string(k) + " is not finite");
    }
    for (std::size_t k = 0; k < field.influences.size(); ++k) {
        const auto& r = field.influences[k];
        const std::string at = std::string(where) + ": influence " + std::to_string(k);
        if (!finite(r.centre) || !finite(r.radii) || !finite(r.plateau) || !finite(r.direction) ||
            !std::isfinite(r.rotation) || !std::isfinite(r.magnitude))
            throwInputError(at, "has a value that is not finite");
        if (r.radii[0] <= 0.0 || r.radii[1] <= 0.0) throwInputError(at, "radii must be positive");
        const bool noPlateau = r.plateau[0] == 0.0 && r.plateau[1] == 0.0;
        const bool plateauInside = r.plateau[0] > 0.0 && r.plateau[1] > 0.0 && r.plateau[0] < r.radii[0] &&
                                   r.plateau[1] < r.radii[1];
        if (!noPlateau && !plateauInside)
            throwInputError(at, "plateau radii must both be 0 or both lie strictly between 0 and the radii");
        if (r.direction.norm() == 0.0) throwInputError(at, "direction must not be the zero vector");
    }
}

} // namespace vl
