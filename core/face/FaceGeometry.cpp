// The base geometry of the bundled faces: an ellipse-section head front in centimetres plus smooth
// bumps for the features, eye openings whose lids rest on the eyeballs (separate parts, see
// core/face/HeadParts.h), sampled into a geometry image.
#include "core/face/FaceDomain.h"
#include "core/face/FaceShape.h"

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

double EyeLens::inside() const {
    if (along <= -1.0 || along >= 1.0) return -1.0;
    const double h = offset >= 0.0 ? upper : lower;
    return h > 0.0 ? 1.0 - std::abs(offset) / h : -1.0;
}

EyeLens eyeLens(double u, double v) {
    EyeLens lens;
    const double du = std::abs(u - kMouthU);
    lens.along = (du - kEyeCentreU) / kEyeHalfLength;
    const double a = std::clamp(lens.along, -1.0, 1.0);
    const double axis = kEyeCentreV + 0.5 * a * (kEyeOuterV - kEyeInnerV);
    lens.offset = v - axis;
    const double shape = 1.0 - a * a;
    // The upper lid arches highest a little towards the nose; the lower lid is flatter.
    lens.upper = 0.021 * shape * (1.0 - 0.25 * a);
    lens.lower = 0.011 * shape * (1.0 + 0.15 * a);
    return lens;
}

double lipWeight(double u, double v) {
    return std::min(1.0, 1.6 * std::max(upperLipBump(u, v), lowerLipBump(u, v)));
}

double browWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - kEyeCentreU;
    // An arch: higher in its middle, thinner towards the temple.
    const double arch = kBrowV + 0.01 - 0.6 * (du - 0.005) * (du - 0.005);
    const double a = (du + 0.005) / 0.08, b = (v - arch) / 0.012;
    return std::clamp(1.5 * (1.0 - a * a - b * b), 0.0, 1.0);
}

double nostrilWeight(double u, double v) {
    const double du = std::abs(u - kMouthU) - 0.03;
    return bump(du, v, 0.0, kSubnasaleV + 0.008, 0.014, 0.007);
}

} // namespace detail

namespace {

using namespace detail;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A smooth maximum (the larger of a and b, rounded over a width k).
double smoothMax(double a, double b, double k) {
    return 0.5 * (a + b + std::sqrt((a - b) * (a - b) + k * k));
}

// Height y(v) of the face: 23 cm per unit of v between chin and brow (eyes to mouth 6.6 cm), the
// midface stretched by midfaceLength, and the band under the chin turning down into the neck.
double faceY(double v, const Proportions& p) {
    constexpr double kScale = 23.0, c = 0.49, w = 0.09;
    const auto integral = [&](double x) {
        return x + (p.midfaceLength - 1.0) * w * std::sqrt(M_PI) / 2.0 * std::erf((x - c) / w);
    };
    double y = kScale * (integral(v) - integral(0.55));
    if (v < 0.1) y += kScale * 0.7 * (0.1 - v);   // under the chin: y changes slowly
    if (v < 0.04) y -= kScale * 1.2 * (0.04 - v); // and turns down into the neck
    return y;
}

double noseHeight(double u, double v, const Proportions& p) {
    // Profile along v: rises from the subnasale to the tip, then falls along the bridge.
    double h;
    if (v < kSubnasaleV)
        h = 0.0;
    else if (v < kNoseTipV)
        h = 2.3 * smoothstep(kSubnasaleV - 0.004, kNoseTipV + 0.006, v);
    else
        h = (2.3 - 1.7 * smoothstep(kNoseTipV, kNasionV, v)) *
            (1.0 - smoothstep(kNasionV - 0.01, kNasionV + 0.07, v));
    h = std::max(h, 0.0) * p.noseProjection;
    // Width: a narrow bridge, a wider rounded tip.
    const double width =
        (0.03 + 0.028 * (1.0 - smoothstep(kNoseTipV - 0.01, kNasionV - 0.06, v))) * p.noseWidth;
    const double across = (u - kMouthU) / width;
    double z = h * std::exp(-across * across * (0.7 + 0.3 * across * across));
    // Alae (nostril wings) either side of the tip, and the nostrils under it.
    for (const double side : {-1.0, 1.0}) {
        z += 0.95 * p.noseProjection *
             bump(u, v, kMouthU + side * 0.052 * p.noseWidth, kSubnasaleV + 0.02, 0.03, 0.024);
        z -= 0.4 * bump(u, v, kMouthU + side * 0.03 * p.noseWidth, kSubnasaleV + 0.008, 0.013, 0.008);
    }
    return z;
}

// Everything in front of the head's ellipse section except the eyes' lids and openings.
double featureDepth(double u, double v, const Proportions& p) {
    double z = 0.0;
    z += noseHeight(u, v, p);
    // Lips: the dental arch pushes the mouth region out; two vermilion rolls on it.
    z += 1.4 * bump(u, v, kMouthU, kMouthV, 0.17, 0.11);
    z += 0.5 * p.lipFullness * upperLipBump(u, v);
    z += 0.55 * p.lipFullness * lowerLipBump(u, v);
    z += 0.2 * bump(u, v, kMouthU, 0.352, 0.012, 0.02); // philtrum
    z -= 0.45 * bump(u, v, kMouthU, 0.222, 0.07, 0.02); // mentolabial sulcus
    z += 0.95 * p.chin * bump(u, v, kMouthU, 0.165, 0.085, 0.055);
    for (const double side : {-1.0, 1.0}) {
        const double eu = kMouthU + side * kEyeCentreU;
        // The orbit: a broad hollow the eye sits in, under the brow ridge and above the cheek.
        z -= 1.3 * p.eyeDepth * bump(u, v, eu, kEyeCentreV + 0.004, 0.085, 0.055);
        z += 0.6 * p.browRidge * bump(u, v, eu, kBrowV, 0.11, 0.03);
        z += 0.7 * p.cheeks * bump(u, v, kMouthU + side * 0.19, 0.44, 0.09, 0.1);
        z += 0.45 * p.cheeks * bump(u, v, kMouthU + side * 0.245, 0.54, 0.075, 0.04);
        z -= 0.35 * bump(u, v, kMouthU + side * 0.34, 0.63, 0.07, 0.08);   // temples
        z -= 0.22 * bump(u, v, kMouthU + side * 0.118, 0.34, 0.014, 0.05); // nasolabial fold
    }
    z += 0.35 * p.browRidge * bump(u, v, kMouthU, kNasionV + 0.025, 0.05, 0.035); // glabella
    return z;
}

// The head without the eyes' lids and openings.
Vec3 headPoint(double u, double v, const Proportions& p) {
    constexpr double kHalfAngle = 1.45; // the domain's left/right border wraps to about 83 degrees
    const double theta = (u - 0.5) * 2.0 * kHalfAngle;
    // Half-width of the head at height v: narrow at the chin, widest at the cheekbones.
    const double lower = 4.0 + 3.6 * smoothstep(0.0, 0.52, v);
    const double halfWidth =
        p.width * (p.jawWidth * lower + (1.0 - p.jawWidth) * 7.6 * smoothstep(0.0, 0.52, v)) -
        0.6 * smoothstep(0.75, 1.0, v);
    const double depth = 8.0;
    // Profile: the forehead slopes back above the brows, the under-chin band recedes to the neck.
    double front = -30.0 * std::pow(std::max(0.0, v - 0.64), 2.0);
    front -= 380.0 * std::pow(std::max(0.0, 0.11 - v), 2.0);
    front -= 1.2 * smoothstep(0.35, 0.0, v); // the lower face sits behind the upper
    // The mouth is wider than the ellipse section alone would make it: the mouth region is stretched
    // sideways (smoothly, most at the corners).
    const double t = (u - kMouthU) / kMouthHalfWidth;
    const double stretch =
        0.45 * t * std::exp(0.5 * (1.0 - t * t)) * std::exp(-((v - kMouthV) / 0.08) * ((v - kMouthV) / 0.08));
    const double x = halfWidth * std::sin(theta) + stretch;
    const double z =
        front - depth * (1.0 - std::cos(theta)) + featureDepth(u, v, p) * std::cos(theta) * std::cos(theta);
    return Vec3(x, faceY(squeezedMouthV(u, v, kBundledClosedGap), p), z);
}

} // namespace

