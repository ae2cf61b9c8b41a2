#pragma once
// One entry point for every export format, and the reduced model of a project: what
// `visemelab export` and the editor's export menu call.
#include "core/reduce/ReducedModel.h"
#include "core/reduce/VisemeSet.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl {

struct Project;

enum class ExportFormat { Glb, Runtime, Vrml, Obj };

std::optional<ExportFormat> exportFormatFromString(std::string_view text); // "glb", "runtime", "vrml", "obj"
const char* toString(ExportFormat format);

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

// The project's reduced model: its meshes, frequencies and phoneme map, grouped by the stored last
// result when it matches the viseme count and target, else by a fresh exact reduction with the
// project's settings. `unreduced` exports every original viseme as its own key instead.
ReducedModel projectReducedModel(const Project& project, bool unreduced = false);
// The same with the project's meshes already loaded (loadProjectVisemeSet).
ReducedModel projectReducedModel(const Project& project, const VisemeSet& set, bool unreduced = false);

// A model (e.g. an imported glTF) as a viseme set: the keys become the visemes.
VisemeSet toVisemeSet(const ReducedModel& model, const std::filesystem::path& source);

} // namespace vl
