#pragma once
// Finding the landmarks of a user's face automatically, saying how and how sure:
//  - from a known layout: a mesh with MediaPipe's canonical face topology (the canonical face, a face
//    fitted to a photo, the iris variant) has its landmarks at known vertices, whatever its (u,v) or
//    pose;
//  - otherwise from the geometry (core/face/GeometryLandmarks.h): symmetry plane, nose tip, mouth and
//    eye openings, with proportions filling in what the shape does not show.
// Landmarks the user gives are kept as they are; only the others are found.
#include "core/face/Landmarks.h"
#include "core/face/UvMesh.h"

#include <string>
#include <vector>

namespace vl::face {

// The landmarks of a mesh with MediaPipe's face topology, or an empty result (every landmark
// missing) when the mesh does not have it.
FaceLandmarks mediaPipeLandmarks(const UvMesh& mesh);

struct LandmarkSuggestion {
    FaceLandmarks landmarks;
    std::string layout; // "mediapipe" when a known layout was recognised, else empty
    std::vector<std::string>
        notes; // what the finder saw (e.g. "mouth opening: boundary loop of 74 vertices")
};

// Keeps every landmark `given` has and finds the others; `useLayouts` false skips the known layouts
// (to check the geometry finder on a mesh whose layout gives the answer).
LandmarkSuggestion suggestLandmarks(const UvMesh& mesh, const FaceLandmarks& given = {},
                                    bool useLayouts = true);

// The mouth's landmarks (corners and lip middles) that were neither given nor found, only estimated
// from the face's proportions. The visemes move the mouth, so a build on an estimated mouth would
// animate the wrong place: `face build` refuses it unless told to accept estimates. Estimated eyes
// only misplace the brow fields and are reported, not refused.
std::vector<Landmark> estimatedMouthLandmarks(const FaceLandmarks& landmarks);

} // namespace vl::face
