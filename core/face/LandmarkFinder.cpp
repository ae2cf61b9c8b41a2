#include "core/face/LandmarkFinder.h"

#include "core/face/GeometryLandmarks.h"

namespace vl::face {

LandmarkSuggestion suggestLandmarks(const UvMesh& mesh, const FaceLandmarks& given, bool useLayouts) {
    LandmarkSuggestion suggestion;
    suggestion.landmarks = given;
    const FaceLandmarks layout = useLayouts ? mediaPipeLandmarks(mesh) : FaceLandmarks{};
    if (layout[Landmark::NoseTip].found()) {
        suggestion.layout = "mediapipe";
        suggestion.notes.push_back("recognised MediaPipe's canonical face topology");
        for (const auto l : allLandmarks())
            if (!suggestion.landmarks[l].found()) suggestion.landmarks[l] = layout[l];
    }
    bool missing = false;
    for (const auto l : allLandmarks())
        missing = missing || (!suggestion.landmarks[l].found() && isRequired(l));
    if (!missing) return suggestion;
    GeometryFinding geometry = findLandmarksFromGeometry(mesh);
    suggestion.notes.insert(suggestion.notes.end(), geometry.notes.begin(), geometry.notes.end());
    for (const auto l : allLandmarks())
        if (!suggestion.landmarks[l].found()) suggestion.landmarks[l] = geometry.landmarks[l];
    return suggestion;
}

std::vector<Landmark> estimatedMouthLandmarks(const FaceLandmarks& landmarks) {
    std::vector<Landmark> estimated;
    for (const auto l : {Landmark::MouthCornerRight, Landmark::MouthCornerLeft, Landmark::UpperLipMid,
                         Landmark::LowerLipMid})
        if (landmarks[l].source == LandmarkSource::Estimate) estimated.push_back(l);
    return estimated;
}

} // namespace vl::face
