#pragma once
// visemes.json, the viseme parameter file: `visemelab visemes` writes it beside the meshes it
// generates and reads an edited one back with --viseme-file:
// {"visemes": [{"name": "aa", "file": "aa.obj", "parameters": {"jaw_open": 1, ...}}, ...]}
// (other top-level keys are ignored). Every error names the file and the JSON path.
#include "core/deform/DeformationCascade.h"
#include "core/deform/Visemes.h"

#include <filesystem>
#include <string_view>
#include <vector>

namespace vl {

// The visemes of a viseme parameter file for the parameters of `face`. Names must be usable as file
// names (<name>.obj: letters, digits, '-', '_', '+'; not "neutral") and unique; parameters must be
// parameters of `face`, with values inside their range. Throws InputError naming `source`.
std::vector<VisemeParameters> parseVisemeFile(std::string_view text, std::string_view source,
                                              const DeformationCascade& face);
std::vector<VisemeParameters> readVisemeFile(const std::filesystem::path& path,
                                             const DeformationCascade& face);

} // namespace vl
