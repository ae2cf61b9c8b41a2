#include "core/project/AvatarReduceRun.h"

#include "core/gltf/Gltfpack.h"
#include "core/project/ReduceInputs.h"

namespace vl {

FrequencySource avatarReduceFrequencies(const AvatarReduceRequest& o, const AvatarScan& scan,
                                        const BundledFrequencies& bundled, std::string& chosen) {
    if (o.freqFile.empty() && o.mapFile.empty())
        return defaultAvatarFrequencies(scan, bundled.oculus, &chosen);
    FrequencySource source;
    if (!o.freqFile.empty()) {
        source = loadFrequencyFile(o.freqFile);
        chosen = o.freqFile.string();
    }
    if (!o.mapFile.empty()) {
        if (o.freqFile.empty()) {
            source = bundled.phonemeTable;
            chosen = "bundled en-us phoneme table";
        }
        source = withPhonemeMap(std::move(source), loadPhonemeMapFile(o.mapFile));
        chosen += " + map " + o.mapFile.string();
    }
    requirePhonemeMap(source, o.freqFile.string());
    return source;
}

ReduceSettings avatarReduceRequestSettings(const AvatarReduceRequest& o) {
    ReduceSettings settings = avatarReduceSettings(o.target);
    settings.weightMode = o.weightMode;
    if (o.weightMode == WeightMode::Painted) {
        settings.paintedWeights = o.paintedWeights;
        settings.paintedWeightsSource = o.paintedWeightsSource;
    }
    settings.rest = o.rest;
    settings.restViseme = o.restViseme;
    settings.constraints = o.constraints;
    settings.maxErrorMm = o.maxErrorMm;
    settings.closure = o.closure;
    return settings;
}

AvatarReduceResult runAvatarReduce(const GltfDocument& doc, const AvatarScan& scan,
                                   const FrequencySource& frequencies, const AvatarReduceRequest& o,
                                   const ProgressCallback& progress) {
    AvatarReduceResult r{{}, avatarReduceRequestSettings(o)};
    r.reduction =
        reduceAvatar(doc, scan, frequencies,
                     withPolicy(r.settings, ReducePolicy::batch(), scan.visemes.size()), o.write, progress);
    if (o.gltfpack) {
        recompressInPlace(r.reduction.glb, r.reduction.summary.notes, findGltfpack(), {o.targets});
    } else if (avatarStoredCompressed(scan)) {
        const std::filesystem::path gltfpack = findGltfpack();
        r.reduction.summary.notes.push_back(
            gltfpack.empty()
                ? std::string("--gltfpack would re-compress the output; gltfpack is not found: ") +
                      kGltfpackHint
                : "--gltfpack re-compresses the output (with " + gltfpack.string() + ")");
    }
    return r;
}

} // namespace vl
