// The base geometry of the bundled faces: an ellipsoid-like head front in centimetres plus smooth
// bumps for the features, sampled into a geometry image.
#include "core/deform/FaceDomain.h"
#include "core/deform/FaceShape.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vl::face {

namespace detail {

Proportions proportionsOf(Individual who) {
    Proportions p;
    if (who == Individual::Retarget) {
        p.width = 1.12;
        p.jawWidth = 1.15;
        p.midfaceLength = 1.22;
        p.noseProjection = 1.15;
        p.noseWidth = 1.15;
        p.lipFullness = 1.5;
        p.chin = 0.7;
        p.cheeks = 1.3;
        p.browRidge = 1.35;
        p.eyeDepth = 1.2;
    }
    return p;
}

double lipWeight(double u, double v) {
    return std::min(1.0, 1.6 * std::max(upperLipBump(u, v), lowerLipBump(u, v)));
}

double eyeWhiteWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - kEyeU;
    const double a = du / 0.058, b = (v - kEyeV) / 0.022;
    return std::clamp(2.5 * (1.0 - (a * a + b * b)), 0.0, 1.0);
}

double irisWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - kEyeU;
    const double r = std::hypot(du / 0.026, (v - kEyeV) / 0.026);
    return std::clamp(2.5 * (1.0 - r), 0.0, 1.0) * eyeWhiteWeight(u, v);
}

double browWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - kEyeU;
    // An arch: higher in its middle, thinner towards the temple.
    const double arch = kBrowV + 0.01 - 0.6 * (du - 0.005) * (du - 0.005);
    const double a = (du + 0.005) / 0.075, b = (v - arch) / 0.012;
    return std::clamp(1.5 * (1.0 - a * a - b * b), 0.0, 1.0);
}

double nostrilWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - 0.024;
    return bump(du, v, 0.0, kSubnasaleV + 0.009, 0.012, 0.007);
}

} // namespace detail

