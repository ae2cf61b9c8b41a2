// `visemelab reduce`: load a viseme set, reduce it to m merged meshes, write meshes, mapping and report.
#include "app/cli/Command.h"
#include "app/cli/ConstraintOptions.h"
#include "app/cli/Progress.h"
#include "app/cli/WeightsOption.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputSet.h"
#include "core/common/TextParsing.h"
#include "core/export/ReductionOutputs.h"
#include "core/import/XfaceImport.h"
#include "core/inspect/DistanceUnits.h"
#include "core/io/VisemeSetFiles.h"
#include "core/project/ProjectRun.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/ReduceRun.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace vl::cli {

namespace {

constexpr int kTargetNotGiven = -1;

struct ReduceOptions {
    std::string project;
    std::string neutral;
    std::vector<std::string> visemes; // NAME=FILE
    std::string visemeDir;
    std::string fdp;                // an Xface face (.fdp)
    std::vector<std::string> freqs; // NAME=F
    std::string freqFile;
    std::string mapFile;
    std::string weights = "uniform";
    int target = kTargetNotGiven;
    std::string outDir = "reduced";
    std::string format = "auto"; // key mesh files: ReductionOutputs.h keyMeshFormatsFromString
    std::string report;
    ConstraintOptions constraints;
    std::string method = "auto";
    double timeLimit = kBatchReduceSeconds;
    std::vector<std::string> compareMaps; // phoneme -> viseme maps costed as groupings
    std::string rest;                     // auto, free or key (ReduceRun.h RestChoice); empty: not given
    std::string restViseme;
};

std::pair<std::string, std::string> splitAssignment(const std::string& text, const std::string& option) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throwInputError(option, "expected NAME=VALUE, got '" + text + "'");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

// The set as the run holds it: a VisemeSet (doubles), or for keys written as binary PLY only (large
// sets: --format auto above kBinaryKeyMeshVertices, or ply) a FloatVisemeSet, whose keys are merged
// one at a time as they are written (docs/performance.md, issue 33: 12 bytes a position, not 24,
// and no key held as doubles). `view` reads whichever is loaded.
struct LoadedSet {
    std::shared_ptr<const VisemeSet> doubles;
    FloatVisemeSet floats;
    SetShapes view;
    bool deferredKeys() const { return !doubles; }
};

void loadFlagSet(const ReduceOptions& o, XfaceFace& xface, LoadedSet& loaded) {
    if (!o.fdp.empty()) { // the "Rest" entity and the Viseme entities; <stem>.dic as phoneme map
        xface = loadXfaceFace(o.fdp);
        loaded.doubles = std::make_shared<const VisemeSet>(std::move(xface.set));
        loaded.view = shapesOf(*loaded.doubles);
        return;
    }
    std::filesystem::path neutral = o.neutral;
    std::vector<std::pair<std::string, std::filesystem::path>> files;
    if (!o.visemeDir.empty()) {
        if (neutral.empty()) neutral = findNeutralMesh(o.visemeDir);
        files = listVisemeFolder(o.visemeDir, neutral);
    } else {
        for (const auto& v : o.visemes) files.emplace_back(splitAssignment(v, "--viseme"));
    }
    if (files.size() < 2) { // the loader's error, before the neutral is read
        loaded.doubles = std::make_shared<const VisemeSet>(loadVisemeSet(neutral, files));
        return;
    }
    ReferenceMesh reference = readReferenceMesh(neutral);
    const KeyMeshFormats formats = *keyMeshFormatsFromString(o.format, reference.mesh.positions.size());
    if (!formats.obj && !formats.wrl) {
        loaded.floats = loadFloatVisemeSet(neutral, std::move(reference), files);
        loaded.view = shapesOf(loaded.floats);
    } else {
        loaded.doubles =
            std::make_shared<const VisemeSet>(loadVisemeSet(neutral, std::move(reference), files));
        loaded.view = shapesOf(*loaded.doubles);
    }
}

FrequencySource loadFrequencies(const ReduceOptions& o, const SetShapes& set, const XfaceFace& xface = {}) {
    FrequencySource source;
    if (!o.freqFile.empty()) {
        source = loadFrequencyFile(o.freqFile);
    } else if (!o.freqs.empty()) {
        for (const auto& f : o.freqs) {
            const auto [name, value] = splitAssignment(f, "--freq");
            source.visemeFrequencies.entries.emplace_back(name, parseFiniteDouble(value, "--freq " + name));
        }
    } else {
        std::fprintf(stderr,
                     "visemelab: no frequencies given (--freq-file / --freq): using equal frequencies\n");
        for (const auto& name : set.names) source.visemeFrequencies.entries.emplace_back(name, 1.0);
    }
    if (!o.mapFile.empty()) source = withPhonemeMap(std::move(source), loadPhonemeMapFile(o.mapFile));
    // An Xface face's .dic maps a phoneme table given without --map (a table that names only the
    // face's visemes stays a viseme table); the phonemes it shows with the neutral (pauses) are not
    // visemes and leave the table.
    if (o.mapFile.empty() && !xface.dictionary.entries.empty() && !o.freqFile.empty()) {
        const bool visemeTable =
            !source.isPhonemeBased() &&
            std::all_of(source.visemeFrequencies.entries.begin(), source.visemeFrequencies.entries.end(),
                        [&](const auto& entry) { return set.find(entry.first) >= 0; });
        if (!visemeTable) {
            PhonemeVisemeMap map = source.map.entries.empty() ? xface.dictionary : source.map;
            source = withPhonemeMap(std::move(source), std::move(map));
            std::erase_if(source.phonemes.entries, [&](const auto& entry) {
                return std::find(xface.restPhonemes.begin(), xface.restPhonemes.end(), entry.first) !=
                       xface.restPhonemes.end();
            });
        }
    }
    requirePhonemeMap(source, "--freq-file");
    return source;
}

ReduceSettings loadSettings(const ReduceOptions& o) {
    ReduceSettings settings;
    settings.target = o.target;
    applyWeightsOption(o.weights, settings);
    return settings;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

RestChoice restChoiceFlag(const std::string& text) {
    if (const auto choice = fromString<RestChoice>(text)) return *choice;
    throwUsage("--rest must be free or key (or auto), got '" + text + "'");
}

// Flag combinations are checked before any file is read, so they always give exit code 2.
void checkFlagCombinations(const ReduceOptions& o) {
    if (!o.visemeDir.empty() && !o.visemes.empty())
        throwUsage("use either --visemes DIR or --viseme NAME=FILE, not both");
    if (!o.freqFile.empty() && !o.freqs.empty())
        throwUsage("use either --freq NAME=F or --freq-file FILE, not both");
    if (o.project.empty() && o.target == kTargetNotGiven && !(o.constraints.maxErrorMm > 0))
        throwUsage("--target M is required (or --project FILE, or --max-error-mm X)");
    if (o.target != kTargetNotGiven && o.constraints.maxErrorMm > 0)
        throwUsage("--max-error-mm chooses the number of keys: drop --target");
    if (o.project.empty() && o.neutral.empty() && o.visemeDir.empty() && o.fdp.empty())
        throwUsage("a neutral mesh is required: --neutral FILE (or --visemes DIR, or --fdp FACE.fdp)");
    if (!o.project.empty() && (!o.neutral.empty() || !o.visemes.empty() || !o.visemeDir.empty()))
        throwUsage("--project already names the meshes; drop --neutral/--viseme/--visemes");
    if (!o.fdp.empty() &&
        (!o.project.empty() || !o.neutral.empty() || !o.visemes.empty() || !o.visemeDir.empty()))
        throwUsage("--fdp already names the meshes; drop --project/--neutral/--viseme/--visemes");
    if (!fromString<ReductionMethod>(o.method))
        throwUsage("--method must be " + enumNameList<ReductionMethod>() + ", got '" + o.method + "'");
    if (!(o.timeLimit >= 0)) throwUsage("--time-limit must be >= 0 seconds (0: no limit)");
    if (!o.rest.empty()) restChoiceFlag(o.rest);
    if (!keyMeshFormatsFromString(o.format, 0))
        throwUsage("--format must be auto, obj+wrl, obj, wrl or ply, got '" + o.format + "'");
    o.constraints.names(); // A,B syntax
}

// Constraint flags add to the project's constraints; errors name the flags.
void applySolverFlags(const ReduceOptions& o, ReduceSettings& settings) {
    const ConstraintNames flags = o.constraints.names();
    if (!flags.empty()) {
        settings.constraintsSource = settings.constraints.empty()
                                         ? "--pin/--apart/--together"
                                         : "/reduction/constraints + --pin/--apart/--together";
        settings.constraints = combineConstraints(settings.constraints, flags);
    }
    settings.options.method = parseEnum<ReductionMethod>(o.method, "--method");
    // A project's rest model holds unless a flag says otherwise; without a project: auto.
    if (!o.rest.empty())
        settings.rest = restChoiceFlag(o.rest);
    else if (o.project.empty())
        settings.rest = RestChoice::Auto;
    if (!o.restViseme.empty()) {
        settings.restViseme = o.restViseme;
        settings.restVisemeSource = "--rest-viseme";
    }
    settings.closure = closureSetting(o.constraints);
    settings.maxErrorMm = o.constraints.maxErrorMm;
    for (const auto& file : o.compareMaps) settings.compareMaps.push_back(loadPhonemeMapFile(file));
}

// Everything a run needs, from a project file (flags given alongside override it) or from flags;
// in.set is the loaded set's doubles (null for a FloatVisemeSet).
ReduceInputs loadInputs(const ReduceOptions& o, bool weightsGiven, LoadedSet& loaded) {
    checkFlagCombinations(o);
    ReduceInputs in;
    if (o.project.empty()) {
        XfaceFace xface;
        loadFlagSet(o, xface, loaded);
        in.set = loaded.doubles;
        in.frequencies = loadFrequencies(o, loaded.view, xface);
        in.settings = loadSettings(o);
        applySolverFlags(o, in.settings);
        in.settings.millimetresPerUnit = guessMillimetresPerUnit(loaded.view.neutral->positions);
        return in;
    }
    const Project project = loadProject(o.project);
    in.set = loaded.doubles = std::make_shared<const VisemeSet>(loadProjectVisemeSet(project));
    loaded.view = shapesOf(*in.set);
    in.frequencies =
        (o.freqFile.empty() && o.freqs.empty()) ? project.frequencies : loadFrequencies(o, loaded.view);
    in.settings = weightsGiven ? loadSettings(o) : projectReduceSettings(project);
    in.settings.target = o.target != kTargetNotGiven ? o.target : project.reduction.target;
    if (weightsGiven) { // the project's constraints apply whatever the weights
        const ReduceSettings fromProject = projectReduceSettings(project);
        in.settings.constraints = fromProject.constraints;
        in.settings.constraintsSource = fromProject.constraintsSource;
        in.settings.rest = fromProject.rest;
        in.settings.restViseme = fromProject.restViseme;
        in.settings.restVisemeSource = fromProject.restVisemeSource;
    }
    applySolverFlags(o, in.settings);
    in.settings.millimetresPerUnit = guessMillimetresPerUnit(in.set->neutral.positions);
    return in;
}

int runReduce(const ReduceOptions& o, bool weightsGiven) {
    const auto t0 = std::chrono::steady_clock::now();
    LoadedSet loaded;
    const ReduceInputs inputs = loadInputs(o, weightsGiven, loaded);
    const SetShapes& set = loaded.view;
    const ReduceSettings& settings = inputs.settings;
    ReduceTimings timings;
    timings.loadMs = millisecondsSince(t0);

    const auto t1 = std::chrono::steady_clock::now();
    ProgressLine progress("reducing");
    const ReduceOutcome outcome =
        loaded.deferredKeys()
            ? runReduction(set, inputs.frequencies,
                           withPolicy(settings, ReducePolicy::batch(o.timeLimit), set.size()),
                           progress.callback(), KeyPositions::Deferred)
            : reduce(inputs, ReducePolicy::batch(o.timeLimit), progress.callback());
    progress.finish();
    timings.reduceMs = millisecondsSince(t1);

    const auto t2 = std::chrono::steady_clock::now();
    const std::filesystem::path outDir = o.outDir;
    const std::filesystem::path reportPath =
        o.report.empty() ? outDir / "report.json" : std::filesystem::path(o.report);
    refuseOverwritingInput(reportPath, "--report"); // before any output changes
    // The meshes, mapping.json and the default report replace the last run's as one set.
    OutputSet files(outDir, "reduce");
    const KeyMeshFormats formats = *keyMeshFormatsFromString(o.format, set.neutral->positions.size());
    if (loaded
            .deferredKeys()) // the keys' writer needs the neutral's faces, not its positions: 24 MB a million
        std::vector<Vec3>().swap(loaded.floats.neutral.positions);
    auto outputs = loaded.deferredKeys() ? writeReductionOutputs(files, outcome, formats, set)
                                         : writeReductionOutputs(files, outcome, formats);
    timings.writeMs = millisecondsSince(t2);
    const std::string report = reductionReportJson(outcome, settings.weightMode, timings, outputs);
    if (o.report.empty()) files.add("report.json", report);
    files.commit();
    if (!o.report.empty()) writeFileAtomically(reportPath, report);

    const Grouping& best = outcome.result.best();
    const int keys = static_cast<int>(outcome.result.curve.size());
    std::printf("Reduced %zu visemes to %d (weights: %s, %s): ", set.size(), keys,
                toString(settings.weightMode), toString(outcome.result.method));
    if (best.optimal)
        std::printf("optimal cost %.6g (proved)\n", best.cost);
    else
        std::printf("best cost found %.6g, lower bound %.6g, gap %.3g %% (time limit reached)\n", best.cost,
                    best.lowerBound, 100 * best.gap());
    for (std::size_t g = 0; g < outcome.model.keys.size(); ++g)
        std::printf("  %2zu: %s\n", g, outcome.model.keys[g].name.c_str());
    std::printf("%s\n", restSummary(outcome).c_str());
    if (outcome.maxError) std::printf("%s\n", maxErrorSummary(*outcome.maxError).c_str());
    std::printf("%s", visemeErrorTable(outcome).c_str());
    std::printf("Cost for p = 1..%d:", keys);
    for (const auto& grouping : outcome.result.curve) {
        if (!grouping.feasible())
            std::printf(" -");
        else if (grouping.optimal)
            std::printf(" %.4g", grouping.cost);
        else
            std::printf(" %.4g(>=%.4g)", grouping.cost, grouping.lowerBound);
    }
    std::printf("\n");
    for (const auto& given : outcome.comparedMaps) {
        const std::size_t p = given.groups.size();
        std::printf("Map %s as a grouping: %zu groups, cost %.6g", given.source.c_str(), p, given.cost);
        if (p <= outcome.result.curve.size() && outcome.result.curve[p - 1].feasible()) {
            const Grouping& opt = outcome.result.curve[p - 1];
            std::printf(" (%s %zu groups: %.6g, map +%.1f %%)",
                        opt.optimal ? "optimum for" : "best found for", p, opt.cost,
                        opt.cost > 0 ? 100 * (given.cost / opt.cost - 1) : 0.0);
        }
        std::printf("\n");
    }
    const std::string written = std::string(formats.obj ? " OBJ" : "") + (formats.wrl ? " VRML" : "") +
                                (formats.ply ? " binary-PLY" : "");
    std::fprintf(stderr, "Merged meshes (%s) and mapping.json in %s\nReport: %s\n", written.c_str() + 1,
                 outDir.string().c_str(), reportPath.string().c_str());
    return kExitOk;
}

} // namespace

void addReduceCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<ReduceOptions>();
    auto* cmd = app.add_subcommand("reduce", "Reduce a viseme set to m merged meshes (certified optimum)");
    cmd->add_option("--project", options->project,
                    "Project file (.vlproj): meshes, frequencies, weights and target; flags override it");
    cmd->add_option("--neutral", options->neutral, "Neutral mesh (OBJ, PLY or VRML)");
    cmd->add_option("--viseme", options->visemes, "A viseme as NAME=FILE (repeatable)");
    cmd->add_option("--visemes", options->visemeDir,
                    "Folder of viseme meshes, sorted by name; neutral.* in it is the neutral mesh");
    cmd->add_option("--fdp", options->fdp,
                    "An Xface face (XfaceEd .fdp): its Rest entity is the neutral, its Viseme entities the "
                    "visemes; <stem>.dic beside it maps a phoneme --freq-file given without --map");
    cmd->add_option("--freq", options->freqs, "A viseme frequency as NAME=F (repeatable)");
    cmd->add_option("--freq-file", options->freqFile,
                    "Frequencies: CSV name,frequency or JSON (viseme table, or phonemes + map)");
    cmd->add_option("--map", options->mapFile,
                    "Phoneme -> viseme map (CSV phoneme,viseme or JSON); makes --freq-file a phoneme table");
    auto* weights = cmd->add_option("--weights", options->weights,
                                    "Vertex weights: uniform, area, or a file of painted weights")
                        ->capture_default_str();
    cmd->add_option("--target,-m", options->target,
                    "Number of merged meshes m (1..n); required without --project");
    cmd->add_option("--out", options->outDir, "Output folder")->capture_default_str();
    cmd->add_option(
           "--format", options->format,
           "Key mesh files: obj+wrl (text, XfaceEd), obj, wrl, ply (binary, float32 positions) or auto "
           "(obj+wrl up to " +
               std::to_string(kBinaryKeyMeshVertices) + " vertices, ply above)")
        ->capture_default_str();
    cmd->add_option("--report", options->report, "JSON report path (default OUT/report.json)");
    addConstraintOptions(*cmd, options->constraints, "none");
    cmd->add_option("--method", options->method,
                    "Solver: auto, dp (subset DP, n <= 22), lp (set-partitioning LP, n <= 26) or bnb (branch "
                    "and bound, n <= 64)")
        ->capture_default_str();
    cmd->add_option("--time-limit", options->timeLimit,
                    "Seconds branch and bound may search for a proof; then the best grouping found is "
                    "reported with its gap (0: no limit)")
        ->capture_default_str();
    cmd->add_option(
        "--compare-map", options->compareMaps,
        "A phoneme -> viseme map (CSV or JSON) whose grouping of the visemes (named by phoneme) is "
        "costed under the same objective and compared with the optimum (repeatable)");
    cmd->add_option("--rest", options->rest,
                    "The rest pose: free (the neutral is an extra key that costs nothing; a viseme joins a "
                    "key or rests) or key (the rest is a key like any other). Default: the project's model "
                    "(/reduction/rest); else free when the set has a rest viseme (sil, viseme_sil or "
                    "--rest-viseme), else key");
    cmd->add_option("--rest-viseme", options->restViseme,
                    "The set's rest viseme (default: sil or viseme_sil); it always rests with --rest free");
    cmd->callback([&run, options, weights] {
        const bool weightsGiven = weights->count() > 0;
        run = [options, weightsGiven] { return runReduce(*options, weightsGiven); };
    });
}

} // namespace vl::cli
