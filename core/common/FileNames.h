#pragma once
// Names that become file names: an exported key mesh (core/export/KeyMeshFiles.h) and the check
// that a viseme read from a parameter file can be written as <name>.obj (core/import/VisemeFile.h)
// use the same rule.
#include <string>
#include <string_view>

namespace vl {

// File-system safe form of a name: letters, digits, '-', '_' and '+' kept, the rest become '_'.
std::string fileSafeName(std::string_view name);

} // namespace vl
