#pragma once
// Which morph targets of a reduced avatar carry which key: read back from what the writer recorded
// (mesh.extras.visemeKeys and targetNames, the key names from the root extras.visemelab; either
// version of the key table, core/gltf/KeyTable.h), so the designer is told what the file really
// holds, whichever name mode wrote it.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vl {

struct AvatarKeyTargets {
    int key = 0;
    std::string
        name; // the key's name as recorded (merged names: its target's), else its members joined with '+'
    // Per mesh carrying the key: the mesh's name and the names of the targets that hold the key.
    std::vector<std::pair<std::string, std::vector<std::string>>> meshes;
};

// The keys of a reduced avatar GLB in key order. Throws InputError naming `source` when the bytes
// are no GLB or its JSON is malformed; a mesh without visemeKeys extras carries no key.
std::vector<AvatarKeyTargets> avatarKeyTargets(std::string_view glb, std::string_view source);

// One line per key, meshes with the same targets joined, e.g.
// "key 2 (viseme_PP+viseme_FF): target 'viseme_PP+viseme_FF' on Wolf3D_Head, Wolf3D_Teeth".
std::vector<std::string> formatAvatarKeyTargets(const std::vector<AvatarKeyTargets>& keys);

} // namespace vl
