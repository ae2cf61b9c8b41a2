#pragma once
// An avatar speaking, without a project (`visemelab say --avatar`): the avatar's visemes as the full
// face, its reduction as the reduced face (reduced in memory to m keys as `avatar reduce` does, or
// read from an avatar `avatar reduce` wrote), and the document the speech animation goes on. An
// avatar without a rest viseme speaks with one added (core/gltf/AvatarRest.h): pauses at all weights 0.
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/project/ProjectSpeech.h"
#include "core/reduce/ReduceRun.h"
#include "core/reduce/ReductionConstraints.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl {

struct AvatarSpeechOptions {
    std::string targets;                // glob over target names; empty = the Oculus visemes
    int reduceTo = 0;                   // > 0: reduce to this many keys in memory (uniform weights)
    std::filesystem::path reduced;      // else, when set: the avatar `avatar reduce` wrote from this one
    ConstraintNames constraints;        // with reduceTo or maxErrorMm: the designer's constraints
    double maxErrorMm = 0;              // > 0: reduce to the fewest keys within this bound (ReduceSettings)
    std::string closure = kClosureAuto; // ReduceSettings::closure: the lips-closed viseme keeps a key
    // The bundled en-us phoneme table with the Oculus map: the frequencies `avatar reduce` uses by
    // default (core/gltf/AvatarReduce.h defaultAvatarFrequencies).
    FrequencySource phonemeTable;
    std::optional<PhonemeVisemeMap> map; // instead of the table's, matched by meaning (VisemeMapNames)
};

// How a mesh's morph targets follow a face track: per target the key whose weight drives it,
// kDefaultWeight (not a viseme: keeps the mesh's default weight) or kZeroWeight (a viseme target
// another target of its key carries on this mesh).
struct MeshDrive {
    static constexpr int kDefaultWeight = -1;
    static constexpr int kZeroWeight = -2;
    int mesh = 0;
    std::vector<int> keyOfTarget;
};

struct AvatarSpeech {
    SpeechFaces faces;        // full: every viseme; reduced: the reduction (the full face without one)
    bool reducedFace = false; // -m or a reduced avatar given
    std::string frequencies;  // which frequencies and map, for messages
    // The document the animation is added to: the reduced avatar when there is one (its keys are
    // driven by the reduced face), else the avatar (driven by the full face).
    std::shared_ptr<const GltfDocument> animated;
    std::vector<MeshDrive> drives; // every mesh of `animated` carrying visemes
};

// Throws InputError naming the file and element: fewer than 2 visemes, no phoneme -> viseme map
// (the avatar's names are not Oculus visemes and no map is given), a map naming visemes the avatar
// lacks, a reduced avatar that is not VisemeLab's reduction of this avatar (either name mode; read
// through core/gltf/OwnOutput.h).
AvatarSpeech avatarSpeech(const std::filesystem::path& avatar, const AvatarSpeechOptions& options);

} // namespace vl
