#pragma once
// Viseme sets read from mesh files: a neutral and named viseme files, a folder of meshes, and the
// one rule for which mesh of a folder is the neutral.
#include "core/io/MeshIO.h"
#include "core/mesh/VisemeSet.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vl {

// Loads the neutral mesh and each (name, file) viseme, checking interpolability, unique non-empty
// names and n >= 2.
VisemeSet loadVisemeSet(const std::filesystem::path& neutral,
                        const std::vector<std::pair<std::string, std::filesystem::path>>& visemes);
// The same with the neutral already read (readReferenceMesh), e.g. to choose a loader by its size.
VisemeSet loadVisemeSet(const std::filesystem::path& neutral, ReferenceMesh neutralMesh,
                        const std::vector<std::pair<std::string, std::filesystem::path>>& visemes);

// The same set held as floats (FloatVisemeSet: `reduce` of large meshes), with the same checks and
// errors. A binary float32 PLY of the neutral's layout is copied from the file's bytes; any other
// file is read as loadVisemeSet reads it and rounded to float32 (the bound in VisemeSet.h).
FloatVisemeSet loadFloatVisemeSet(const std::filesystem::path& neutral,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& visemes);
FloatVisemeSet loadFloatVisemeSet(const std::filesystem::path& neutral, ReferenceMesh neutralMesh,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& visemes);

// All mesh files of a folder sorted by file name, named by their stem (the neutral file excluded).
std::vector<std::pair<std::string, std::filesystem::path>>
listVisemeFolder(const std::filesystem::path& folder, const std::filesystem::path& excluded = {});

// The one rule for which mesh of a folder is the neutral (`reduce --visemes`, `project new`, the
// editor's Open folder): the mesh file whose stem is "neutral" in any case (neutral.obj, Neutral.PLY);
// failing that, the one whose stem contains "neutral" (face_neutral.obj). Throws InputError naming the
// folder when no file qualifies, and naming the candidates when several do at the same rank (a
// neutral.obj beside a neutral.ply must not be decided by the order of a listing).
std::filesystem::path findNeutralMesh(const std::filesystem::path& folder);

} // namespace vl
