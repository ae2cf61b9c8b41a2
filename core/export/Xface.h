#pragma once
// XfaceEd / XfacePlayer compatibility (the Xface toolkit the paper targets).
//
// Export: the neutral and each key mesh as VRML97 (core/io), a face-definition file <face>.fdp in
// XfaceEd's format (see ../shared/data/xface-alice/alice.fdp): a head (file version 0.2, FAPU
// estimated from the neutral's bounding box until feature points are set in XfaceEd, identity
// translation/rotation) and a source with an Expression entity "Rest" for the neutral and one
// Viseme entity per key mesh; and <face>.dic, an Xface phoneme dictionary (first line the language,
// then one "phoneme viseme-alias" line per phoneme) mapping every phoneme to its merged viseme, plus
// pause lines "# <alias>" (as Xface's own dictionaries write silence) and "_ <alias>" (MBROLA's
// silence): the key "sil" was merged into, else "Rest". The VRML files use the layout XfacePlayer's
// loader reads (core/io formatVrml).
//
// The reader is core/import/XfaceImport.h.
#include "core/common/OutputSet.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// The .fdp text for a model whose meshes are named by KeyMeshFiles (extension ".wrl").
std::string formatFdp(const ReducedModel& model);

// Xface phoneme dictionary: language line, then "phoneme alias" lines (blank lines ignored).
std::string formatXfaceDictionary(const ReducedModel& model, std::string_view language = "english");

// The alias each key gets in the .fdp and .dic: its name with white space replaced, made unique
// and never "Rest".
std::vector<std::string> xfaceAliases(const ReducedModel& model);

// Stages the VRML meshes, <faceName>.fdp and <faceName>.dic in `outputs`; returns the file names.
std::vector<std::string> addXfaceFace(OutputSet& outputs, const ReducedModel& model,
                                      std::string_view faceName = "face");
// The same written into outDir as the output set "export-vrml".
std::vector<std::string> writeXfaceFace(const std::filesystem::path& outDir, const ReducedModel& model,
                                        std::string_view faceName = "face");

} // namespace vl
