#pragma once
// The real faces in VISEMELAB_SHARED_DATA_DIR the face tests use (never copied into the repository),
// how to skip loudly without them, and how to read one as a UvMesh.
#include "core/face/Landmarks.h"
#include "core/face/UvMesh.h"
#include "core/io/MeshIO.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl::face::test {

inline const std::filesystem::path kShared = VISEMELAB_SHARED_DATA_DIR;
inline const std::filesystem::path kMediaPipe =
    kShared / "mediapipe-canonical-face" / "canonical_face_model.obj";
inline const std::filesystem::path kIct = kShared / "ict-facekit-mouth" / "generic_neutral_mesh.obj";

inline UvMesh loadUvMesh(const std::filesystem::path& path) {
    CornerTexCoords corners;
    const MeshData mesh = readMesh(path, corners);
    return makeUvMesh(mesh, corners, path.string());
}

// Every landmark at its canonical position in texture space: for meshes whose (u,v) are the face
// domain's (the bundled sample's skin, analytic test surfaces), where the alignment is the identity
// (apart from the mouth squeeze and retraction it applies in the domain).
inline FaceLandmarks canonicalLandmarks(const UvMesh& mesh) {
    FaceLandmarks landmarks;
    for (const auto l : allLandmarks()) {
        LandmarkInput input;
        input.uv = canonicalPosition(l);
        landmarks[l] = resolveLandmark(mesh, input, LandmarkSource::File, 1.0, "test", toString(l));
    }
    return landmarks;
}

} // namespace vl::face::test

#define SKIP_WITHOUT(path)                                                                                   \
    if (!std::filesystem::exists(path))                                                                      \
    GTEST_SKIP() << "shared data missing: " << (path)                                                        \
                 << " (set VISEMELAB_SHARED_DATA_DIR to the folder holding it)"
