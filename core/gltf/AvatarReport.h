#pragma once
// What `visemelab avatar inspect` reports about an avatar: meshes, primitives, vertex counts,
// storage (Draco, meshopt, quantised, sparse), which targets are visemes and which were ignored
// and why. As text for people and as JSON for tools (and inside the `avatar reduce` report).
#include "core/gltf/AvatarScan.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vl {

std::string formatAvatarReport(const AvatarScan& scan);
// The part of it about one mesh: node, skin, primitives (vertices, storage), its visemes and the
// targets kept as they are, with why.
std::string formatAvatarMeshReport(const AvatarMesh& mesh);
nlohmann::ordered_json avatarReportJson(const AvatarScan& scan);

// Patterns of known naming conventions that match some target of the file (e.g. VRoid's
// "Fcl_MTH_[AIUEO]"), suggested when the default selection finds no viseme.
std::vector<std::string> suggestedPatterns(const AvatarScan& scan);

} // namespace vl
