// The expression fields of the bundled faces (paper section 3.4 and Figure 1), as influence regions
// in the normalised (u,v) space: they apply unchanged to every individual (retargeting).
#include "core/deform/FaceDomain.h"
#include "core/deform/FaceShape.h"

#include <string>

namespace vl::face {

namespace {

using detail::kEyeU;

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
};

// side = +1 for the face's left (viewer's right, +x, u > 0.5), -1 for its right.
std::vector<InfluenceField> frontalis(double side) {
    // Raises the brow; strongest on the brow itself, fading up the forehead and down to the lid.
    return {region({kMouthU + side * kEyeU, 0.675}, {0.13, 0.1}, {0, 1, 0.15}, 0.75, {0.06, 0.025})};
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

std::vector<InfluenceField> jawOpen() {
    // Constant over the chin and the lower lip, zero at the upper lip; the outer ellipse meets the
    // mouth line at the corners, so the lower rim opens in an arc; decreasing to the border.
    return {region({kMouthU, 0.12}, {0.42, 0.186}, {0, -1, -0.3}, 2.1, {0.22, 0.16}),
            // rounds the lower lip's arc, and lifts the upper lip a little as the lips part
            region({kMouthU, kMouthV - kMouthHalfHeight}, {0.12, 0.03}, {0, -1, -0.1}, 0.5, {0, 0},
                   Falloff::Cosine),
            region({kMouthU, kMouthV + kMouthHalfHeight}, {0.12, 0.03}, {0, 1, 0.1}, 0.3, {0, 0},
                   Falloff::Cosine),
            // thin regions hugging the lower rim half-way to each corner (too thin to reach the upper
            // rim): they widen the opening from a V into a U
            region({kMouthU - 0.055, kMouthV - 0.013}, {0.05, 0.017}, {0, -1, -0.1}, 0.8),
            region({kMouthU + 0.055, kMouthV - 0.013}, {0.05, 0.017}, {0, -1, -0.1}, 0.8)};
}

std::vector<InfluenceField> lipPucker() {
    // Forward over the lips, corners drawn to the middle, lips rounded slightly apart.
    return {region({kMouthU, kMouthV}, {0.17, 0.11}, {0, 0, 1}, 1.0, {0.06, 0.035}),
            region({kMouthU - kMouthHalfWidth, kMouthV}, {0.075, 0.06}, {1, 0, 0.3}, 0.85),
            region({kMouthU + kMouthHalfWidth, kMouthV}, {0.075, 0.06}, {-1, 0, 0.3}, 0.85),
            region({kMouthU, kMouthV + 0.035}, {0.07, 0.035}, {0, 1, 0.2}, 0.25),
            region({kMouthU, kMouthV - 0.035}, {0.07, 0.035}, {0, -1, 0.2}, 0.25)};
}

std::vector<InfluenceField> lipPress() {
    // Lips rolled in and pressed together: thinner, the rims meeting.
    return {region({kMouthU, kMouthV + 0.035}, {0.11, 0.045}, {0, -0.1, -1}, 0.4, {0.05, 0.012}),
            region({kMouthU, kMouthV - 0.035}, {0.11, 0.045}, {0, 0.1, -1}, 0.4, {0.05, 0.012})};
}

std::vector<InfluenceField> upperLipRaise() {
    return {region({kMouthU, kMouthV + 0.045}, {0.12, 0.06}, {0, 1, 0.25}, 0.55, {0.05, 0.02})};
}

std::vector<InfluenceField> lowerLipTuck() {
    // The lower lip rises and rolls back under the upper teeth (F, V).
    return {region({kMouthU, kMouthV - 0.035}, {0.11, 0.05}, {0, 0.45, -1}, 0.6, {0.05, 0.015})};
}

} // namespace

DeformationCascade makeFaceCascade(Individual who) {
    Builder b;
    b.cascade.name = std::string(individualName(who)) + " face";
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
    return b.cascade;
}

DeformationCascade makeBundledFace() {
    return makeFaceCascade(Individual::Bundled);
}

DeformationCascade makeRetargetFace() {
    VectorField base;
    base.sampled = makeFaceGeometry(Individual::Retarget);
    return retarget(makeBundledFace(), base, std::string(individualName(Individual::Retarget)) + " face");
}

} // namespace vl::face