namespace {

using namespace detail;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Height y(v) of the face: 21 cm over the domain, the midface stretched by midfaceLength, and the
// band under the chin flattened so it faces down.
double faceY(double v, const Proportions& p) {
    constexpr double kScale = 21.0, c = 0.49, w = 0.09;
    const auto integral = [&](double x) {
        return x + (p.midfaceLength - 1.0) * w * std::sqrt(M_PI) / 2.0 * std::erf((x - c) / w);
    };
    double y = kScale * (integral(v) - integral(0.55));
    if (v < 0.12) y += kScale * 0.65 * (0.12 - v); // under the chin: y changes slowly
    if (v < 0.05) y -= kScale * 1.2 * (0.05 - v);  // and turns down into the neck
    return y;
}

double noseHeight(double u, double v, const Proportions& p) {
    // Profile along v: rises steeply from the subnasale to the tip, then falls along the bridge.
    double h;
    if (v < kSubnasaleV)
        h = 0.0;
    else if (v < kNoseTipV)
        h = 2.5 * smoothstep(kSubnasaleV, kNoseTipV + 0.008, v);
    else
        h = (2.5 - 1.9 * smoothstep(kNoseTipV, kNasionV, v)) *
            (1.0 - smoothstep(kNasionV - 0.01, kNasionV + 0.06, v));
    h = std::max(h, 0.0) * p.noseProjection;
    // Width: narrow bridge, wider tip.
    const double width = (0.022 + 0.026 * (1.0 - smoothstep(kNoseTipV, kNasionV - 0.05, v))) * p.noseWidth;
    const double across = (u - kMouthU) / width;
    double z = h * std::exp(-across * across * across * across * 0.6);
    // Alae (nostril wings) either side of the tip, and the nostrils under it.
    for (const double side : {-1.0, 1.0}) {
        z += 1.1 * p.noseProjection *
             bump(u, v, kMouthU + side * 0.047 * p.noseWidth, kSubnasaleV + 0.02, 0.024, 0.022);
        z -= 0.45 * bump(u, v, kMouthU + side * 0.024 * p.noseWidth, kSubnasaleV + 0.009, 0.011, 0.007);
    }
    return z;
}

double featureDepth(double u, double v, const Proportions& p) {
    double z = 0.0;
    z += noseHeight(u, v, p);
    // Lips: the dental arch pushes the mouth region out; two vermilion rolls on it.
    z += 1.3 * bump(u, v, kMouthU, kMouthV, 0.16, 0.11);
    z += 0.5 * p.lipFullness * upperLipBump(u, v);
    z += 0.55 * p.lipFullness * lowerLipBump(u, v);
    z += 0.2 * bump(u, v, kMouthU, 0.352, 0.012, 0.02); // philtrum
    z -= 0.45 * bump(u, v, kMouthU, 0.222, 0.07, 0.02); // mentolabial sulcus
    z += 0.9 * p.chin * bump(u, v, kMouthU, 0.16, 0.085, 0.055);
    for (const double side : {-1.0, 1.0}) {
        const double eu = kMouthU + side * kEyeU;
        // Eye socket, eyeball (a rounded cap that meets the socket smoothly) and the lids' folds.
        z -= 1.5 * p.eyeDepth * bump(u, v, eu, kEyeV + 0.004, 0.08, 0.06);
        const double a = (u - eu) / 0.062, b = (v - kEyeV) / 0.045;
        z += 1.15 * std::pow(std::max(0.0, 1.0 - a * a - b * b), 1.2); // smooth rim, no crease
        z += 0.2 * bump(u, v, eu, kEyeV + 0.028, 0.055, 0.01);
        z += 0.1 * bump(u, v, eu, kEyeV - 0.026, 0.05, 0.008);
        // Brow ridge and cheeks.
        z += 0.65 * p.browRidge * bump(u, v, kMouthU + side * 0.135, kBrowV, 0.11, 0.028);
        z += 0.7 * p.cheeks * bump(u, v, kMouthU + side * 0.19, 0.44, 0.09, 0.1);
        z += 0.45 * p.cheeks * bump(u, v, kMouthU + side * 0.245, 0.545, 0.075, 0.04);
        z -= 0.35 * bump(u, v, kMouthU + side * 0.34, 0.63, 0.07, 0.08);   // temples
        z -= 0.25 * bump(u, v, kMouthU + side * 0.115, 0.34, 0.012, 0.05); // nasolabial fold
    }
    z += 0.35 * p.browRidge * bump(u, v, kMouthU, kNasionV + 0.025, 0.05, 0.035); // glabella
    return z;
}

Vec3 facePoint(double u, double v, const Proportions& p) {
    constexpr double kHalfAngle = 1.45; // the domain's left/right border wraps to about 83 degrees
    const double theta = (u - 0.5) * 2.0 * kHalfAngle;
    // Half-width of the head at height v: narrow at the chin, widest at the cheekbones.
    const double lower = 3.8 + 4.0 * smoothstep(0.0, 0.52, v);
    const double halfWidth =
        p.width * (p.jawWidth * lower + (1.0 - p.jawWidth) * 7.8 * smoothstep(0.0, 0.52, v)) -
        0.6 * smoothstep(0.75, 1.0, v);
    const double depth = 8.0;
    // Profile: the forehead slopes back above the brows, the under-chin band recedes to the neck.
    double front = -30.0 * std::pow(std::max(0.0, v - 0.64), 2.0);
    front -= 380.0 * std::pow(std::max(0.0, 0.13 - v), 2.0);
    front -= 1.2 * smoothstep(0.35, 0.0, v); // the lower face sits behind the upper
    const double x = halfWidth * std::sin(theta);
    const double z =
        front - depth * (1.0 - std::cos(theta)) + featureDepth(u, v, p) * std::cos(theta) * std::cos(theta);
    return Vec3(x, faceY(squeezedMouthV(u, v, kBundledClosedGap), p), z);
}

} // namespace

std::string_view individualName(Individual who) {
    return who == Individual::Bundled ? "bundled" : "retarget";
}

Individual parseIndividual(std::string_view name, std::string_view where) {
    if (name == "bundled") return Individual::Bundled;
    if (name == "retarget") return Individual::Retarget;
    throwInputError(where, "unknown face '" + std::string(name) + "' (expected bundled or retarget)");
}

SampledField makeFaceGeometry(Individual who, int gridSize) {
    if (gridSize < 2 || gridSize > 4097)
        throwInputError("face geometry", "grid size " + std::to_string(gridSize) + " is outside 2..4097");
    const Proportions p = proportionsOf(who);
    return sampleGrid(gridSize, gridSize, [&p](double u, double v) { return facePoint(u, v, p); });
}

} // namespace vl::face