namespace detail {

Vec3 eyeballCentre(const Proportions& p, double side) {
    // The eyeball's front stands 0.55 cm out of the orbit's hollow at the eye's centre.
    const Vec3 c = headPoint(kMouthU + side * kEyeCentreU, kEyeCentreV, p);
    return Vec3(c[0], c[1], c[2] + 0.55 - kEyeballRadius);
}

} // namespace detail

namespace {

// The head with the eyes: near each eye the skin is the lids, a shell resting on the eyeball, and
// between the lid margins it turns back into the socket behind the eyeball.
Vec3 facePoint(double u, double v, const Proportions& p) {
    Vec3 point = headPoint(u, v, p);
    const double side = u >= kMouthU ? 1.0 : -1.0;
    const EyeLens lens = eyeLens(u, v);
    if (std::abs(lens.along) > 2.2 || std::abs(lens.offset) > 0.08) return point;
    const Vec3 centre = eyeballCentre(p, side);
    constexpr double kLid = 0.12; // lid thickness over the eyeball
    const double r2 =
        (point[0] - centre[0]) * (point[0] - centre[0]) + (point[1] - centre[1]) * (point[1] - centre[1]);
    const double shell = kEyeballRadius + kLid;
    const double lidZ = centre[2] + std::sqrt(std::max(0.0, shell * shell - r2));
    // The lids cover an ellipse around the opening and blend into the orbit outside it.
    const double eu = (std::abs(u - kMouthU) - kEyeCentreU) / 0.095;
    const double ev = (v - kEyeCentreV - 0.006) / (v > kEyeCentreV ? 0.045 : 0.032);
    const double lids = 1.0 - smoothstep(0.75, 1.35, std::sqrt(eu * eu + ev * ev));
    double z = point[2] + lids * (smoothMax(point[2], lidZ, 0.25) - point[2]);
    // The upper lid's crease and the lower lid's slight roll.
    const double along = std::clamp(lens.along, -1.0, 1.0), shape = 1.0 - along * along;
    z -= 0.16 * shape * std::exp(-std::pow((lens.offset - lens.upper - 0.022) / 0.008, 2.0));
    z += 0.05 * shape * std::exp(-std::pow((lens.offset + lens.lower + 0.008) / 0.006, 2.0));
    // Inside the opening the skin turns back into the socket, deepest on the axis.
    const double inside = lens.inside();
    if (inside > 0.0) z -= 1.0 * std::sqrt(shape) * std::sqrt(1.0 - (1.0 - inside) * (1.0 - inside));
    point[2] = z;
    return point;
}

} // namespace

Vec3 eyeballCentre(Individual who, double side) {
    return detail::eyeballCentre(proportionsOf(who), side >= 0.0 ? 1.0 : -1.0);
}

SampledField makeFaceGeometry(Individual who, int gridSize) {
    if (gridSize < 2 || gridSize > 4097)
        throwInputError("face geometry", "grid size " + std::to_string(gridSize) + " is outside 2..4097");
    const Proportions p = proportionsOf(who);
    return sampleGrid(gridSize, gridSize, [&p](double u, double v) { return facePoint(u, v, p); });
}

} // namespace vl::face
