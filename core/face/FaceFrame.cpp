#include "core/face/FaceFrame.h"

#include "core/common/Error.h"
#include "core/face/BundledFace.h"

namespace vl::face {

namespace {

Vec3 at(const std::array<Vec3, kLandmarkCount>& p, Landmark l) {
    return p[static_cast<std::size_t>(l)];
}

} // namespace

double FaceFrame::scaleTo(const FaceFrame& other) const {
    return 0.5 * (eyeDistance / other.eyeDistance + eyeMouthDistance / other.eyeMouthDistance);
}

FaceFrame frameFromLandmarks(const std::array<Vec3, kLandmarkCount>& p) {
    const Vec3 eyeRight = (at(p, Landmark::EyeOuterRight) + at(p, Landmark::EyeInnerRight)) * 0.5;
    const Vec3 eyeLeft = (at(p, Landmark::EyeOuterLeft) + at(p, Landmark::EyeInnerLeft)) * 0.5;
    const Vec3 mouth = (at(p, Landmark::MouthCornerRight) + at(p, Landmark::MouthCornerLeft)) * 0.5;
    const Vec3 eyes = (eyeRight + eyeLeft) * 0.5;
    FaceFrame f;
    f.origin = mouth;
    f.eyeDistance = (eyeLeft - eyeRight).norm();
    f.eyeMouthDistance = (eyes - mouth).norm();
    if (f.eyeDistance <= 0.0 || f.eyeMouthDistance <= 0.0)
        throwInputError("landmarks", "the eyes and the mouth do not span a face (they coincide)");
    f.right = (eyeLeft - eyeRight) / f.eyeDistance;
    Vec3 up = eyes - mouth;
    up -= f.right * OpenMesh::dot(up, f.right);
    if (up.norm() < 1e-6 * f.eyeMouthDistance)
        throwInputError("landmarks", "the eyes and the mouth lie on one line");
    f.up = up.normalized();
    f.forward = OpenMesh::cross(f.right, f.up);
    // A mirrored mesh (left-handed coordinates) has its nose behind right x up: the frame mirrors
    // too, so fields that push the lips forward still push them out of the face.
    if (OpenMesh::dot(at(p, Landmark::NoseTip) - mouth, f.forward) < 0.0) f.forward = -f.forward;
    return f;
}

std::array<Vec3, kLandmarkCount> baseLandmarkPositions(const DeformationCascade& cascade) {
    const DeformationStage* base = nullptr;
    for (const auto& stage : cascade.stages)
        if (stage.kind == StageKind::Constant) base = &stage;
    std::array<Vec3, kLandmarkCount> p{};
    if (!base) throwInputError("deformation cascade '" + cascade.name + "'", "has no base geometry");
    for (const auto l : allLandmarks()) {
        const Vec2 c = canonicalPosition(l);
        p[static_cast<std::size_t>(l)] = base->field.at(c[0], c[1]);
    }
    return p;
}

FaceFrame faceFrameOf(const DeformationCascade& cascade) {
    return frameFromLandmarks(baseLandmarkPositions(cascade));
}

const FaceFrame& bundledFaceFrame() {
    static const FaceFrame frame = faceFrameOf(makeBundledFace());
    return frame;
}

} // namespace vl::face
