#include "core/export/Export.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/OutputSet.h"
#include "core/export/GltfExport.h"
#include "core/export/KeyMeshFiles.h"
#include "core/export/MappingJson.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/export/Xface.h"

namespace vl {

std::vector<std::filesystem::path> exportModel(const ReducedModel& model, ExportFormat format,
                                               const std::filesystem::path& out,
                                               const ExportOptions& options) {
    if (out.empty()) throwInputError("export", "no output path");
    const auto inFolder = [&](const std::vector<std::string>& names) {
        std::vector<std::filesystem::path> paths;
        for (const std::string& name : names) paths.push_back(out / name);
        return paths;
    };
    // mapping.json beside every format: <stem>.mapping.json beside a file, inside a folder export.
    const auto withMapping = [&](const std::filesystem::path& file) {
        const std::filesystem::path mapping = out.parent_path() / (out.stem().string() + ".mapping.json");
        writeFileAtomically(mapping, formatMappingJson(model, {}));
        return std::vector<std::filesystem::path>{file, mapping};
    };
    // A folder export replaces the previous export of its format as one set (core/common/OutputSet.h).
    const auto folderExport = [&](const char* setName, const auto& stage) {
        OutputSet files(out, setName);
        std::vector<std::string> names = stage(files);
        const std::string extension = format == ExportFormat::Vrml ? ".wrl" : ".obj";
        names.push_back("mapping.json");
        files.add(names.back(), formatMappingJson(model, {{"file", extension}}));
        files.commit();
        return inFolder(names);
    };
    switch (format) {
    case ExportFormat::Glb:
        writeGlb(out, model);
        return withMapping(out);
    case ExportFormat::Runtime:
        writeRuntimePackage(out, model, {.quantise = options.quantise});
        return withMapping(out);
    case ExportFormat::Vrml:
        return folderExport("export-vrml",
                            [&](OutputSet& files) { return addXfaceFace(files, model, options.faceName); });
    case ExportFormat::Obj:
        return folderExport("export-obj",
                            [&](OutputSet& files) { return addKeyMeshFiles(files, model, ".obj"); });
    }
    return {};
}

VisemeSet toVisemeSet(const ReducedModel& model, const std::filesystem::path& source) {
    validateReducedModel(model, source.string());
    VisemeSet set;
    set.neutral = model.neutral;
    set.neutralSource = source;
    for (const KeyMesh& key : model.keys) set.visemes.push_back({key.name, key.positions});
    return set;
}

} // namespace vl
