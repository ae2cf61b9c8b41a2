#pragma once
// The bundled deformable face (paper section 3.4): a base geometry image generated procedurally from
// analytic shapes (an ellipsoid-like head front plus smooth bumps: forehead, brow ridge, eye sockets
// with eyeballs and lids, nose with nostrils, lips, chin, cheeks, jaw line) and AddVector fields for
// the muscles that visemes need, split left/right where the paper does. A second individual (other
// proportions) reuses the same fields unchanged: retargeting. Units are centimetres; the face looks
// along +z, +y is up, +x is the viewer's right (the face's left).
#include "core/common/EnumNames.h"
#include "core/deform/DeformationCascade.h"

#include <span>
#include <string_view>
#include <vector>

namespace vl::face {

enum class Individual { Bundled, Retarget };

// Base geometry image of an individual, sampled on a gridSize x gridSize grid.
SampledField makeFaceGeometry(Individual who, int gridSize = 301);

// The expression fields of every individual, in cascade order, with their parameters.
// Parameter names: frontalis_l, frontalis_r, zygomatic_l, zygomatic_r, risorius_l, risorius_r,
// jaw_open, lip_pucker, lip_press, upper_lip_raise, lower_lip_tuck.
DeformationCascade makeFaceCascade(Individual who);
DeformationCascade makeBundledFace();  // makeFaceCascade(Individual::Bundled)
DeformationCascade makeRetargetFace(); // retarget(makeBundledFace(), its geometry): same fields

// The eyeball an individual's lids rest on (core/face/HeadParts.h puts the eyeball part there): its
// centre for the eye on `side` (+1 the face's left, -1 its right), in centimetres.
Vec3 eyeballCentre(Individual who, double side);
constexpr double kEyeballRadius = 1.2;

// Preview colours (RGB in [0,1]) at each (u,v): on the skin the regions (lips, brows, nostrils, eye
// openings), and the head's parts by their tile (face::HeadTile): eyeballs, teeth, tongue, cavity.
std::vector<Vec3> faceColours(std::span<const Vec2> uvs);

} // namespace vl::face

namespace vl {
template <> struct EnumNames<face::Individual> {
    static constexpr const char* what = "face";
    static constexpr EnumName<face::Individual> names[] = {{face::Individual::Bundled, "bundled"},
                                                           {face::Individual::Retarget, "retarget"}};
};
} // namespace vl
