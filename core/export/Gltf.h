#pragma once
// glTF 2.0 export and import of morph-target faces (tinygltf).
//
// Export (.glb): one mesh, one triangle primitive with the neutral face as POSITION, NORMAL,
// TEXCOORD_0 (when the mesh has (u,v)) and indices, and one morph target per key mesh holding
// POSITION and NORMAL displacements from the neutral. mesh.extras carries the target names
// ("targetNames", the convention Blender and three.js read), "phonemeToTarget" (phoneme -> target
// index), "targetFrequencies", "targetMembers" (original visemes merged into each target) and,
// when known, "phonemeFrequencies". glTF puts the texture origin at the top-left, VisemeLab (like
// OBJ and VRML) at the bottom-left: v is written as 1 - v and flipped back on import.
//
// Import (.glb or .gltf): the first mesh that has morph targets (else the first mesh); all its
// triangle primitives are concatenated. Targets become key meshes (neutral + displacement), named
// from extras.targetNames or "target<k>"; the VisemeLab extras are read back when present. Node
// transforms are ignored (shapes stay in mesh space). Read with core/gltf's hardened reader (limits,
// confined URIs; sparse, quantised, EXT_meshopt_compression and Draco data). Whole avatars (every
// mesh, the visemes among other targets, written back as the same avatar): core/gltf/Avatar*.
#include "core/export/GltfAnimation.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace vl {

// The .glb bytes, with `animation` (when given) animating the morph target weights.
std::string formatGlb(const ReducedModel& model, const GltfMorphAnimation* animation = nullptr);
// formatGlb written atomically.
void writeGlb(const std::filesystem::path& path, const ReducedModel& model,
              const GltfMorphAnimation* animation = nullptr);

// Throws InputError naming `source` (and the glTF element) for anything it cannot read.
ReducedModel parseGltf(std::string_view bytes, std::string_view source, bool binary,
                       const std::filesystem::path& baseDir = {});
// By extension: .glb binary, .gltf JSON (external buffers relative to the file).
ReducedModel readGltf(const std::filesystem::path& path);

} // namespace vl
