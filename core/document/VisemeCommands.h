#pragma once
// Authoring the viseme set (what FaceGen, Blender's "new shape from mix" and XfaceEd let a designer
// do): store the face's sliders as a new or an existing viseme, rename, duplicate, reorder, add a
// rest viseme. Every edit keeps what names a viseme consistent: the direct frequency table, the
// phoneme -> viseme map, the reduction constraints and the face's presets (a viseme and a preset of
// the same name are one viseme: its mesh and its parameters). Painted weights are per vertex and
// stay as they are. Removing a viseme is edit::removeViseme (Commands.h).
#include "core/document/Document.h"

#include <string>
#include <string_view>
#include <vector>

namespace vl::edit {

// Throws InputError at `where` unless `name` can name a new viseme: not empty, no control
// characters, no leading or trailing space, no '+' (merged keys are their members joined by '+'),
// and neither a viseme of the set nor a preset of the face.
void checkNewVisemeName(const Document& document, const std::string& name, std::string_view where);

// Renames viseme `index` everywhere it is named (see above).
Document renameViseme(const Document& document, int index, const std::string& name);
// A copy of viseme `index` named `name`, inserted after it: same mesh and source file, same direct
// frequency, a copy of its preset; no phoneme maps to it and no constraint names it.
Document duplicateViseme(const Document& document, int index, const std::string& name);
// Moves viseme `from` to position `to` (both in 0..n-1); the direct table and the presets follow
// the new order.
Document moveViseme(const Document& document, int from, int to);
// A viseme with the neutral's shape (the mouth at rest), e.g. for the pause "sil" of a phoneme map.
Document addRestViseme(const Document& document, const std::string& name);
// Viseme `index` takes the shape `positions` (a sculpt stroke, core/paint/SculptBrush.h): embedded from
// now on (no longer the file it came from); its name, frequency, phonemes and preset stay (regenerating
// it from the preset would drop the sculpting). Refused for avatars, for a count other than the
// neutral's and for non-finite positions.
Document setVisemeShape(const Document& document, int index, std::vector<Vec3> positions);
// A new viseme `name` mixing others, Blender's "new shape from mix": neutral + sum_i w_i (viseme_i -
// neutral), inserted after the last viseme mixed; frequency 1 in a direct table, no phoneme maps to it.
// Refused for avatars, an empty mix, unknown indices and non-finite weights.
Document addBlendedViseme(const Document& document, const std::string& name,
                          const std::vector<std::pair<int, double>>& mix);

// The face's presets: its own, or the Oculus presets (oculusVisemes()) when it has none.
std::vector<VisemeParameters> facePresets(const FaceModel& face);
// True when the viseme set is the face's own: its neutral has (u,v) and is the face at its default
// parameters there, so a viseme of the face can be generated on the set's mesh.
bool visemeSetMadeByFace(const Document& document);
// For a set the face made: the face's parameter vector of each viseme in set order (its preset's, the
// defaults for one without a preset: sculpted or blended), so that the head's parts (teeth, tongue,
// cavity) can be posed with it; empty when the set is not the face's.
std::vector<std::vector<double>> visemeFaceParameters(const Document& document);
// The face's current slider values as a preset named `name` (values equal to the default omitted).
VisemeParameters presetOfSliders(const FaceModel& face, const std::string& name);

// The sliders become a new preset `name` and, when the set is the face's (visemeSetMadeByFace),
// a new viseme generated on the set's mesh (embedded; direct frequency 1, no phoneme yet).
Document storeSlidersAsNewViseme(const Document& document, const std::string& name);
// The sliders replace the preset `name` (an existing preset or viseme); when the set is the face's
// and has a viseme `name`, its mesh is regenerated (and embedded: it no longer comes from a file).
Document storeSlidersInViseme(const Document& document, const std::string& name);
// Removes the preset `name` (refused while it is the parameters of a viseme of the face's own set:
// remove the viseme instead).
Document removePreset(const Document& document, const std::string& name);

} // namespace vl::edit
