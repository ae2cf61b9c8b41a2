#pragma once
// Where a face is, which way it looks and how big it is, from its landmarks: right (towards the
// face's left eye, the bundled face's +x), up (from the mouth to the eyes), forward (right x up, out
// of the face) and two sizes. Comparing a face's frame with the bundled face's gives the rotation
// and scale that carry the bundled face's fields and parts over to it.
#include "core/deform/DeformationCascade.h"
#include "core/face/Landmarks.h"

#include <array>

namespace vl::face {

struct FaceFrame {
    Vec3 origin{0, 0, 0}; // middle of the mouth (between its corners)
    Vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1};
    double eyeDistance = 0.0;      // between the eye centres (mid-points of the corners)
    double eyeMouthDistance = 0.0; // from the eyes' middle to the mouth's middle

    // Rotation into this frame: the bundled face's x, y, z axes become right, up, forward.
    Vec3 rotate(const Vec3& bundled) const {
        return right * bundled[0] + up * bundled[1] + forward * bundled[2];
    }
    // This face's size relative to `other` (1 for the same size; 0.01 for a face in metres against
    // one in centimetres).
    double scaleTo(const FaceFrame& other) const;
};

// The frame from the positions of the required landmarks (indexed by Landmark). Throws InputError
// when they are degenerate (the eyes coincide, or lie on the line to the mouth).
FaceFrame frameFromLandmarks(const std::array<Vec3, kLandmarkCount>& positions);

// Landmark positions on a cascade's base geometry: its last Constant stage at each landmark's
// canonical (u,v) (exact for faces built from a mesh, whose alignment maps them there).
std::array<Vec3, kLandmarkCount> baseLandmarkPositions(const DeformationCascade& cascade);
// frameFromLandmarks(baseLandmarkPositions(cascade)).
FaceFrame faceFrameOf(const DeformationCascade& cascade);
// The bundled face's frame (computed once).
const FaceFrame& bundledFaceFrame();

} // namespace vl::face
