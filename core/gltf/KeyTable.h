#pragma once
// The layout of the key table `avatar reduce` writes (version 2 of extras.visemelab; docs/avatars.md,
// "Extras written"), shared by the writer (core/gltf/AvatarWriter.cpp) and the readers
// (core/gltf/OwnOutput.cpp; app/web/visemelab-player.js follows the same rule). The table is written
// once, at the root; a mesh lists per key only its targets (extras.visemeKeys, one array per key) and
// aliases only the viseme names that impliedTarget() does not already resolve to the right target.
// Version 1 (every mesh repeating names, members, frequencies and every alias) is still read.
#include <string>
#include <vector>

namespace vl {

constexpr int kKeyTableVersion = 2;

// A frequency as written: 4 significant digits. Readers report it and speech carries it along; no
// computation depends on the digits beyond (the bundled tables give 3 to 4), and each one costs a byte.
double writtenFrequency(double frequency);

// The target viseme `name` resolves to on a mesh without an alias of its own: the target of that name
// in `targetNames` (the last one, as three.js's morphTargetDictionary keeps it), else the first target
// on the mesh of the key listing it as a member (`members[k]`, `keyTargets[k]`), else -1.
int impliedTarget(const std::string& name, const std::vector<std::string>& targetNames,
                  const std::vector<std::vector<std::string>>& members,
                  const std::vector<std::vector<int>>& keyTargets);

} // namespace vl
