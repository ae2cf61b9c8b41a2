#include "core/face/Landmarks.h"

#include "core/common/Error.h"
#include "core/face/FaceDomain.h"
#include "core/face/UvMesh.h"

#include <limits>

namespace vl::face {

Vec2 canonicalPosition(Landmark landmark) {
    const double h = kMouthHalfHeight, w = kMouthHalfWidth;
    switch (landmark) {
    case Landmark::MouthCornerRight:
        return {kMouthU - w, kMouthV};
    case Landmark::MouthCornerLeft:
        return {kMouthU + w, kMouthV};
    case Landmark::UpperLipMid:
        return {kMouthU, kMouthV + h};
    case Landmark::LowerLipMid:
        return {kMouthU, kMouthV - h};
    case Landmark::EyeOuterRight:
        return {kMouthU - kEyeOuterU, kEyeOuterV};
    case Landmark::EyeInnerRight:
        return {kMouthU - kEyeInnerU, kEyeInnerV};
    case Landmark::EyeInnerLeft:
        return {kMouthU + kEyeInnerU, kEyeInnerV};
    case Landmark::EyeOuterLeft:
        return {kMouthU + kEyeOuterU, kEyeOuterV};
    case Landmark::NoseTip:
        return {kMouthU, kNoseTipV};
    case Landmark::UpperLipRight:
        return {kMouthU - w / 2, kMouthV + mouthHoleHalfHeight(kMouthU - w / 2)};
    case Landmark::UpperLipLeft:
        return {kMouthU + w / 2, kMouthV + mouthHoleHalfHeight(kMouthU + w / 2)};
    case Landmark::LowerLipRight:
        return {kMouthU - w / 2, kMouthV - mouthHoleHalfHeight(kMouthU - w / 2)};
    case Landmark::LowerLipLeft:
        return {kMouthU + w / 2, kMouthV - mouthHoleHalfHeight(kMouthU + w / 2)};
    }
    return {0, 0};
}

std::string_view sourceName(LandmarkSource source) {
    switch (source) {
    case LandmarkSource::Missing:
        return "missing";
    case LandmarkSource::File:
        return "file";
    case LandmarkSource::Layout:
        return "layout";
    case LandmarkSource::Geometry:
        return "geometry";
    case LandmarkSource::Estimate:
        return "estimate";
    }
    return "?";
}

bool FaceLandmarks::hasRequired() const {
    for (std::size_t k = 0; k < kRequiredLandmarkCount; ++k)
        if (!at[k].found()) return false;
    return true;
}

FoundLandmark resolveLandmark(const UvMesh& mesh, const LandmarkInput& input, LandmarkSource source,
                              double confidence, std::string method, std::string_view where) {
    FoundLandmark found;
    found.source = source;
    found.confidence = confidence;
    found.method = std::move(method);
    const auto islands = describeIslands(mesh);
    const auto bigger = [&](std::uint32_t a, std::uint32_t b) { return islands[a].area > islands[b].area; };
    UvHit hit;
    switch (input.kind) {
    case LandmarkInput::Kind::Vertex: {
        if (input.vertex >= mesh.positions.size())
            throwInputError(where, "vertex " + std::to_string(input.vertex) +
                                       " is out of range (the mesh has " +
                                       std::to_string(mesh.positions.size()) + " vertices)");
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                if (mesh.triangles[t][k] == input.vertex &&
                    (!hit.found || bigger(mesh.island[t], mesh.island[hit.triangle]))) {
                    hit.found = true;
                    hit.triangle = t;
                    for (int c = 0; c < 3; ++c) hit.b[c] = c == k ? 1.0 : 0.0;
                }
        if (!hit.found)
            throwInputError(where, "vertex " + std::to_string(input.vertex) +
                                       " is on no triangle with texture coordinates");
        hit.position = mesh.positions[input.vertex];
        break;
    }
    case LandmarkInput::Kind::Position:
        hit = closestSurfacePoint(mesh, input.position);
        break;
    case LandmarkInput::Kind::UV:
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tex = mesh.texTriangles[t];
            double w[3];
            barycentric(input.uv, mesh.texCoords[tex[0]], mesh.texCoords[tex[1]], mesh.texCoords[tex[2]], w);
            if (std::min({w[0], w[1], w[2]}) < -1e-9) continue;
            if (hit.found && !bigger(mesh.island[t], mesh.island[hit.triangle])) continue;
            hit.found = true;
            hit.triangle = t;
            std::copy(w, w + 3, hit.b);
        }
        if (!hit.found)
            throwInputError(where, "(u,v) (" + std::to_string(input.uv[0]) + ", " +
                                       std::to_string(input.uv[1]) + ") lies on no triangle of the mesh");
        {
            const auto& tri = mesh.triangles[hit.triangle];
            hit.position = mesh.positions[tri[0]] * hit.b[0] + mesh.positions[tri[1]] * hit.b[1] +
                           mesh.positions[tri[2]] * hit.b[2];
        }
        break;
    }
    found.uv = uvOf(mesh, hit);
    found.position = hit.position;
    found.island = static_cast<int>(mesh.island[hit.triangle]);
    return found;
}

} // namespace vl::face
