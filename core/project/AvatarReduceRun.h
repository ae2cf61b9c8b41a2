#pragma once
// `avatar reduce` from its options to its output bytes: the frequencies it chooses, the settings,
// the reduction, the optional gltfpack re-compression and the report. The CLI command and
// `visemelab batch` jobs both run it, so a batch job writes the single command's bytes.
#include "core/export/ReductionOutputs.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/AvatarWriter.h"
#include "core/gltf/GltfDocument.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReduceRun.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

struct AvatarReduceRequest {
    int target = 0;        // m; or
    double maxErrorMm = 0; // > 0: the fewest keys within this bound
    std::string targets;   // glob over target names; empty: the Oculus visemes
    std::filesystem::path freqFile, mapFile;
    WeightMode weightMode = WeightMode::Uniform;
    std::vector<double> paintedWeights; // with WeightMode::Painted
    std::string paintedWeightsSource;
    RestChoice rest = RestChoice::Free;
    std::string restViseme;
    ConstraintNames constraints;
    std::string closure = kClosureAuto; // "" for none
    AvatarWriteOptions write;
    bool gltfpack = false;
};

// The bundled frequencies `avatar reduce` falls back on, loaded by the caller (core/phonetics
// PhonemeMaps.h, which this layer cannot reach): the en-us phoneme table alone (with --map) and with
// the Oculus map (without --freq-file and --map).
struct BundledFrequencies {
    FrequencySource phonemeTable;
    FrequencySource oculus;
};

// The frequencies: a given table (with mapFile: phonemes), or the bundled phoneme table with the
// given map, else defaultAvatarFrequencies. `chosen` says which.
FrequencySource avatarReduceFrequencies(const AvatarReduceRequest& request, const AvatarScan& scan,
                                        const BundledFrequencies& bundled, std::string& chosen);

// The settings the reduction runs with (before the time-limit policy).
ReduceSettings avatarReduceRequestSettings(const AvatarReduceRequest& request);

struct AvatarReduceResult {
    AvatarReduction reduction; // glb: the bytes to write
    ReduceSettings settings;
};

// Reduces and (with request.gltfpack) re-compresses; notes what gltfpack would do otherwise.
AvatarReduceResult runAvatarReduce(const GltfDocument& doc, const AvatarScan& scan,
                                   const FrequencySource& frequencies, const AvatarReduceRequest& request,
                                   const ProgressCallback& progress = {});

} // namespace vl
