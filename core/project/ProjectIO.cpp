// Loading and saving project files: version dispatch, validation, atomic write, path rebasing.
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/io/JsonWrite.h"
#include "core/project/ProjectJson.h"

namespace vl {

namespace {

std::filesystem::path folderOf(const std::filesystem::path& file) {
    return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

[[noreturn]] void rethrowWithPrefix(const InputError& e, std::string_view prefix) {
    throw InputError(std::string(prefix) + e.what());
}

std::string toText(const Project& project) {
    try {
        return formatJsonPretty(projectToJson(project));
    } catch (const Json::exception& e) { // e.g. a name that is not valid UTF-8
        throwInputError("project", std::string("cannot be written as JSON: ") + e.what());
    }
}

// projectFromJsonText without the file name in front of the validation errors (saving checks a
// project that has no file yet).
Project projectFromJsonTextAt(std::string_view text, const std::filesystem::path& projectFile,
                              bool checkFiles) {
    const Json document = parseJsonStrict(text, projectFile.string());
    const JsonNode root(document, "");
    const int version = projectVersionOf(root);
    Project project;
    if (version >= kFirstLayoutVersion) {
        project = projectFromJson(root, {folderOf(projectFile), checkFiles, version});
    } else {
        const Json upgraded = migrateProjectJson(root, version);
        try {
            project = projectFromJson(JsonNode(upgraded, ""),
                                      {folderOf(projectFile), checkFiles, kFirstLayoutVersion});
        } catch (const InputError& e) {
            rethrowWithPrefix(e, "in the version " + std::to_string(version) +
                                     " project after migration to version " +
                                     std::to_string(kFirstLayoutVersion) + ": ");
        }
    }
    project.path = projectFile;
    // Later checks of the frequencies (against the loaded meshes) name the project file too.
    project.frequencies.origin.text = projectFile.string() + ":/frequencies";
    if (!project.frequencies.map.entries.empty())
        project.frequencies.map.origin.text = project.frequencies.origin.text + "/map";
    return project;
}

} // namespace

Project projectFromJsonText(std::string_view text, const std::filesystem::path& projectFile,
                            bool checkFiles) {
    try {
        return projectFromJsonTextAt(text, projectFile, checkFiles);
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.starts_with(projectFile.string() + ": "))
            throw; // JSON syntax errors name the file themselves
        rethrowWithPrefix(e, projectFile.string() + ": ");
    }
}

// Every file the project names is off limits to the run's outputs, read or not (core/common/InputRegistry.h).
static void noteProjectReferences(const Project& project) {
    if (!project.neutral.file.empty()) noteReferencedFile(resolveProjectFile(project, project.neutral.file));
    for (const ProjectViseme& viseme : project.visemes)
        if (!viseme.file.empty()) noteReferencedFile(resolveProjectFile(project, viseme.file));
    if (project.avatar.isSet()) noteReferencedFile(resolveProjectFile(project, project.avatar.file));
}

Project loadProject(const std::filesystem::path& file) {
    Project project =
        projectFromJsonText(readFileToString(file), file, true); // read errors name the file too
    noteProjectReferences(project);
    return project;
}

std::string projectToJsonText(const Project& project) {
    std::string text = toText(project);
    // One set of rules for loading and saving: the text must load back to the same state. This also
    // refuses NaN (written as null by nlohmann) and every other invalid value with its JSON path.
    const Project reloaded = projectFromJsonTextAt(text, project.path, false);
    Project expected = project;
    expected.path = reloaded.path;
    if (reloaded != expected)
        throwInputError("project",
                        "does not survive a save/load round trip (groups not in canonical order?)");
    return text;
}

void saveProject(const std::filesystem::path& file, const Project& project) {
    std::string text;
    try {
        text = projectToJsonText(rebaseProject(project, file));
    } catch (const InputError& e) {
        rethrowWithPrefix(e, "cannot save " + file.string() + ": ");
    }
    writeFileAtomically(file, text);
}

std::filesystem::path resolveProjectFile(const Project& project, const std::filesystem::path& file) {
    if (file.is_absolute() || project.path.empty()) return file;
    return (folderOf(project.path) / file).lexically_normal();
}

std::filesystem::path projectRelativePath(const std::filesystem::path& projectFile,
                                          const std::filesystem::path& file) {
    const auto target = std::filesystem::absolute(file).lexically_normal();
    const auto relative =
        target.lexically_relative(std::filesystem::absolute(folderOf(projectFile)).lexically_normal());
    return relative.empty() ? target : relative;
}

Project rebaseProject(const Project& project, const std::filesystem::path& newFile) {
    Project rebased = project;
    rebased.path = newFile;
    // Every mesh path, absolute ones too, is stored relative to the project file so that a project
    // folder moved or copied as a whole (with its meshes) keeps working.
    const auto oldFolder = std::filesystem::absolute(folderOf(project.path)).lexically_normal();
    const auto rebase = [&](std::filesystem::path& file) {
        if (!file.empty()) file = projectRelativePath(newFile, file.is_absolute() ? file : oldFolder / file);
    };
    rebase(rebased.neutral.file);
    for (auto& viseme : rebased.visemes) rebase(viseme.file);
    rebase(rebased.avatar.file);
    return rebased;
}

} // namespace vl
