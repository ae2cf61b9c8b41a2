#pragma once
// One mesh file per key mesh (plus the neutral), in any format core/io writes: the OBJ export and
// the VRML meshes of the XfaceEd export.
#include "core/common/OutputSet.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

// "neutral" + extension for the neutral mesh, "reduced_<k>_<safe name>" + extension for key k
// (the names the reduce command uses, unique through the index; fileSafeName: core/common/FileNames.h).
std::string neutralFileName(std::string_view extension);
std::string keyFileName(const ReducedModel& model, std::size_t key, std::string_view extension);

// Stages the neutral and every key mesh with `extension` (".obj", ".ply" or ".wrl") in `outputs`;
// returns the file names, neutral first.
std::vector<std::string> addKeyMeshFiles(OutputSet& outputs, const ReducedModel& model,
                                         std::string_view extension);

// Writes the neutral and every key mesh into `outDir` (created if missing) as one output set named
// "export-<format>" (stale key meshes of an earlier export removed); returns the file names written.
std::vector<std::string> writeKeyMeshFiles(const std::filesystem::path& outDir, const ReducedModel& model,
                                           std::string_view extension);

} // namespace vl
