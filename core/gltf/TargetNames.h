#pragma once
// Morph-target names as avatar tools write them, and how VisemeLab picks the visemes among them.
//
// - Names come from mesh.extras.targetNames (the convention of Blender, three.js and Ready Player
//   Me), else from the first primitive's extras.targetNames (UniVRM / VRoid write them there).
// - A glob pattern (`*`, `?`, `[AIUEO]`, `[a-z]`, `[!...]`) selects targets by name, compared
//   without regard to ASCII case.
// - Without a pattern, the Oculus / OVRLipSync visemes are selected: sil PP FF TH DD kk CH SS nn
//   RR aa E ih oh ou, with or without the "viseme_" prefix, any case, and the Ready Player Me /
//   TalkingHead spellings I, O, U of ih, oh, ou.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

class GltfDocument;

// The 15 Oculus viseme names in their canonical order and spelling (assets/phonemes/map_oculus.csv).
const std::vector<std::string>& oculusVisemeNames();

// The canonical Oculus name a target name stands for ("viseme_I" -> "ih", "AA" -> "aa"), if any.
std::optional<std::string> oculusVisemeOf(std::string_view targetName);

// Throws InputError naming `where` for an unterminated '[' class or an empty pattern.
void checkGlobPattern(std::string_view pattern, std::string_view where);
// Glob match of the whole name, ASCII case-insensitive.
bool globMatch(std::string_view pattern, std::string_view name);

struct TargetName {
    std::string name; // "target<k>" when the file has none
    bool named = false;
};

// The names of mesh `mesh`'s morph targets (one per target of its first primitive).
std::vector<TargetName> meshTargetNames(const GltfDocument& doc, int mesh);

} // namespace vl
