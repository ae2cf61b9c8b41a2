#pragma once
// The avatar a document's viseme set was read from (File > Import avatar...): the glTF file as read
// (the template the reduced avatar is written from, core/gltf/AvatarWriter.h), the pattern that
// selects its viseme targets, and what the scan found (core/gltf/AvatarScan.h). Immutable and
// shared between the document states of an undo history; compared by identity.
#include "core/mesh/Mesh.h"

#include <filesystem>
#include <memory>
#include <string>

namespace vl {

class GltfDocument;
struct AvatarScan;

struct DocumentAvatar {
    std::filesystem::path file;               // absolute; a project stores it relative to itself
    std::string pattern;                      // glob over target names; empty = the Oculus visemes
    std::shared_ptr<const GltfDocument> gltf; // null = the document has no avatar
    std::shared_ptr<const AvatarScan> scan;   // its set is the document's viseme set

    bool isSet() const { return gltf != nullptr; }
    bool operator==(const DocumentAvatar&) const = default;
};

} // namespace vl
