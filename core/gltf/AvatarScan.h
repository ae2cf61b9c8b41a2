#pragma once
// Reading an avatar: every mesh and primitive of a glTF file, the morph targets that are visemes,
// and one viseme set over all of them.
//
// The visemes of all meshes that carry them (head, teeth, tongue, eyes) form ONE set: a viseme is
// joined across meshes by its name (the Oculus spelling when it is an Oculus viseme, e.g. "viseme_I"
// on the head and "ih" on the teeth are the same viseme, else the name without regard to case).
// The set's geometry is the concatenation of every primitive of those meshes in world space (node
// transforms, or rest-pose skinning for skinned meshes: core/gltf/SceneGraph); a mesh that lacks a
// viseme contributes zero displacement to it. Per-vertex weights and costs are measured on that
// geometry; the writer never bakes the transforms into its output.
#include "core/gltf/OwnOutput.h"
#include "core/mesh/VisemeSet.h"

#include <string>
#include <vector>

namespace vl {

class GltfDocument;

// Bounds that keep memory proportional to what a file really holds: distinct visemes, and the bytes
// of the world-space geometry ((visemes + 1) x vertices x 24 + triangles, summed over every primitive
// read, checked before it is allocated). 512 MiB keeps `avatar inspect` and `face build` of any file
// under 1 GiB of memory (docs/robustness.md); a 1 M-vertex head with 15 visemes takes 384 MiB.
inline constexpr std::size_t kMaxAvatarVisemes = 64;
inline constexpr std::size_t kMaxAvatarVisemeBytes = std::size_t{512} << 20;

// World-space coordinates beyond this are refused: their squared distances (and the float32 a key is
// written as) would overflow.
inline constexpr double kMaxWorldCoordinate = 1e30;

struct AvatarSelection {
    std::string pattern;     // glob over target names (core/gltf/TargetNames.h); empty: the Oculus visemes
    bool context = false;    // also read the meshes without visemes (AvatarScan::context), e.g. to show them
    std::string addedRest{}; // non-empty: add this rest viseme, no target's (core/gltf/AvatarRest.h)
};

struct AvatarTarget {
    std::string name;
    bool named = false;  // false: the file has no targetNames, the name is "target<k>"
    int viseme = -1;     // index into AvatarScan::visemes, or -1 when not selected
    std::string ignored; // why it is not a viseme (empty when selected)
};

struct AvatarPrimitive {
    int mode = 4;                     // glTF primitive mode
    std::size_t vertices = 0;         // POSITION count
    std::size_t triangles = 0;        // after strips/fans are expanded
    std::size_t firstVertex = 0;      // in AvatarScan::set.neutral (meshes carrying visemes only)
    std::vector<std::string> storage; // "Draco", "meshopt", "quantised", "sparse targets"
};

struct AvatarMesh {
    int index = 0;
    std::string name;
    int node = -1; // the node that places it for measuring (-1: identity)
    int uses = 0;  // how many nodes instance it
    int skin = -1; // the skin of that node, -1 when not skinned
    std::vector<AvatarTarget> targets;
    std::vector<AvatarPrimitive> primitives;
    bool carriesVisemes = false;
    std::string note; // why it carries none, or how it was measured
};

struct AvatarScan {
    std::string source;
    std::string selection; // how visemes were selected, for reports
    std::vector<AvatarMesh> meshes;
    std::vector<std::string> visemes;    // names as first met in the file; set order
    std::vector<std::string> visemeKeys; // the joining key of each (core/gltf/TargetNames)
    bool oculusNames = false;            // every viseme is an Oculus viseme
    VisemeSet set;                       // world-space geometry of the meshes carrying visemes
    MeshData context; // with AvatarSelection::context: the other meshes, world space (rest pose)
    std::vector<std::string> extensionsUsed, extensionsRequired;
    std::size_t fileVertices = 0; // POSITION counts of every primitive of every mesh
    // A file VisemeLab reduced. With merged names its visemes are the key targets (their names or
    // members matching the pattern, when one is given); with original names every viseme kept its
    // target, selected as usual.
    OwnOutput own;
    std::string addedRest; // the rest viseme added after the file's (core/gltf/AvatarRest.h), if any
};

// The key that joins a target name across meshes: its Oculus spelling, else the lower-case name.
std::string visemeJoinKey(std::string_view targetName);

// Reads the avatar; throws InputError naming the file and element for anything it cannot read.
// The viseme set may hold fewer than 2 visemes (a report still describes the file).
AvatarScan scanAvatar(const GltfDocument& doc, const AvatarSelection& selection);

// True when the avatar was stored compressed or quantised (Draco, meshopt, quantised accessors): its
// reduced keys are written as plain floats, so re-compression (core/gltf/Gltfpack.h) is worth offering.
bool avatarStoredCompressed(const AvatarScan& scan);

} // namespace vl
