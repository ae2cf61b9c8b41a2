// The expression fields of the bundled faces (paper section 3.4 and Figure 1), as influence regions
// in the normalised (u,v) space: they apply unchanged to every individual (retargeting).
#include "core/face/FaceDomain.h"
#include "core/face/FaceShape.h"

#include <string>

namespace vl::face {

namespace {

using detail::kEyeCentreU;

InfluenceField region(Vec2 centre, Vec2 radii, Vec3 direction, double magnitude, Vec2 plateau = Vec2(0, 0),
                      Falloff falloff = Falloff::Smoothstep) {
    InfluenceField f;
    f.centre = centre;
    f.radii = radii;
    f.plateau = plateau;
    f.direction = direction;
    f.magnitude = magnitude;
    f.falloff = falloff;
    return f;
}

struct Builder {
    DeformationCascade cascade;

    // Adds a parameter and the AddVector stage it drives.
    void add(std::string name, double min, double max, std::vector<InfluenceField> regions) {
        cascade.parameters.push_back({name, min, max, 0.0});
        DeformationStage stage;
        stage.kind = StageKind::AddVector;
        stage.name = std::move(name);
        stage.parameter = cascade.parameters.size() - 1;
        stage.field.influences = std::move(regions);
        cascade.stages.push_back(std::move(stage));
    }
    // A parameter that moves a head part only (no field on the skin; core/face/HeadParts.h).
    void addPartParameter(std::string name, double min, double max) {
        cascade.parameters.push_back({name, min, max, 0.0});
    }
};

// side = +1 for the face's left (viewer's right, +x, u > 0.5), -1 for its right.
std::vector<InfluenceField> frontalis(double side) {
    // Raises the brow; strongest on the brow itself, fading up the forehead and down to the lid.
    return {region({kMouthU + side * kEyeCentreU, 0.675}, {0.13, 0.1}, {0, 1, 0.15}, 0.75, {0.06, 0.025})};
}

std::vector<InfluenceField> zygomatic(double side) {
    // Pulls the mouth corner and cheek up and out towards the temple.
    const Vec2 corner(kMouthU + side * kMouthHalfWidth, kMouthV);
    return {region(corner, {0.1, 0.09}, {side * 0.6, 0.8, -0.2}, 1.0, {0.015, 0.012}),
            region({corner[0] + side * 0.04, kMouthV + 0.07}, {0.08, 0.07}, {side * 0.3, 0.6, 0.4}, 0.35)};
}

std::vector<InfluenceField> risorius(double side) {
    // Pulls the mouth corner sideways towards the ear (a stretched, flat mouth).
    const Vec2 corner(kMouthU + side * kMouthHalfWidth, kMouthV);
    return {region(corner, {0.11, 0.075}, {side * 1.0, -0.05, -0.35}, 0.9, {0.015, 0.012})};
}

// Regions that act on the lips' rims are level along them (the hole's flat top and bottom edges)
// or centred on a lip's middle: a field sloping along a rim would fold the lip into a V. The upper
// rim's middle lies outside every region that moves the lower lip (and the other way round).
constexpr Vec2 kUpperMid{kMouthU, kMouthV + kMouthHalfHeight};
constexpr Vec2 kLowerMid{kMouthU, kMouthV - kMouthHalfHeight};

std::vector<InfluenceField> jawOpen() {
    const Vec3 down(0, -1, -0.28);
    return {// The mandible: constant over the chin and the lower lip's flat rim, falling off to zero just
            // below the upper rim; the field decreases to the jaw line. The lower teeth and the tongue
            // follow it (core/face/HeadParts.h: anchored on the chin, inside this plateau).
            region({kMouthU, 0.12}, {0.45, 0.197}, down, 2.0, {0.35, 0.163}),
            // The modioli (where the lip muscles meet beside each corner) hold the corners: the lower
            // lip follows the jaw less towards them, so its rim drops in a rounded U with about an
            // ellipse's profile along the width (0.86 of the middle's drop half-way out, 0.62 three
            // quarters out) instead of a flat bottom with steep sides (a trapezoid opening). Centred
            // below each corner, they cancel part of the mandible there; the chin (and the teeth
            // anchored on it) and the upper lip are out of their reach.
            region({kMouthU - kMouthHalfWidth, kMouthV - 0.03}, {0.1, 0.05}, -down, 1.3, {0, 0},
                   Falloff::Gaussian),
            region({kMouthU + kMouthHalfWidth, kMouthV - 0.03}, {0.1, 0.05}, -down, 1.3, {0, 0},
                   Falloff::Gaussian),
            // The lower lip drops a little further than the teeth, uncovering their edges.
            region(kLowerMid, {0.1, 0.035}, {0, -1, -0.05}, 0.2, {0.07, 0.015}),
            // The upper lip arches up a little as the lips part.
            region(kUpperMid, {0.1, 0.03}, {0, 1, 0.1}, 0.2, {0.05, 0.01})};
}

std::vector<InfluenceField> lipPucker() {
    // Lips pushed forward, corners drawn towards the middle, and the lips apart in a small rounded
    // opening (flat-topped regions on both middles).
    return {region({kMouthU, kMouthV}, {0.17, 0.11}, {0, 0, 1}, 1.0, {0.06, 0.035}),
            region({kMouthU - kMouthHalfWidth, kMouthV}, {0.075, 0.06}, {1, 0, 0.3}, 0.85),
            region({kMouthU + kMouthHalfWidth, kMouthV}, {0.075, 0.06}, {-1, 0, 0.3}, 0.85),
            region(kUpperMid, {0.065, 0.03}, {0, 1, 0.15}, 0.32, {0.025, 0.01}),
            region(kLowerMid, {0.065, 0.03}, {0, -1, 0.15}, 0.32, {0.025, 0.01})};
}

std::vector<InfluenceField> lipPress() {
    // Lips rolled in and pressed together: thinner, the rims meeting.
    return {region({kMouthU, kMouthV + 0.035}, {0.11, 0.045}, {0, -0.1, -1}, 0.35, {0.05, 0.012}),
            region({kMouthU, kMouthV - 0.035}, {0.11, 0.045}, {0, 0.1, -1}, 0.35, {0.05, 0.012})};
}

std::vector<InfluenceField> upperLipRaise() {
    // The upper lip's middle lifts (the plateau holds its rim), uncovering the upper teeth.
    return {region({kMouthU, kMouthV + 0.045}, {0.12, 0.06}, {0, 1, 0.25}, 0.55, {0.06, 0.025})};
}

std::vector<InfluenceField> lowerLipTuck() {
    // The lower lip rises and rolls back under the upper teeth (F, V).
    return {region(kLowerMid, {0.11, 0.038}, {0, 0.6, -1}, 0.5, {0.05, 0.015})};
}

} // namespace

DeformationCascade makeFaceCascade(Individual who) {
    Builder b;
    b.cascade.name = std::string(toString(who)) + " face";
    DeformationStage base;
    base.kind = StageKind::Constant;
    base.name = "base_geometry";
    base.field.sampled = makeFaceGeometry(who);
    b.cascade.stages.push_back(std::move(base));
    b.add("frontalis_l", -0.5, 1.0, frontalis(1));
    b.add("frontalis_r", -0.5, 1.0, frontalis(-1));
    b.add("zygomatic_l", 0.0, 1.0, zygomatic(1));
    b.add("zygomatic_r", 0.0, 1.0, zygomatic(-1));
    b.add("risorius_l", 0.0, 1.0, risorius(1));
    b.add("risorius_r", 0.0, 1.0, risorius(-1));
    b.add("jaw_open", 0.0, 1.0, jawOpen());
    b.add("lip_pucker", 0.0, 1.0, lipPucker());
    b.add("lip_press", 0.0, 1.0, lipPress());
    b.add("upper_lip_raise", 0.0, 1.0, upperLipRaise());
    b.add("lower_lip_tuck", 0.0, 1.0, lowerLipTuck());
    b.addPartParameter("tongue_up", 0.0, 1.0);
    b.addPartParameter("tongue_out", 0.0, 1.0);
    return b.cascade;
}

DeformationCascade makeBundledFace() {
    return makeFaceCascade(Individual::Bundled);
}

DeformationCascade makeRetargetFace() {
    VectorField base;
    base.sampled = makeFaceGeometry(Individual::Retarget);
    return retarget(makeBundledFace(), base, std::string(toString(Individual::Retarget)) + " face");
}

} // namespace vl::face
