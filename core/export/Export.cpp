#include "core/export/Export.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/export/Gltf.h"
#include "core/export/KeyMeshFiles.h"
#include "core/export/MappingJson.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/export/Xface.h"
#include "core/project/ProjectRun.h"

namespace vl {

std::optional<ExportFormat> exportFormatFromString(std::string_view text) {
    for (ExportFormat f : {ExportFormat::Glb, ExportFormat::Runtime, ExportFormat::Vrml, ExportFormat::Obj})
        if (text == toString(f)) return f;
    return std::nullopt;
}

const char* toString(ExportFormat format) {
    switch (format) {
    case ExportFormat::Glb:
        return "glb";
    case ExportFormat::Runtime:
        return "runtime";
    case ExportFormat::Vrml:
        return "vrml";
    case ExportFormat::Obj:
        return "obj";
    }
    return "?";
}

std::vector<std::filesystem::path> exportModel(const ReducedModel& model, ExportFormat format,
                                               const std::filesystem::path& out,
                                               const ExportOptions& options) {
    if (out.empty()) throwInputError("export", "no output path");
    const auto inFolder = [&](const std::vector<std::string>& names) {
        std::vector<std::filesystem::path> paths;
        for (const std::string& name : names) paths.push_back(out / name);
        return paths;
    };
    // mapping.json beside every format: inside a folder export, <stem>.mapping.json beside a file.
    const auto withMapping = [&](std::vector<std::filesystem::path> written, bool folder) {
        std::vector<std::string> keyFiles;
        if (folder)
            for (std::size_t k = 0; k < model.keys.size(); ++k)
                keyFiles.push_back(keyFileName(model, k, format == ExportFormat::Vrml ? ".wrl" : ".obj"));
        const std::filesystem::path mapping =
            folder ? out / "mapping.json" : out.parent_path() / (out.stem().string() + ".mapping.json");
        writeFileAtomically(mapping, formatMappingJson(model, keyFiles));
        written.push_back(mapping);
        return written;
    };
    switch (format) {
    case ExportFormat::Glb:
        writeGlb(out, model);
        return withMapping({out}, false);
    case ExportFormat::Runtime:
        writeRuntimePackage(out, model, {.quantise = options.quantise});
        return withMapping({out}, false);
    case ExportFormat::Vrml:
        return withMapping(inFolder(writeXfaceFace(out, model, options.faceName)), true);
    case ExportFormat::Obj:
        return withMapping(inFolder(writeKeyMeshFiles(out, model, ".obj")), true);
    }
    return {};
}

ReducedModel projectReducedModel(const Project& project, bool unreduced) {
    return projectReducedModel(project, loadProjectVisemeSet(project), unreduced);
}

ReducedModel projectReducedModel(const Project& project, const VisemeSet& set, bool unreduced) {
    std::vector<std::string> names;
    for (const Viseme& v : set.visemes) names.push_back(v.name);
    if (unreduced)
        return unreducedModel(set, visemeFrequencies(project.frequencies, names), project.frequencies);
    const auto& stored = project.reduction.result;
    if (stored && !stored->curve.empty() &&
        static_cast<int>(stored->curve.size()) == project.reduction.target) {
        const std::vector<int> groupOf = stored->groupOf();
        if (groupOf.size() == set.size())
            return buildReducedModel(set, visemeFrequencies(project.frequencies, names), groupOf,
                                     project.frequencies);
    }
    const ReduceOutcome outcome = reduceProject(project, set);
    return buildReducedModel(set, outcome.frequencies, outcome.result.groupOf(), project.frequencies);
}

VisemeSet toVisemeSet(const ReducedModel& model, const std::filesystem::path& source) {
    validateReducedModel(model, source.string());
    VisemeSet set;
    set.neutral = model.neutral;
    set.neutralSource = source;
    for (const KeyMesh& key : model.keys) set.visemes.push_back({key.name, source, key.positions});
    return set;
}

} // namespace vl
