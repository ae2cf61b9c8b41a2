#include "core/document/OwnFace.h"

#include "core/common/Error.h"
#include "core/import/GltfImport.h"
#include "core/io/MeshIO.h"

#include <algorithm>
#include <cctype>

namespace vl {

face::UvMesh loadUvMeshFile(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".glb" || ext == ".gltf") return face::makeUvMesh(readGltf(path).neutral, path.string());
    CornerTexCoords corners;
    const MeshData mesh = readMesh(path, corners);
    return face::makeUvMesh(mesh, corners, path.string());
}

std::string OwnFaceCandidate::missingRequired() const {
    std::string missing;
    for (const auto l : face::allLandmarks())
        if (face::isRequired(l) && !landmarks()[l].found())
            missing += (missing.empty() ? "" : ", ") + std::string(toString(l));
    return missing;
}

OwnFaceCandidate loadOwnFaceCandidate(const std::filesystem::path& path) {
    OwnFaceCandidate candidate;
    candidate.file = path;
    candidate.name = path.stem().string();
    auto mesh = std::make_shared<const face::UvMesh>(loadUvMeshFile(path));
    candidate.suggestion = face::suggestLandmarks(*mesh);
    candidate.mesh = std::move(mesh);
    return candidate;
}

OwnFaceCandidate placeLandmark(const OwnFaceCandidate& candidate, face::Landmark landmark, const Vec2& uv) {
    if (!candidate.mesh) throwInputError("landmark", "no mesh loaded");
    face::LandmarkInput input;
    input.uv = uv;
    OwnFaceCandidate next = candidate;
    next.suggestion.landmarks[landmark] = face::resolveLandmark(
        *candidate.mesh, input, face::LandmarkSource::File, 1.0, "placed by you", toString(landmark));
    return next;
}

} // namespace vl
