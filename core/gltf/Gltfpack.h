#pragma once
// Re-compressing a reduced avatar with gltfpack, meshoptimizer's command-line tool (a native build,
// or the npm package `gltfpack`): `gltfpack -c` stores every accessor, the new keys included, with
// EXT_meshopt_compression and KHR_mesh_quantization, as real exporters ship avatars.
//
// gltfpack rebuilds the document: meshes are re-ordered and placed on unnamed child nodes of the
// named nodes it keeps (-kn), mesh names and every extras object except targetNames are dropped,
// and so are extensions it does not know. What VisemeLab wrote and clients need is put back: mesh
// names and extras (targetNames, visemeKeys, targetAliases) by matching each mesh through the
// named node that places it, and the document's extras (the key table). The result is read back
// and must yield the same visemes on the same meshes, else nothing is written. A VRM is refused:
// its extension addresses nodes, meshes and materials by the indices gltfpack renumbers.
#include "core/gltf/AvatarScan.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

// The gltfpack to run: $VISEMELAB_GLTFPACK when set, else `gltfpack` on PATH; empty when none.
std::filesystem::path findGltfpack();

// How to get gltfpack, for messages.
inline constexpr const char* kGltfpackHint =
    "install it with `npm install -g gltfpack` (or a native build from meshoptimizer), or set "
    "VISEMELAB_GLTFPACK to its path";

struct Recompressed {
    std::string glb;
    std::vector<std::string> notes; // what gltfpack changed, for the user
};

// Runs `gltfpack -c -kn -km -ke -af 0` on `glb` (written to a private temporary folder, removed
// after) and restores what it drops. `selection` is the viseme selection the avatar was reduced
// with: the re-compressed avatar must yield the same visemes on the same meshes. Throws InputError
// naming gltfpack: not runnable, failed (its exit status and last output lines), a VRM, or a mesh
// with visemes that gltfpack's output no longer identifies.
Recompressed recompressWithGltfpack(const std::string& glb, const std::filesystem::path& gltfpack,
                                    const AvatarSelection& selection);

// `glb` replaced by its re-compression, gltfpack's notes appended to `notes`: what `avatar reduce
// --gltfpack` and the editor's avatar export do before they write the avatar.
void recompressInPlace(std::string& glb, std::vector<std::string>& notes,
                       const std::filesystem::path& gltfpack, const AvatarSelection& selection);

} // namespace vl
