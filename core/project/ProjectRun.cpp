#include "core/project/ProjectRun.h"

#include "core/common/Error.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/io/JsonRead.h"
#include "core/io/MeshIO.h"

namespace vl {

namespace {

// "proj.vlproj: /visemes/3": a JSON path of the project, named with the project file when it has one.
std::string projectWhere(const Project& project, std::string_view jsonPath) {
    if (project.path.empty()) return std::string(jsonPath);
    return project.path.string() + ": " + std::string(jsonPath);
}

// "proj.vlproj: /visemes/3/file (mouth/aa.obj)": where a mesh came from, for messages.
std::string meshSource(const Project& project, std::string_view jsonPath, const std::filesystem::path& file) {
    if (file.empty()) return projectWhere(project, jsonPath);
    return projectWhere(project, jsonPath) + "/file (" + file.generic_string() + ")";
}

MeshData readProjectMesh(const Project& project, std::string_view jsonPath,
                         const std::filesystem::path& file) {
    try {
        return readMesh(resolveProjectFile(project, file));
    } catch (const InputError& e) {
        throwInputError(meshSource(project, jsonPath, file), e.what());
    }
}

} // namespace

void checkAvatarVisemeNames(const Project& project, const std::vector<std::string>& avatarVisemes) {
    std::vector<std::string> listed;
    for (const ProjectViseme& viseme : project.visemes) listed.push_back(viseme.name);
    if (listed == avatarVisemes) return;
    const auto join = [](const std::vector<std::string>& names) {
        std::string text;
        for (const std::string& name : names) text += (text.empty() ? "" : " ") + name;
        return text.empty() ? std::string("none") : text;
    };
    throwInputError(
        projectWhere(project, "/visemes"),
        "the project lists the visemes " + join(listed) + " but the avatar " +
            project.avatar.file.generic_string() + " now has " + join(avatarVisemes) + " (selected by " +
            (project.avatar.targets.empty() ? "Oculus names" : "'" + project.avatar.targets + "'") + ")");
}

VisemeSet loadProjectVisemeSet(const Project& project) {
    if (project.avatar.isSet()) {
        AvatarScan scan;
        try {
            scan = scanAvatar(loadGltfDocument(resolveProjectFile(project, project.avatar.file)),
                              {project.avatar.targets, false, project.avatar.addedRest});
        } catch (const InputError& e) {
            throwInputError(projectWhere(project, "/avatar/file"), e.what());
        }
        checkAvatarVisemeNames(project, scan.visemes);
        for (std::size_t i = 0; i < project.visemes.size(); ++i) { // sculpted in the editor
            const std::vector<Vec3>& sculpted = project.visemes[i].positions;
            if (sculpted.empty()) continue;
            if (sculpted.size() != scan.set.vertexCount())
                throwInputError(projectWhere(project, jsonPathAppend("/visemes", i) + "/positions"),
                                "expected " + std::to_string(scan.set.vertexCount()) +
                                    " vertices (the avatar's meshes carrying visemes), found " +
                                    std::to_string(sculpted.size()));
            scan.set.visemes[i].positions = sculpted;
        }
        return std::move(scan.set);
    }
    if (!project.neutral.isSet())
        throwInputError(projectWhere(project, "/neutral"), "the project has no neutral mesh");
    VisemeSet set;
    const std::string neutralSource = meshSource(project, "/neutral", project.neutral.file);
    if (project.neutral.isEmbedded()) {
        set.neutral = project.neutral.embedded;
    } else {
        set.neutral = readProjectMesh(project, "/neutral", project.neutral.file);
        set.neutralSource = resolveProjectFile(project, project.neutral.file);
    }
    // Before any viseme is read: a project may name one big mesh file for thousands of visemes.
    checkVisemeSetSize(project.visemes.size(), set.vertexCount(), projectWhere(project, "/visemes"));
    std::vector<std::filesystem::path> files(project.visemes.size()); // empty for embedded shapes
    for (std::size_t i = 0; i < project.visemes.size(); ++i) {
        const ProjectViseme& viseme = project.visemes[i];
        const std::string path = jsonPathAppend("/visemes", i);
        Viseme loaded{viseme.name, {}};
        if (viseme.isEmbedded()) {
            if (viseme.positions.size() != set.neutral.positions.size())
                throwInputError(projectWhere(project, path + "/positions"),
                                "not interpolable: " + std::to_string(viseme.positions.size()) +
                                    " vertices (the neutral mesh " + neutralSource + " has " +
                                    std::to_string(set.neutral.positions.size()) + ")");
            loaded.positions = viseme.positions;
        } else {
            MeshData mesh = readProjectMesh(project, path, viseme.file);
            checkInterpolable(set.neutral, neutralSource, mesh, meshSource(project, path, viseme.file));
            files[i] = resolveProjectFile(project, viseme.file);
            loaded.positions = std::move(mesh.positions);
        }
        set.visemes.push_back(std::move(loaded));
    }
    checkVisemeSetValues(set, projectWhere(project, "/visemes"), files);
    return set;
}

ReduceSettings projectReduceSettings(const Project& project) {
    ReduceSettings settings;
    settings.weightMode = project.weights.mode;
    settings.paintedWeights = project.weights.painted;
    settings.paintedWeightsSource = projectWhere(project, "/weights/painted");
    settings.target = project.reduction.target;
    settings.constraints = project.reduction.constraints;
    settings.constraintsSource = projectWhere(project, "/reduction/constraints");
    settings.rest = project.reduction.rest;
    settings.restViseme = project.reduction.restViseme;
    settings.restVisemeSource = projectWhere(project, "/reduction/restViseme");
    // An avatar project reduces as `avatar reduce` does: the lips-closed viseme keeps a key.
    if (project.avatar.isSet()) settings.closure = kClosureAuto;
    return settings;
}

ReduceInputs projectReduceInputs(const Project& project, std::shared_ptr<const VisemeSet> set) {
    if (set->size() < 2)
        throwInputError(projectWhere(project, "/visemes"),
                        "a reduction needs at least 2 visemes, found " + std::to_string(set->size()));
    if (project.reduction.target < 1 || static_cast<std::size_t>(project.reduction.target) > set->size())
        throwInputError(projectWhere(project, "/reduction/target"), std::to_string(project.reduction.target) +
                                                                        " is outside the allowed range 1.." +
                                                                        std::to_string(set->size()));
    if (project.weights.mode == WeightMode::Painted && project.weights.painted.size() != set->vertexCount())
        throwInputError(projectWhere(project, "/weights/painted"),
                        "expected " + std::to_string(set->vertexCount()) +
                            " weights (one per vertex), found " +
                            std::to_string(project.weights.painted.size()));
    return {std::move(set), project.frequencies, projectReduceSettings(project)};
}

ReduceOutcome reduceProject(const Project& project, const VisemeSet& set, const ProgressCallback& progress,
                            const ReducePolicy& policy) {
    // Viewed, not copied: the caller keeps the set alive for the run.
    return reduce(projectReduceInputs(project, viewedSet(set)), policy, progress);
}

void storeReductionResult(Project& project, const ReduceOutcome& outcome) {
    project.reduction.result = outcome.result;
}

ReducedModel projectReducedModel(const Project& project, bool unreduced, const ReducePolicy& policy) {
    return projectReducedModel(project, loadProjectVisemeSet(project), unreduced, policy);
}

ReducedModel projectReducedModel(const Project& project, const VisemeSet& set, bool unreduced,
                                 const ReducePolicy& policy) {
    if (unreduced)
        return unreducedModelOf({viewedSet(set), project.frequencies, projectReduceSettings(project)});
    const ReduceInputs inputs = projectReduceInputs(project, viewedSet(set));
    return reducedModel(inputs, recordedGrouping(inputs, project.reduction.result), policy);
}

ProjectExport exportProjectModel(const Project& project, const VisemeSet& set, ExportFormat format,
                                 const std::filesystem::path& out, const ExportOptions& options,
                                 bool unreduced, const ReducePolicy& policy) {
    const ReducedModel model = projectReducedModel(project, set, unreduced, policy);
    return {model.keys.size(), exportModel(model, format, out, options)};
}

} // namespace vl
