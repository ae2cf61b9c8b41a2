#pragma once
// Landmarks from the shape of a face mesh of unknown layout, pose and units (see the .cpp for the
// steps). Each landmark says how it was found and how sure the finder is.
#include "core/face/Landmarks.h"
#include "core/face/UvMesh.h"

#include <string>
#include <vector>

namespace vl::face {

struct GeometryFinding {
    FaceLandmarks landmarks;
    std::vector<std::string> notes;
};

GeometryFinding findLandmarksFromGeometry(const UvMesh& mesh);

} // namespace vl::face
