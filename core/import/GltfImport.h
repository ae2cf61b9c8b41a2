#pragma once
// glTF 2.0 import of morph-target faces (.glb or .gltf) as a reduced model.
//
// The first mesh that has morph targets (else the first mesh); all its triangle primitives are
// concatenated. Targets become key meshes (neutral + displacement), named from extras.targetNames
// or "target<k>"; the VisemeLab extras core/export/GltfExport.h writes (target names, members and
// frequencies, the phoneme map and phoneme frequencies) are read back when present. v is flipped
// back to VisemeLab's bottom-left texture origin. Node transforms are ignored (shapes stay in mesh
// space). Read with core/gltf's hardened reader (limits, confined URIs; sparse, quantised,
// EXT_meshopt_compression and Draco data). Whole avatars (every mesh, the visemes among other
// targets, written back as the same avatar): core/gltf/Avatar*.
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string_view>

namespace vl {

// Throws InputError naming `source` (and the glTF element) for anything it cannot read.
ReducedModel parseGltf(std::string_view bytes, std::string_view source, bool binary,
                       const std::filesystem::path& baseDir = {});
// By extension: .glb binary, .gltf JSON (external buffers relative to the file).
ReducedModel readGltf(const std::filesystem::path& path);

} // namespace vl
