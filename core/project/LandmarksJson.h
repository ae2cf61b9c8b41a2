#pragma once
// Landmark files (`visemelab face build --landmarks L.json`; docs/deformable-face.md):
//   {"format": "visemelab-landmarks",                        (optional)
//    "landmarks": {"nose_tip": {"vertex": 4},
//                  "mouth_corner_left": {"uv": [0.6, 0.31]},
//                  "eye_inner_right": {"position": [-1.8, 2.6, 3.7]}, ...}}
// Each landmark is a vertex index (from 0, as the mesh file orders vertices), a (u,v) of the mesh's
// texture space, or a 3D point (projected onto the mesh); when several are given the first of
// vertex, uv, position counts. The file `face build` writes also records the position, where each
// landmark came from and how sure the finder was ("source", "confidence", "method"): it reads back.
// Landmarks left out are found automatically.
#include "core/face/Landmarks.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vl {

// Throws InputError "<file>: <JSON path>: <what>" for unknown landmark names, bad values or
// a landmark given twice.
std::vector<std::pair<face::Landmark, face::LandmarkInput>>
readLandmarkFile(const std::filesystem::path& file);
std::vector<std::pair<face::Landmark, face::LandmarkInput>> landmarksFromJsonText(std::string_view text,
                                                                                  std::string_view source);

// The found landmarks as a landmark file (uv, position, source, confidence, method).
std::string landmarksToJsonText(const face::FaceLandmarks& landmarks);

} // namespace vl
