// Landmarks of meshes with MediaPipe's canonical face topology (468 vertices, or 478 with the irises):
// the face geometry module's canonical_face_model.obj and every face fitted with it share vertex
// numbering, so the landmarks are vertices. Recognised by a few triangles around those vertices.
#include "core/face/LandmarkFinder.h"

#include <algorithm>
#include <set>

namespace vl::face {

namespace {

struct LayoutVertex {
    Landmark landmark;
    std::uint32_t vertex;
};

// The inner lip contour's corners (78, 308) are where the lips meet; 13/14 its middles, 81/311 and
// 178/402 its quarter points; 33/133/362/263 the eye corners; 4 the nose tip (pronasale).
constexpr LayoutVertex kVertices[] = {
    {Landmark::MouthCornerRight, 78}, {Landmark::MouthCornerLeft, 308}, {Landmark::UpperLipMid, 13},
    {Landmark::LowerLipMid, 14},      {Landmark::EyeOuterRight, 33},    {Landmark::EyeInnerRight, 133},
    {Landmark::EyeInnerLeft, 362},    {Landmark::EyeOuterLeft, 263},    {Landmark::NoseTip, 4},
    {Landmark::UpperLipRight, 81},    {Landmark::UpperLipLeft, 311},    {Landmark::LowerLipRight, 178},
    {Landmark::LowerLipLeft, 402}};

// One triangle of the canonical topology at each landmark vertex (0-based).
constexpr std::uint32_t kSignature[][3] = {{78, 95, 191},  {308, 415, 324}, {12, 13, 268},   {15, 316, 14},
                                           {246, 33, 7},   {173, 155, 133}, {382, 398, 362}, {263, 466, 249},
                                           {4, 275, 5},    {41, 42, 81},    {271, 311, 272}, {178, 88, 179},
                                           {402, 403, 318}};

} // namespace

FaceLandmarks mediaPipeLandmarks(const UvMesh& mesh) {
    FaceLandmarks none;
    if (mesh.positions.size() != 468 && mesh.positions.size() != 478) return none;
    std::set<std::array<std::uint32_t, 3>> triangles;
    for (const auto& t : mesh.triangles) {
        std::array<std::uint32_t, 3> sorted{t[0], t[1], t[2]};
        std::sort(sorted.begin(), sorted.end());
        triangles.insert(sorted);
    }
    for (const auto& s : kSignature) {
        std::array<std::uint32_t, 3> sorted{s[0], s[1], s[2]};
        std::sort(sorted.begin(), sorted.end());
        if (!triangles.count(sorted)) return none;
    }
    FaceLandmarks found;
    for (const auto& [landmark, vertex] : kVertices) {
        LandmarkInput input;
        input.kind = LandmarkInput::Kind::Vertex;
        input.vertex = vertex;
        found[landmark] =
            resolveLandmark(mesh, input, LandmarkSource::Layout, 0.98,
                            "MediaPipe face topology, vertex " + std::to_string(vertex), toString(landmark));
    }
    return found;
}

} // namespace vl::face
