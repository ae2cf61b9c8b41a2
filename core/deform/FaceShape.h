#pragma once
// Internal to the bundled face: the analytic shapes behind its geometry image and preview colours.
#include "core/deform/BundledFace.h"
#include "core/deform/FaceDomain.h"

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

// Landmarks in the normalised (u,v) space (the same for every individual).
constexpr double kEyeU = 0.135; // eye centres at 0.5 -/+ kEyeU
constexpr double kEyeV = 0.585;
constexpr double kBrowV = 0.66;
constexpr double kSubnasaleV = 0.372;
constexpr double kNasionV = 0.615;
constexpr double kUpperLipV = 0.333; // centre of the upper vermilion
constexpr double kLowerLipV = 0.268; // centre of the lower vermilion

// The two vermilion rolls (height profile of the lips, before fullness) and, from them, the weight
// in [0,1] of lip colour at (u,v).
inline double upperLipBump(double u, double v) {
    return bump(u, v, kMouthU, kUpperLipV, 0.085, 0.017);
}
inline double lowerLipBump(double u, double v) {
    return bump(u, v, kMouthU, kLowerLipV, 0.08, 0.02);
}
double lipWeight(double u, double v);
// Weight of the visible eyeball (between the lids) and of the iris, for colours.
double eyeWhiteWeight(double u, double v);
double irisWeight(double u, double v);
double browWeight(double u, double v);
double nostrilWeight(double u, double v);

} // namespace vl::face::detail
