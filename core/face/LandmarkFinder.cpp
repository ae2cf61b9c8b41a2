#include "core/face/LandmarkFinder.h"

namespace vl::face {

LandmarkSuggestion suggestLandmarks(const UvMesh& mesh, const FaceLandmarks& given) {
    LandmarkSuggestion suggestion;
    suggestion.landmarks = given;
    const FaceLandmarks layout = mediaPipeLandmarks(mesh);
    if (layout[Landmark::NoseTip].found()) {
        suggestion.layout = "mediapipe";
        suggestion.notes.push_back("recognised MediaPipe's canonical face topology");
        for (const auto l : allLandmarks())
            if (!suggestion.landmarks[l].found()) suggestion.landmarks[l] = layout[l];
    }
    return suggestion;
}

} // namespace vl::face
