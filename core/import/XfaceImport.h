#pragma once
// XfaceEd / XfacePlayer faces read back (the Xface toolkit the paper targets); the writer is
// core/export/Xface.h.
//
// An .fdp's entities; the neutral is the entity aliased "Rest" (else the first entity), the visemes
// are the category="Viseme" entities in file order, each entity's mesh files (relative to the .fdp)
// read with core/io and concatenated. <stem>.dic beside the .fdp, when present, gives the phoneme
// map. Errors name the file, line and entity.
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vl {

// The alias of the neutral face's entity: the exporter writes it, the reader looks for it.
constexpr const char* kXfaceRestAlias = "Rest";

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

// Xface phoneme dictionary: language line, then "phoneme alias" lines (blank lines ignored).
PhonemeVisemeMap parseXfaceDictionary(std::string_view text, std::string_view source,
                                      std::string* language = nullptr);

struct XfaceFace {
    VisemeSet set;
    PhonemeVisemeMap dictionary;           // empty when no <stem>.dic exists; phonemes -> Viseme entities
    std::vector<std::string> restPhonemes; // .dic phonemes shown by the neutral entity (pauses): not visemes
};
XfaceFace loadXfaceFace(const std::filesystem::path& fdpPath);

} // namespace vl
