// `visemelab project new|check`: create a project file from meshes and tables, or validate one
// (the file and the meshes it references) with the JSON path of the first problem.
#include "app/cli/Command.h"
#include "core/common/Error.h"
#include "core/document/AvatarDocument.h"
#include "core/face/BundledFace.h"
#include "core/gltf/TargetNames.h"
#include "core/gltf/VisemeMapNames.h"
#include "core/io/VisemeSetFiles.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/ProjectRun.h"

#include <algorithm>
#include <cstdio>

namespace vl::cli {

namespace {

struct NewProjectOptions {
    std::string out;
    std::string visemeDir;
    std::string avatar;
    std::string targets;
    std::string neutral;
    std::string freqFile;
    std::string phonemeFile;
    std::string mapFile;
    std::string weights = "uniform";
    int target = 1;
    std::string face;
    std::string order;
    bool reduce = false;
    std::string rest = toString(kNewProjectRest); // the reduction model (ReduceRun.h RestChoice)
    bool addRest = false, noAddRest = false;      // --avatar: force / refuse the added rest viseme
};

RestChoice restOf(const NewProjectOptions& o) {
    if (const auto choice = fromString<RestChoice>(o.rest)) return *choice;
    throwUsage("--rest must be auto, free or key, got '" + o.rest + "'");
}

// Whether an avatar lacking a rest viseme gains one: by default when the rest is free or auto (silence
// then rests at all weights 0, and an Oculus avatar gets the bundled en-us table), else when asked.
bool addsAvatarRest(const NewProjectOptions& o) {
    if (o.addRest && o.noAddRest) throwUsage("give --add-rest or --no-add-rest, not both");
    return !o.noAddRest && (o.addRest || restOf(o) != RestChoice::Key);
}

// Frequencies from the options: a viseme table, or a phoneme table plus a phoneme -> viseme map.
FrequencySource frequenciesOf(const NewProjectOptions& o) {
    if (!o.freqFile.empty()) return loadFrequencyFile(o.freqFile);
    FrequencySource source;
    if (o.phonemeFile.empty()) return source;
    const FrequencySource table = loadFrequencyFile(o.phonemeFile);
    // A plain two-column file reads as direct frequencies: here its names are phonemes.
    source.phonemes = table.isPhonemeBased() ? table.phonemes : table.visemeFrequencies;
    source.map = loadPhonemeMapFile(o.mapFile);
    return source;
}

// The visemes in the order of the comma-separated `order` (which must name each exactly once).
std::vector<ProjectViseme> reordered(std::vector<ProjectViseme> visemes, const std::string& order) {
    if (order.empty()) return visemes;
    std::vector<ProjectViseme> result;
    std::size_t start = 0;
    while (start <= order.size()) {
        const auto end = std::min(order.find(',', start), order.size());
        const std::string name = order.substr(start, end - start);
        start = end + 1;
        const auto it =
            std::find_if(visemes.begin(), visemes.end(), [&](const auto& v) { return v.name == name; });
        if (it == visemes.end())
            throwInputError("--order", "'" + name + "' is not a viseme of the folder (or is repeated)");
        result.push_back(std::move(*it));
        visemes.erase(it);
    }
    if (!visemes.empty()) throwInputError("--order", "does not list '" + visemes.front().name + "'");
    return result;
}

// An avatar project: the avatar's visemes by name, frequencies as the editor's Import avatar...
// chooses them unless tables are given (their viseme names matched to the avatar's by meaning).
Project avatarProject(const NewProjectOptions& o, bool targetGiven) {
    if (!o.neutral.empty() || !o.order.empty() || !o.face.empty())
        throwUsage(
            "--avatar takes its meshes and their order from the avatar: drop --neutral, --order, --face");
    if (!o.targets.empty()) checkGlobPattern(o.targets, "--targets");
    Project project = newAvatarProject(
        o.avatar, o.targets, bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus"), addsAvatarRest(o));
    if (!o.freqFile.empty() || !o.phonemeFile.empty()) {
        std::vector<std::string> names;
        for (const ProjectViseme& viseme : project.visemes) names.push_back(viseme.name);
        project.frequencies = frequenciesOntoVisemes(frequenciesOf(o), names);
    }
    if (targetGiven) project.reduction.target = o.target;
    project.reduction.rest = restOf(o);
    return project;
}

int runNew(const NewProjectOptions& o, bool targetGiven) {
    if (!o.freqFile.empty() && !o.phonemeFile.empty()) throwUsage("give --freq-file or --phonemes, not both");
    if (o.phonemeFile.empty() != o.mapFile.empty()) throwUsage("--phonemes and --map go together");
    if (o.visemeDir.empty() == o.avatar.empty()) throwUsage("give --visemes FOLDER or --avatar FILE");
    const std::filesystem::path out = o.out;
    if (!o.avatar.empty()) {
        Project project = avatarProject(o, targetGiven);
        project.path = out;
        if (o.reduce) storeReductionResult(project, reduceProject(project, loadProjectVisemeSet(project)));
        saveProject(out, project);
        const std::string added = project.avatar.addedRest.empty()
                                      ? std::string()
                                      : " (" + project.avatar.addedRest + " added: the base mesh, no target)";
        std::fprintf(stderr, "wrote %s: avatar %s, %zu visemes%s, target %d%s\n", out.string().c_str(),
                     o.avatar.c_str(), project.visemes.size(), added.c_str(), project.reduction.target,
                     o.reduce ? ", reduced" : "");
        return kExitOk;
    }
    if (o.addRest || o.noAddRest) throwUsage("--add-rest and --no-add-rest go with --avatar");
    Project project;
    project.path = out;
    project.reduction.rest = restOf(o);

    const std::filesystem::path neutral =
        o.neutral.empty() ? findNeutralMesh(o.visemeDir) : std::filesystem::path(o.neutral);
    project.neutral.file = projectRelativePath(out, neutral);
    for (const auto& [name, file] : listVisemeFolder(o.visemeDir, neutral))
        project.visemes.push_back({name, projectRelativePath(out, file), {}});

    project.visemes = reordered(std::move(project.visemes), o.order);
    project.frequencies = frequenciesOf(o);
    const auto mode = fromString<WeightMode>(o.weights);
    if (!mode || *mode == WeightMode::Painted)
        throwInputError("--weights", "expected uniform or area, got '" + o.weights + "'");
    project.weights.mode = *mode;
    project.reduction.target = o.target;

    if (!o.face.empty()) {
        project.deformation.cascade = face::makeFaceCascade(parseEnum<face::Individual>(o.face, "--face"));
        project.deformation.values = project.deformation.cascade.defaults();
        project.deformation.visemes = oculusVisemes();
    }
    if (o.reduce) storeReductionResult(project, reduceProject(project, loadProjectVisemeSet(project)));
    saveProject(out, project);
    std::fprintf(stderr, "wrote %s: %zu visemes%s\n", out.string().c_str(), project.visemes.size(),
                 o.reduce ? (", reduced to " + std::to_string(o.target)).c_str() : "");
    return kExitOk;
}

int runCheck(const std::string& file) {
    const Project project = loadProject(file);
    std::size_t vertices = 0;
    if (project.neutral.isSet()) vertices = loadProjectVisemeSet(project).vertexCount();
    std::printf("%s: valid project (version %d): %zu visemes, %zu vertices, %s frequencies, weights %s, "
                "target %d%s%s\n",
                file.c_str(), projectVersionFor(project), project.visemes.size(), vertices,
                project.frequencies.isPhonemeBased() ? "phoneme" : "viseme", toString(project.weights.mode),
                project.reduction.target, project.reduction.result ? ", with a reduction result" : "",
                project.deformation.isSet() ? ", with a deformable face" : "");
    return kExitOk;
}

} // namespace

void addProjectCommand(CLI::App& app, CommandRunner& run) {
    auto* cmd = app.add_subcommand("project", "Create or check a project file (.vlproj)");
    cmd->require_subcommand(1, 1);

    auto o = std::make_shared<NewProjectOptions>();
    auto* create =
        cmd->add_subcommand("new", "Create a project from a folder of viseme meshes or from an avatar");
    create->add_option("--out", o->out, "Project file to write")->required();
    create->add_option("--visemes", o->visemeDir,
                       "Folder of viseme meshes (sorted by name; neutral.* excluded)");
    create->add_option(
        "--avatar", o->avatar,
        "Avatar (.glb, .gltf, .vrm) whose morph targets are the visemes (instead of --visemes)");
    create->add_option("--targets", o->targets,
                       "With --avatar: glob selecting the viseme targets (default: the Oculus visemes)");
    create->add_option("--neutral", o->neutral,
                       "Neutral mesh (default: neutral.obj/.ply/.wrl in the folder)");
    create->add_option("--freq-file", o->freqFile, "Viseme frequencies (CSV or JSON)");
    create->add_option("--phonemes", o->phonemeFile, "Phoneme frequency table (CSV or JSON), with --map");
    create->add_option("--map", o->mapFile, "Phoneme -> viseme map (CSV or JSON)");
    create->add_option("--weights", o->weights, "uniform | area")->capture_default_str();
    auto* target = create->add_option("--target", o->target, "Reduction target m (default 1; avatars n / 2)");
    create->add_option("--face", o->face, "Include a deformable face: bundled | retarget");
    create->add_option("--order", o->order, "Viseme order, comma-separated (default: sorted by file name)");
    create->add_flag("--reduce", o->reduce, "Run the reduction and store its result in the project");
    create
        ->add_option("--rest", o->rest,
                     "The reduction model: auto (free when the set has a rest viseme, sil or viseme_sil), "
                     "free (the rest pose is a free key; visemes may rest) or key (the rest is a key like "
                     "any other, as projects before version 3)")
        ->capture_default_str();
    create->add_flag(
        "--add-rest", o->addRest,
        "With --avatar: add a rest viseme (viseme_sil or sil: the base mesh, no target) when the "
        "avatar has none, whatever the model (default: added with --rest auto or free)");
    create->add_flag("--no-add-rest", o->noAddRest,
                     "With --avatar: keep only the avatar's visemes, even when it has no rest viseme");
    create->callback([&run, o, target] {
        const bool targetGiven = target->count() > 0;
        run = [o, targetGiven] { return runNew(*o, targetGiven); };
    });

    auto file = std::make_shared<std::string>();
    auto* check = cmd->add_subcommand("check", "Validate a project file and read the meshes it references");
    check->add_option("project", *file, "Project file (.vlproj)")->required();
    check->callback([&run, file] { run = [file] { return runCheck(*file); }; });
}

} // namespace vl::cli
