#pragma once
// Writing the same avatar back with its viseme targets reduced.
//
// The output is the input document, edited: every node, skin, material, texture, image, animation,
// extension and extra that is not a selected viseme target is kept, and the bytes of every kept
// accessor, image and compressed stream are copied unchanged (EXT_meshopt_compression views and
// Draco streams stay compressed; a compressed view shared with replaced targets, as gltfpack writes
// them, is re-encoded with only the rest, losslessly). The new targets are stored as their members are in the
// input (core/gltf/TargetStorage.h: quantised stays quantised on the same grid, meshopt-compressed stays
// compressed, each in its smallest layout), so merging visemes shrinks the data. On each primitive of a
// mesh carrying visemes, the viseme targets are replaced by the m reduced keys, the same grouping
// on every mesh: key g on a mesh is the frequency-weighted mean of its members' displacements on that
// mesh (a member the mesh lacks counts as zero, as in the reduction's concatenated geometry), for
// POSITION and, unless disabled, NORMAL and TANGENT. A key of one member reuses that member's
// accessors as they are (unless it was sculpted on that primitive: AvatarWriteOptions::sculpted).
//
// Names clients drive by:
// - AvatarNames::Original (default): every original viseme target stays, under its own name and
//   index; the members of a group point to one shared accessor. Weights, animations and VRM binds
//   are untouched.
// - AvatarNames::Merged: one target per key present on the mesh, at the place of its first member,
//   named by core/gltf/MergedNames.h (at most 63 bytes, e.g. "viseme_PP+FF+TH"; a key of one member
//   keeps its name). Target indices after it shift: mesh.weights, node.weights, morph-weight
//   animations (a key's weight is the sum of its members'), VRM 0.x blendShapeMaster binds and
//   VRM 1.0 morphTargetBinds are remapped.
// In both modes a resting viseme (in no key) keeps a zero-displacement target under its own name.
// mesh.extras.targetNames follow the targets. The key table is written once, at the root:
// extras.visemelab version 2 (core/gltf/KeyTable.h: keys with members and frequencies, resting
// visemes, phoneme -> key, phoneme frequencies); each mesh's extras gain only what is its own:
// "visemeKeys" (per key, its targets on the mesh) and, when some viseme name would not resolve by
// targetNames and the table, "targetAliases" (that name -> the target carrying it).
// core/gltf/OwnOutput.h reads all of it back.
//
// Accessors and buffer views that only the replaced targets (or rewritten animations) used are
// removed and the rest renumbered wherever glTF 2.0, KHR_draco_mesh_compression,
// EXT_meshopt_compression and EXT_mesh_gpu_instancing refer to them; every buffer with data
// becomes the one GLB BIN chunk; external images are embedded.
#include "core/common/EnumNames.h"
#include "core/reduce/ReducedModel.h"

#include <string>
#include <vector>

namespace vl {

class GltfDocument;
struct AvatarScan;

enum class AvatarNames { Original, Merged };
template <> struct EnumNames<AvatarNames> {
    static constexpr const char* what = "names";
    static constexpr EnumName<AvatarNames> names[] = {{AvatarNames::Original, "original"},
                                                      {AvatarNames::Merged, "merged"}};
};

struct AvatarWriteOptions {
    AvatarNames names = AvatarNames::Original;
    bool targetNormals = true; // NORMAL/TANGENT displacements of the reduced keys
    int maxTargets = 0;        // > 0: refuse when a primitive would have more morph targets
    // Sculpted visemes (the editor): per viseme of the scan, its world-space positions over the scan's
    // set, or empty when it is as in the file. On each primitive where a sculpted viseme differs
    // from the file, its POSITION displacement is taken from these positions, mapped back into the
    // mesh's own space (AvatarPlacement.h); NORMAL/TANGENT stay the file's. Primitives where it does
    // not differ keep their bytes.
    const std::vector<std::vector<Vec3>>* sculpted = nullptr;
};

struct AvatarMeshChange {
    int mesh = 0;
    std::string name;
    std::size_t targetsBefore = 0, targetsAfter = 0;
    std::size_t visemeTargets = 0; // selected viseme targets before
    std::size_t keys = 0;          // reduced keys present on the mesh
};

struct AvatarWriteSummary {
    std::vector<AvatarMeshChange> meshes;
    std::size_t accessorsBefore = 0, accessorsAfter = 0;
    std::size_t binaryBytesBefore = 0, binaryBytesAfter = 0;
    std::vector<std::string> notes; // e.g. what stays compressed, extensions kept verbatim
};

// The GLB of the reduced avatar. `model` is buildReducedModel's result over `scan.set` (keys,
// members, frequencies, phoneme map); `groupOf[i]` is viseme i's key and `frequencies[i]` its
// normalised frequency. Throws InputError for --max-targets refusals and unreadable data.
std::string writeReducedAvatar(const GltfDocument& doc, const AvatarScan& scan, const ReducedModel& model,
                               const std::vector<int>& groupOf, const std::vector<double>& frequencies,
                               const AvatarWriteOptions& options, AvatarWriteSummary* summary = nullptr);

} // namespace vl
