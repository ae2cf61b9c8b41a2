#pragma once
// An avatar's visemes reduced end to end: the viseme set of core/gltf/AvatarScan reduced with the
// ordinary reduction (core/reduce/ReduceRun: exact optimum over the concatenated world-space
// geometry), its keys built by buildReducedModel, and the same avatar written back
// (core/gltf/AvatarWriter). Frequency tables and phoneme maps name visemes as the bundled files do
// ("aa", "ih"); they are matched to the avatar's target names by meaning (core/gltf/TargetNames).
#include "core/gltf/AvatarScan.h"
#include "core/gltf/AvatarWriter.h"
#include "core/reduce/ReduceRun.h"

#include <string>
#include <vector>

namespace vl {

class GltfDocument;

// `source` with every viseme name that stands for one of the avatar's visemes (same join key, or a
// Rhubarb / MPEG-4 map read by meaning: core/gltf/VisemeMapNames.h) replaced by the avatar's name for
// it; other names stay (and are reported as unknown later).
FrequencySource matchVisemeNames(FrequencySource source, const AvatarScan& scan);

// True when every viseme the map names is one of the avatar's visemes.
bool mapFitsAvatar(const PhonemeVisemeMap& map, const AvatarScan& scan);

// Equal frequencies for every viseme of the avatar.
FrequencySource uniformFrequencies(const AvatarScan& scan);

// What an avatar reduces with when the user gave no table: `oculusTable` (a phoneme table with an
// Oculus phoneme -> viseme map, e.g. the bundled en-us table and map) matched to the avatar's names
// when its visemes are Oculus visemes and the map names only visemes the avatar has; else equal
// frequencies. `chosen` (optional) says which, for messages.
FrequencySource defaultAvatarFrequencies(const AvatarScan& scan, const FrequencySource& oculusTable,
                                         std::string* chosen = nullptr);

// What `avatar reduce -m target` and `say --avatar -m target` reduce with unless told otherwise: the
// rest free (the rest pose of a morph-target avatar, all weights 0, costs nothing), the lips-closed
// viseme kept as a key of its own (ReduceSettings::closure), lengths in metres (errors in mm).
ReduceSettings avatarReduceSettings(int target);

struct AvatarReduction {
    ReduceOutcome outcome; // its model: keys over the concatenated geometry, phoneme -> key
    std::string glb;
    AvatarWriteSummary summary;
};

// Throws InputError when the avatar has fewer than 2 visemes, frequencies do not fit, or writing
// is refused (--max-targets).
AvatarReduction reduceAvatar(const GltfDocument& doc, const AvatarScan& scan,
                             const FrequencySource& frequencies, const ReduceSettings& settings,
                             const AvatarWriteOptions& write, const ProgressCallback& progress = {});

} // namespace vl
