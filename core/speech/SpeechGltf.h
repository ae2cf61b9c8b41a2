#pragma once
// A face track as a glTF morph weight animation (core/export/GltfAnimation.h): the same motion the
// runtime's KeyframeAnimation plays. Linear and cubic (Catmull-Rom Hermite) tracks are exported
// exactly as their keyframes (glTF LINEAR and CUBICSPLINE interpolate weights the same way);
// dominance blending, which glTF cannot express, is sampled at `fps` with LINEAR in between.
#include "core/export/GltfAnimation.h"
#include "core/speech/FaceTrack.h"

namespace vl {

GltfMorphAnimation gltfAnimationOf(const FaceTrack& face, double fps);

// The track sampled at t = f / fps (and at its end) through FaceTrack::keyWeights.
GltfMorphAnimation sampledGltfAnimation(const FaceTrack& face, double fps);

} // namespace vl
