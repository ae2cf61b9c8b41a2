#pragma once
// Facial landmarks that align a user's mesh with the normalised face domain: where they sit in the
// domain (the same for every individual) and where they were found on the user's mesh, with how
// and how sure. "Right" and "left" are the face's own (its right is the viewer's left, u < 0.5).
#include "core/common/EnumNames.h"
#include "core/mesh/Mesh.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vl::face {

enum class Landmark {
    MouthCornerRight,
    MouthCornerLeft,
    UpperLipMid, // on the line where the lips meet (the inner lip contour), in the middle
    LowerLipMid,
    EyeOuterRight,
    EyeInnerRight,
    EyeInnerLeft,
    EyeOuterLeft,
    NoseTip,
    // Optional: the lips' meeting line half-way between the middle and each corner. They let the
    // alignment follow a curved mouth; without them it interpolates.
    UpperLipRight,
    UpperLipLeft,
    LowerLipRight,
    LowerLipLeft,
};
constexpr std::size_t kLandmarkCount = 13;
constexpr std::size_t kRequiredLandmarkCount = 9; // the ones before UpperLipRight

// Names (EnumNames below): "mouth_corner_right", "upper_lip_mid", "eye_outer_left", "nose_tip", ...
inline bool isRequired(Landmark landmark) {
    return static_cast<std::size_t>(landmark) < kRequiredLandmarkCount;
}

// The landmark's position in the normalised face domain (core/face/FaceDomain.h): the mouth
// corners and lip middles are the corners of the mouth hole.
Vec2 canonicalPosition(Landmark landmark);

enum class LandmarkSource {
    Missing,  // not found
    File,     // given by the user (--landmarks, or the editor)
    Layout,   // a known (u,v) layout / topology (e.g. MediaPipe's canonical face)
    Geometry, // found from the shape (mouth opening, symmetry plane, nose tip)
    Estimate, // inferred from proportions of the landmarks that were found
};
std::string_view sourceName(LandmarkSource source); // "missing", "file", "layout", "geometry", "estimate"

struct FoundLandmark {
    LandmarkSource source = LandmarkSource::Missing;
    Vec2 uv{0, 0};           // in the mesh's texture space
    Vec3 position{0, 0, 0};  // on the mesh
    double confidence = 0.0; // 0..1: how sure the finder is (1 for landmarks the user gave)
    std::string method;      // how it was found, e.g. "MediaPipe canonical face, vertex 13"
    int island = -1;         // UV island of the mesh it lies on (-1: not resolved yet)

    bool found() const { return source != LandmarkSource::Missing; }
};

struct FaceLandmarks {
    std::array<FoundLandmark, kLandmarkCount> at;

    FoundLandmark& operator[](Landmark l) { return at[static_cast<std::size_t>(l)]; }
    const FoundLandmark& operator[](Landmark l) const { return at[static_cast<std::size_t>(l)]; }
    bool hasRequired() const;
};

struct UvMesh;

// A landmark as a user gives it: a point of the mesh's texture space, a 3D point (projected onto the
// mesh), or a vertex index (as the file numbers vertices, from 0).
struct LandmarkInput {
    enum class Kind { UV, Position, Vertex } kind = Kind::UV;
    Vec2 uv{0, 0};
    Vec3 position{0, 0, 0};
    std::uint32_t vertex = 0;
};

// The landmark on the mesh: (u,v), position and island filled in consistently. A (u,v) that several
// islands overlap takes the island of largest area; a vertex on a UV seam takes its corner in the
// largest island. Throws InputError naming `where` for a vertex out of range or a (u,v) on no
// triangle.
FoundLandmark resolveLandmark(const UvMesh& mesh, const LandmarkInput& input, LandmarkSource source,
                              double confidence, std::string method, std::string_view where);

constexpr std::array<Landmark, kLandmarkCount> allLandmarks() {
    std::array<Landmark, kLandmarkCount> all{};
    for (std::size_t k = 0; k < kLandmarkCount; ++k) all[k] = static_cast<Landmark>(k);
    return all;
}

} // namespace vl::face

namespace vl {
template <> struct EnumNames<face::Landmark> {
    static constexpr const char* what = "landmark";
    static constexpr EnumName<face::Landmark> names[] = {
        {face::Landmark::MouthCornerRight, "mouth_corner_right"},
        {face::Landmark::MouthCornerLeft, "mouth_corner_left"},
        {face::Landmark::UpperLipMid, "upper_lip_mid"},
        {face::Landmark::LowerLipMid, "lower_lip_mid"},
        {face::Landmark::EyeOuterRight, "eye_outer_right"},
        {face::Landmark::EyeInnerRight, "eye_inner_right"},
        {face::Landmark::EyeInnerLeft, "eye_inner_left"},
        {face::Landmark::EyeOuterLeft, "eye_outer_left"},
        {face::Landmark::NoseTip, "nose_tip"},
        {face::Landmark::UpperLipRight, "upper_lip_right"},
        {face::Landmark::UpperLipLeft, "upper_lip_left"},
        {face::Landmark::LowerLipRight, "lower_lip_right"},
        {face::Landmark::LowerLipLeft, "lower_lip_left"}};
};
static_assert(std::size(EnumNames<face::Landmark>::names) == face::kLandmarkCount);
} // namespace vl
