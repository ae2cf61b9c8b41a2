#pragma once
// visemes.json, the viseme parameter file: `visemelab visemes` writes it beside the meshes it
// generates and reads an edited one back with --viseme-file:
// {"visemes": [{"name": "aa", "file": "aa.obj", "parameters": {"jaw_open": 1, ...}}, ...]}
// (other top-level keys are ignored; an entry may also carry "ipa", "example" and "note", which are
// documentation only). Every error names the file and the JSON path.
#include "core/deform/DeformationCascade.h"
#include "core/deform/Visemes.h"

#include <filesystem>
#include <string>
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

// The bundled parameter sets (`visemelab visemes --set NAME`): "oculus", the 15 Oculus visemes
// (oculusVisemes()), and "arpabet", the pause sil and the 39 ARPAbet phonemes with the names of the
// bundled en-us phoneme table (assets/phonemes/arpabet_face.json, read from `assetsDir`).
std::vector<std::string> bundledVisemeSetNames();
std::filesystem::path arpabetVisemeFilePath(const std::filesystem::path& assetsDir);
// Throws InputError at `where` for an unknown name, listing the valid ones.
std::vector<VisemeParameters> bundledVisemeSet(std::string_view name, const std::filesystem::path& assetsDir,
                                               const DeformationCascade& face,
                                               std::string_view where = "--set");

} // namespace vl
