#pragma once
// Recognising a file `visemelab avatar reduce` wrote (core/gltf/AvatarWriter.h), in either version
// of its key table (core/gltf/KeyTable.h): the root extras.visemelab (keys with their members, the
// resting visemes, the name mode) and each mesh's extras.visemeKeys (key -> its targets on the mesh)
// and extras.targetAliases (viseme name -> target; version 2 lists only the names that targetNames
// and the key table do not resolve, and the reader resolves the others as a player does). The reader trusts
// nothing: an element of the wrong type, an index out of range or a key listed twice is ignored with a note
// naming it; when the key table itself is unusable the file is not recognised (and the notes say why). It
// never throws for the extras' sake.
#include <map>
#include <string>
#include <vector>

namespace vl {

class GltfDocument;

struct OwnKey {
    std::string name;                 // the key's name as written (its target's name with merged names)
    std::vector<std::string> members; // the original visemes it merges
    double frequency = 0.0;
};

struct OwnMesh {
    int mesh = 0;
    std::vector<std::vector<int>> keyTargets; // per key: its targets on this mesh (first: the one to drive)
    std::map<std::string, int> aliases;       // every viseme name that resolves on the mesh -> target
};

struct OwnOutput {
    bool recognised = false;
    int version = 0;          // of extras.visemelab: 1 or 2 (core/gltf/KeyTable.h); 0 when not read
    bool mergedNames = false; // "merged": one target per key; else every viseme kept its own target
    std::vector<OwnKey> keys;
    std::vector<std::string> resting; // visemes in no key: the rest pose (zero-displacement targets)
    std::vector<OwnMesh> meshes;      // the meshes with a key table, in index order
    std::vector<std::string> notes;   // what was ignored, or why the file is not recognised

    // Members of every key and the resting visemes: the visemes of the avatar that was reduced.
    std::size_t visemeCount() const;
    // The key whose (first) target on mesh `mesh` is `target`, or -1.
    int keyOfTarget(int mesh, int target) const;
    bool isResting(const std::string& name) const;
};

OwnOutput recogniseOwnOutput(const GltfDocument& doc);
// The meshes' key tables read against keys already known (`own.keys`, `own.mergedNames`), e.g. those
// of a reduction just written, whatever the document's root extras hold; sets `recognised`.
void readOwnMeshes(const GltfDocument& doc, OwnOutput& own);

// "reduced by VisemeLab: 6 keys from 15 visemes (names merged)".
std::string describeOwnOutput(const OwnOutput& own);

} // namespace vl
