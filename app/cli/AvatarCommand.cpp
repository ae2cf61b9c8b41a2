// `visemelab avatar inspect|reduce`: real avatars (glTF / GLB / VRM) in, the same avatar out.
#include "app/cli/Command.h"
#include "app/cli/ConstraintOptions.h"
#include "app/cli/Progress.h"
#include "app/cli/WeightsOption.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/export/ReductionOutputs.h"
#include "core/gltf/AvatarKeyTargets.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/Gltfpack.h"
#include "core/gltf/TargetNames.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/AvatarReduceRun.h"
#include "core/project/ReduceInputs.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace vl::cli {

namespace {

struct InspectOptions {
    std::string input;
    std::string targets;
    std::string json;
};

// Outputs never replace an input of the run.
void refuseOverwrite(const std::string& output, const std::string& input, const char* option) {
    std::error_code ec, ec2;
    if (std::filesystem::equivalent(output, input, ec) ||
        std::filesystem::weakly_canonical(output, ec) == std::filesystem::weakly_canonical(input, ec2))
        throwUsage(std::string(option) + " " + output + " is the input file; choose another path");
}

struct AvatarReduceOptions {
    std::string input;
    std::string out;
    int target = 0;
    std::string targets;
    std::string freqFile;
    std::string mapFile;
    std::string weights = "uniform";
    std::string report;
    std::string names = "original";
    bool noTargetNormals = false;
    int maxTargets = 0;
    bool gltfpack = false;
    std::string rest = "free"; // free or key (ReduceRun.h RestChoice)
    std::string restViseme;
    ConstraintOptions constraints;
};

double avatarMillisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The bundled en-us phoneme table, alone and with the Oculus map (core/project/AvatarReduceRun.h).
BundledFrequencies bundledAvatarFrequencies() {
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    return {loadFrequencyFile(defaultPhonemeTablePath(assets)), bundledPhonemeFrequencies(assets, "oculus")};
}

int runAvatarReduce(const AvatarReduceOptions& o) {
    refuseOverwrite(o.out, o.input, "--out");
    if (!o.report.empty()) {
        refuseOverwrite(o.report, o.input, "--report");
        refuseOverwrite(o.report, o.out, "--report");
    }
    if (std::filesystem::path(o.out).extension() == ".gltf")
        throwUsage("--out " + o.out +
                   ": the reduced avatar is written as binary glTF; name it .glb (or .vrm)");
    if (o.names != "original" && o.names != "merged") throwUsage("--names must be original or merged");
    if (o.maxTargets < 0) throwUsage("--max-targets must be >= 1");
    if (!o.targets.empty()) checkGlobPattern(o.targets, "--targets");
    if (o.rest != "free" && o.rest != "key") throwUsage("--rest must be free or key, got '" + o.rest + "'");
    AvatarReduceRequest request;
    request.target = o.target;
    request.maxErrorMm = o.constraints.maxErrorMm;
    request.targets = o.targets;
    request.freqFile = o.freqFile;
    request.mapFile = o.mapFile;
    ReduceSettings weights;
    applyWeightsOption(o.weights, weights);
    request.weightMode = weights.weightMode;
    request.paintedWeights = std::move(weights.paintedWeights);
    request.paintedWeightsSource = weights.paintedWeightsSource;
    request.rest = o.rest == "key" ? RestChoice::Key : RestChoice::Free;
    request.restViseme = o.restViseme;
    request.constraints = o.constraints.names();
    request.closure = closureSetting(o.constraints);
    if ((o.target > 0) == (o.constraints.maxErrorMm > 0))
        throwUsage("give the number of keys -m M, or --max-error-mm X (which chooses it)");
    AvatarWriteOptions& write = request.write;
    write.names = o.names == "merged" ? AvatarNames::Merged : AvatarNames::Original;
    write.targetNormals = !o.noTargetNormals;
    write.maxTargets = o.maxTargets;
    request.gltfpack = o.gltfpack;

    const auto t0 = std::chrono::steady_clock::now();
    const GltfDocument doc = loadGltfDocument(o.input);
    const AvatarScan scan = scanAvatar(doc, {o.targets});
    std::string chosen;
    const FrequencySource frequencies =
        avatarReduceFrequencies(request, scan, bundledAvatarFrequencies(), chosen);
    ReduceTimings timings;
    timings.loadMs = avatarMillisecondsSince(t0);

    const auto t1 = std::chrono::steady_clock::now();
    ProgressLine progress("reducing");
    AvatarReduceResult run = runAvatarReduce(doc, scan, frequencies, request, progress.callback());
    progress.finish();
    AvatarReduction& r = run.reduction;
    const ReduceSettings& settings = run.settings;
    timings.reduceMs = avatarMillisecondsSince(t1);
    const auto t2 = std::chrono::steady_clock::now();
    writeFileAtomically(o.out, r.glb);
    timings.writeMs = avatarMillisecondsSince(t2);
    if (!o.report.empty())
        writeFileAtomically(o.report,
                            avatarReductionReport(r, scan, settings, write, timings, o.input, o.out));

    const Grouping& best = r.outcome.result.best();
    std::printf("Reduced %zu visemes to %zu (weights: %s; frequencies: %s), %s %.6g\n", scan.visemes.size(),
                r.outcome.model.keys.size(), toString(settings.weightMode), chosen.c_str(),
                best.optimal ? "optimal cost" : "best cost found (not proved optimal)", best.cost);
    for (std::size_t g = 0; g < r.outcome.model.keys.size(); ++g)
        std::printf("  %2zu: %s\n", g, r.outcome.model.keys[g].name.c_str());
    std::printf("%s\n", restSummary(r.outcome).c_str());
    if (r.outcome.maxError) std::printf("%s\n", maxErrorSummary(*r.outcome.maxError).c_str());
    std::printf("%s", visemeErrorTable(r.outcome).c_str());
    for (const VisemeMotion& motion : visemeMotions(scan.set, r.outcome))
        std::printf("  %s\n", formatVisemeMotion(motion).c_str());
    for (const AvatarMeshChange& m : r.summary.meshes)
        std::printf("mesh %d \"%s\": %zu morph targets -> %zu (%zu viseme targets, %zu keys, names %s)\n",
                    m.mesh, m.name.c_str(), m.targetsBefore, m.targetsAfter, m.visemeTargets, m.keys,
                    toString(write.names));
    // Which target now carries which key, as the written file records it (mesh extras visemeKeys).
    for (const std::string& line : formatAvatarKeyTargets(avatarKeyTargets(r.glb, o.out)))
        std::printf("  %s\n", line.c_str());
    for (const std::string& note : r.summary.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
    std::fprintf(stderr, "Wrote %s (%zu bytes; %zu bytes of binary data before%s, was %zu)%s%s\n",
                 o.out.c_str(), r.glb.size(), r.summary.binaryBytesAfter, o.gltfpack ? " re-compression" : "",
                 r.summary.binaryBytesBefore, o.report.empty() ? "" : "; report ", o.report.c_str());
    return kExitOk;
}

int runInspect(const InspectOptions& o) {
    if (!o.json.empty()) refuseOverwrite(o.json, o.input, "--json");
    if (!o.targets.empty()) checkGlobPattern(o.targets, "--targets");
    const AvatarScan scan = scanAvatar(loadGltfDocument(o.input), {o.targets});
    std::fputs(formatAvatarReport(scan).c_str(), stdout);
    if (!o.json.empty()) writeFileAtomically(o.json, avatarReportJson(scan).dump(2) + "\n");
    return kExitOk;
}

} // namespace

void addAvatarCommand(CLI::App& app, CommandRunner& run) {
    auto* avatar =
        app.add_subcommand("avatar", "Avatars (glTF, GLB, VRM): inspect their visemes, reduce them");
    avatar->require_subcommand(1, 1);

    auto inspect = std::make_shared<InspectOptions>();
    auto* cmd =
        avatar->add_subcommand("inspect", "Report meshes, primitives, vertex counts and which morph targets "
                                          "are visemes (and why the others are not)");
    cmd->add_option("input", inspect->input, "Avatar file (.glb, .gltf, .vrm)")->required();
    cmd->add_option("--targets", inspect->targets,
                    "Glob selecting the viseme targets by name (*, ?, [AIUEO]); default: the Oculus visemes, "
                    "with or without the viseme_ prefix");
    cmd->add_option("--json", inspect->json, "Also write the report as JSON to this file");
    cmd->callback([&run, inspect] { run = [inspect] { return runInspect(*inspect); }; });

    auto reduce = std::make_shared<AvatarReduceOptions>();
    auto* r = avatar->add_subcommand("reduce",
                                     "Reduce an avatar's visemes to m keys and write the same avatar back");
    r->add_option("input", reduce->input, "Avatar file (.glb, .gltf, .vrm)")->required();
    r->add_option("--target,-m", reduce->target, "Number of keys m (1..n), or --max-error-mm")
        ->check(kPositive);
    addConstraintOptions(*r, reduce->constraints, kClosureAuto);
    r->add_option("--out", reduce->out, "The reduced avatar (.glb or .vrm; never the input)")->required();
    r->add_option("--rest", reduce->rest,
                  "The rest pose: free (default: the neutral is an extra key that costs nothing; a viseme "
                  "joins a key or rests, moving nothing) or key (the rest is a key like any other)")
        ->capture_default_str();
    r->add_option("--rest-viseme", reduce->restViseme,
                  "The avatar's rest viseme (default: viseme_sil or sil when present); it always rests");
    r->add_option("--targets", reduce->targets,
                  "Glob selecting the viseme targets by name (*, ?, [AIUEO]); default: the Oculus visemes");
    r->add_option(
        "--freq-file", reduce->freqFile,
        "Frequencies: viseme table, or phoneme table with --map (default: the bundled en-us phoneme "
        "table and Oculus map for Oculus visemes, else equal)");
    r->add_option("--map", reduce->mapFile,
                  "Phoneme -> viseme map (CSV or JSON); the bundled en-us table by default");
    r->add_option("--weights", reduce->weights,
                  "Vertex weights over all the avatar's viseme meshes: uniform, area, or a file")
        ->capture_default_str();
    r->add_option("--report", reduce->report, "JSON report (the keys of reduce, plus the meshes touched)");
    r->add_option(
         "--names", reduce->names,
         "original: every viseme target stays, members share one accessor; merged: one target per key")
        ->capture_default_str();
    r->add_flag("--no-target-normals", reduce->noTargetNormals,
                "Write the keys without NORMAL/TANGENT displacements");
    r->add_flag(
        "--gltfpack", reduce->gltfpack,
        "Re-compress the output with gltfpack (EXT_meshopt_compression; $VISEMELAB_GLTFPACK or on PATH)");
    r->add_option("--max-targets", reduce->maxTargets,
                  "Refuse when a primitive would have more morph targets (engines that cap them)");
    r->callback([&run, reduce] { run = [reduce] { return runAvatarReduce(*reduce); }; });
}

} // namespace vl::cli
