#pragma once
// A user's mesh on its way to becoming the document's face (Deformation > Use my mesh..., and
// `visemelab face build`): read with its texture coordinates, landmarks suggested (from a known
// layout or the geometry), then confirmed or moved by the user before the face is built
// (edit::useOwnFace). The candidate is the step's state, not document state: nothing changes until
// the user confirms.
#include "core/face/LandmarkFinder.h"
#include "core/face/UvMesh.h"

#include <filesystem>
#include <memory>

namespace vl {

// The mesh with (u,v) from OBJ, PLY, VRML (per-corner, seams kept) or glTF/glb (the first mesh's
// neutral). Throws InputError naming the file when it cannot be read or has no (u,v).
face::UvMesh loadUvMeshFile(const std::filesystem::path& path);

struct OwnFaceCandidate {
    std::filesystem::path file;
    std::string name; // the face's name: the file's stem
    std::shared_ptr<const face::UvMesh> mesh;
    face::LandmarkSuggestion suggestion; // landmarks (found or placed), layout, what the finder saw

    const face::FaceLandmarks& landmarks() const { return suggestion.landmarks; }
    // The required landmarks still missing, comma separated (empty when the face can be built).
    std::string missingRequired() const;
};

// Reads the mesh and suggests its landmarks.
OwnFaceCandidate loadOwnFaceCandidate(const std::filesystem::path& path);

// The candidate with `landmark` placed by the user at `uv` of the mesh's texture space (source
// "file", sure 100%). Throws InputError when `uv` lies on no triangle of the mesh.
OwnFaceCandidate placeLandmark(const OwnFaceCandidate& candidate, face::Landmark landmark, const Vec2& uv);

} // namespace vl
