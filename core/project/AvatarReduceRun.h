#pragma once
// `visemelab avatar reduce` as one use case for every front end (the command, batch jobs, the Python
// package): the avatar read (a file, or bytes named like one), its visemes scanned, the frequencies
// chosen as the command documents them, the reduction under the batch policy, the optional gltfpack
// pass, and the report. Front ends check their own flags and write the outputs.
#include "core/export/ReductionOutputs.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarScan.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vl {

struct AvatarReduceRequest {
    std::filesystem::path input;      // the avatar file, or the name its bytes are reported under
    std::optional<std::string> bytes; // the avatar's bytes (GLB or JSON glTF): input is not read
    std::string targets;              // glob over target names; empty: the Oculus visemes
    ReduceSettings settings; // avatarReduceSettings(m) with the front end's weights, rest, constraints
    AvatarWriteOptions write;
    std::filesystem::path freqFile; // a frequency table (with mapFile: phonemes); empty: the default
    std::filesystem::path mapFile;  // a phoneme -> viseme map; empty: the table's
    // The bundled en-us phoneme table with the Oculus map (bundledPhonemeFrequencies(assets, "oculus")):
    // the default frequencies when the avatar's visemes are Oculus visemes, the table beside a map.
    FrequencySource bundledTable;
    bool gltfpack = false; // re-compress the output with gltfpack (found by findGltfpack)
};

struct AvatarReduceRun {
    AvatarScan scan;
    AvatarReduction reduction; // .glb: the bytes to write
    std::string frequencies;   // which table and map reduced it, for messages
    ReduceTimings timings;     // writeMs: the gltfpack pass (writing is the front end's)
};

// Throws InputError naming the file and element for what the avatar, the tables or the reduction
// refuse (see reduceAvatar, scanAvatar, loadFrequencyFile).
AvatarReduceRun runAvatarReduce(const AvatarReduceRequest& request, const ProgressCallback& progress = {});

// The JSON report of `avatar reduce --report` (avatarReductionReport) naming `output`.
std::string avatarReduceReport(const AvatarReduceRun& run, const AvatarReduceRequest& request,
                               const std::string& output);

} // namespace vl
