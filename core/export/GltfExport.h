#pragma once
// glTF 2.0 export of morph-target faces (tinygltf); the reader is core/import/GltfImport.h.
//
// Export (.glb): one mesh, one triangle primitive with the neutral face as POSITION, NORMAL,
// TEXCOORD_0 (when the mesh has (u,v)) and indices, and one morph target per key mesh holding
// POSITION and NORMAL displacements from the neutral. mesh.extras carries the target names
// ("targetNames", the convention Blender and three.js read), "phonemeToTarget" (phoneme -> target
// index), "targetFrequencies", "targetMembers" (original visemes merged into each target) and,
// when known, "phonemeFrequencies". glTF puts the texture origin at the top-left, VisemeLab (like
// OBJ and VRML) at the bottom-left: v is written as 1 - v (and flipped back on import).
#include "core/export/GltfAnimation.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>

namespace vl {

// The .glb bytes, with `animation` (when given) animating the morph target weights.
std::string formatGlb(const ReducedModel& model, const GltfMorphAnimation* animation = nullptr);
// formatGlb written atomically.
void writeGlb(const std::filesystem::path& path, const ReducedModel& model,
              const GltfMorphAnimation* animation = nullptr);

} // namespace vl
