#pragma once
// One entry point for every export format: what `visemelab export` and the editor's export menu
// call (the reduced model of a project comes from core/project/ProjectRun.h).
#include "core/common/EnumNames.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl {

enum class ExportFormat { Glb, Runtime, Vrml, Obj };
template <> struct EnumNames<ExportFormat> {
    static constexpr const char* what = "format";
    static constexpr EnumName<ExportFormat> names[] = {{ExportFormat::Glb, "glb"},
                                                       {ExportFormat::Runtime, "runtime"},
                                                       {ExportFormat::Vrml, "vrml"},
                                                       {ExportFormat::Obj, "obj"}};
};

struct ExportOptions {
    bool quantise = false;         // runtime package: 16-bit positions
    std::string faceName = "face"; // vrml: <faceName>.fdp / .dic
};

// glb and runtime write the file `out` and <stem>.mapping.json beside it; vrml and obj write into
// the folder `out` (created), mapping.json included (core/export/MappingJson.h: every original
// viseme and phoneme -> key). Returns the paths written.
std::vector<std::filesystem::path> exportModel(const ReducedModel& model, ExportFormat format,
                                               const std::filesystem::path& out,
                                               const ExportOptions& options = {});

// A model (e.g. an imported glTF) as a viseme set: the keys become the visemes.
VisemeSet toVisemeSet(const ReducedModel& model, const std::filesystem::path& source);

} // namespace vl
