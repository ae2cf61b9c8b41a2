#include "core/project/AvatarReduceRun.h"

#include "core/gltf/GltfDocument.h"
#include "core/gltf/Gltfpack.h"
#include "core/project/ReduceInputs.h"

#include <chrono>

namespace vl {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A given table (with a map: phonemes), or the bundled en-us phoneme table with the given map;
// without either, the core's default (the bundled table and Oculus map when the avatar's visemes are
// Oculus visemes, else equal). Says what it chose.
FrequencySource avatarFrequencies(const AvatarReduceRequest& r, const AvatarScan& scan, std::string& chosen) {
    if (r.freqFile.empty() && r.mapFile.empty())
        return defaultAvatarFrequencies(scan, r.bundledTable, &chosen);
    FrequencySource source;
    if (!r.freqFile.empty()) {
        source = loadFrequencyFile(r.freqFile);
        chosen = r.freqFile.string();
    }
    if (!r.mapFile.empty()) {
        if (r.freqFile.empty()) {
            source = r.bundledTable; // its phonemes; the map replaces the Oculus one
            chosen = "bundled en-us phoneme table";
        }
        source = withPhonemeMap(std::move(source), loadPhonemeMapFile(r.mapFile));
        chosen += " + map " + r.mapFile.string();
    }
    requirePhonemeMap(source, r.freqFile.string());
    return source;
}

} // namespace

AvatarReduceRun runAvatarReduce(const AvatarReduceRequest& request, const ProgressCallback& progress) {
    AvatarReduceRun run;
    const auto t0 = std::chrono::steady_clock::now();
    const GltfDocument doc =
        request.bytes ? parseGltfDocument(*request.bytes, request.input.string(), request.input.parent_path())
                      : loadGltfDocument(request.input);
    run.scan = scanAvatar(doc, {request.targets});
    const FrequencySource frequencies = avatarFrequencies(request, run.scan, run.frequencies);
    run.timings.loadMs = millisecondsSince(t0);

    const auto t1 = std::chrono::steady_clock::now();
    run.reduction = reduceAvatar(doc, run.scan, frequencies,
                                 withPolicy(request.settings, ReducePolicy::batch(), run.scan.visemes.size()),
                                 request.write, progress);
    run.timings.reduceMs = millisecondsSince(t1);

    const auto t2 = std::chrono::steady_clock::now();
    AvatarWriteSummary& summary = run.reduction.summary;
    if (request.gltfpack) {
        recompressInPlace(run.reduction.glb, summary.notes, findGltfpack(), {request.targets});
    } else if (avatarStoredCompressed(run.scan)) {
        const std::filesystem::path gltfpack = findGltfpack();
        summary.notes.push_back(gltfpack.empty()
                                    ? std::string("--gltfpack would re-compress the output; gltfpack is not "
                                                  "found: ") +
                                          kGltfpackHint
                                    : "--gltfpack re-compresses the output (with " + gltfpack.string() + ")");
    }
    run.timings.writeMs = millisecondsSince(t2);
    return run;
}

std::string avatarReduceReport(const AvatarReduceRun& run, const AvatarReduceRequest& request,
                               const std::string& output) {
    return avatarReductionReport(run.reduction, run.scan, request.settings, request.write, run.timings,
                                 request.input.string(), output);
}

} // namespace vl
