#pragma once
// Internal to the bundled face: the analytic shapes behind its geometry image and preview colours.
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/mesh/Mesh.h"

#include <cmath>

namespace vl::face::detail {

// Proportions that tell individuals apart; 1 is the bundled face.
struct Proportions {
    double width = 1.0;          // head width
    double jawWidth = 1.0;       // width of the lower face
    double midfaceLength = 1.0;  // vertical extent of the nose region
    double noseProjection = 1.0; // how far the nose stands out
    double noseWidth = 1.0;
    double lipFullness = 1.0;
    double chin = 1.0;
    double cheeks = 1.0;
    double browRidge = 1.0;
    double eyeDepth = 1.0;
};

Proportions proportionsOf(Individual who);

// exp(-(du/ru)^2 - (dv/rv)^2): the smooth bump every feature is made of.
inline double bump(double u, double v, double cu, double cv, double ru, double rv) {
    const double a = (u - cu) / ru, b = (v - cv) / rv;
    return std::exp(-(a * a + b * b));
}

// Feature positions in the normalised (u,v) space (the same for every individual); the eye corners,
// mouth and nose tip are the landmarks of core/face/FaceDomain.h.
constexpr double kEyeCentreU = 0.5 * (kEyeInnerU + kEyeOuterU); // eye centres at 0.5 -/+ this
constexpr double kEyeCentreV = 0.5 * (kEyeInnerV + kEyeOuterV);
constexpr double kEyeHalfLength = 0.5 * (kEyeOuterU - kEyeInnerU); // in u
constexpr double kBrowV = 0.655;
constexpr double kSubnasaleV = 0.378;
constexpr double kNasionV = 0.615;
constexpr double kUpperLipV = 0.333; // centre of the upper vermilion
constexpr double kLowerLipV = 0.268; // centre of the lower vermilion

// The eye opening (palpebral fissure) of the eye on `side` (+1 the face's left, u > 0.5): a lens
// between the corners. Returns the position along the corner-to-corner axis in [-1 inner, 1 outer]
// (outside that range for points beyond the corners) and the opening's upper and lower half-heights
// there (in v); `offset` is the point's height above the axis.
struct EyeLens {
    double along = 0.0;
    double offset = 0.0;
    double upper = 0.0, lower = 0.0;
    // Where the point is inside the opening: 1 on the axis, 0 on the lid margins, < 0 outside.
    double inside() const;
};
EyeLens eyeLens(double u, double v);

// The two vermilion rolls (height profile of the lips, before fullness) and, from them, the weight
// in [0,1] of lip colour at (u,v).
inline double upperLipBump(double u, double v) {
    return bump(u, v, kMouthU, kUpperLipV, 0.085, 0.017);
}
inline double lowerLipBump(double u, double v) {
    return bump(u, v, kMouthU, kLowerLipV, 0.08, 0.02);
}
double lipWeight(double u, double v);
double browWeight(double u, double v);
double nostrilWeight(double u, double v);

// The eyeball of an individual (core/face/HeadParts.h places the eyeball part there): its centre in
// the face's coordinates. The lids rest on it, the opening between them shows it.
Vec3 eyeballCentre(const Proportions& p, double side);

} // namespace vl::face::detail
