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
// Import: an .fdp's entities; the neutral is the entity aliased "Rest" (else the first entity),
// the visemes are the category="Viseme" entities in file order, each entity's mesh files (relative
// to the .fdp) read with core/io and concatenated. <stem>.dic beside the .fdp, when present, gives
// the phoneme map. Errors name the file, line and entity.
#include "core/common/OutputSet.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct FdpEntity {
    std::string alias;
    std::string category;                 // "Viseme", "Expression", "Modifier", ...
    std::vector<std::string> meshFiles;   // as written in <mesh file=...>
    std::vector<std::string> meshFormats; // <mesh format=...>, e.g. "wrl"
    int line = 0;
};

struct FdpDocument {
    std::string fileVersion;                          // <head><file version=...>
    std::vector<std::pair<std::string, double>> fapu; // <head><fapu ...> attributes in file order
    std::vector<FdpEntity> entities;                  // <source><entity> in file order
};

// Parses the XML; throws InputError "<source>:<line>: ..." for malformed XML or a missing
// <xfdp>/<source>, an entity without alias or mesh file.
FdpDocument parseFdp(std::string_view text, std::string_view source);
// The .fdp text for a model whose meshes are named by KeyMeshFiles (extension ".wrl").
std::string formatFdp(const ReducedModel& model);

// Xface phoneme dictionary: language line, then "phoneme alias" lines (blank lines ignored).
PhonemeVisemeMap parseXfaceDictionary(std::string_view text, std::string_view source,
                                      std::string* language = nullptr);
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

struct XfaceFace {
    VisemeSet set;
    PhonemeVisemeMap dictionary;           // empty when no <stem>.dic exists; phonemes -> Viseme entities
    std::vector<std::string> restPhonemes; // .dic phonemes shown by the neutral entity (pauses): not visemes
};
XfaceFace loadXfaceFace(const std::filesystem::path& fdpPath);

} // namespace vl
