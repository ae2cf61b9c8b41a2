#pragma once
// Edits of a Document as validated functions: each takes the current document and returns the
// edited one, or throws InputError naming what is wrong and leaves nothing changed. The editor
// commits the result as one undo step; tests and scripts call them directly.
#include "core/document/Document.h"
#include "core/document/OwnFace.h"
#include "core/face/FaceBuild.h"

#include <string>
#include <vector>

namespace vl::edit {

// --- viseme set -------------------------------------------------------------------------------
// Adds a viseme (interpolable with the neutral, a new non-empty name); `file` is where it came
// from (empty = embedded). Direct frequency tables get the new name with frequency 1.
Document addViseme(const Document& document, const std::string& name, const MeshData& mesh,
                   const std::filesystem::path& file);
// Removes viseme `index` (at least 2 stay); its direct frequency, the constraints and the face
// preset that name it go, the target is clamped. Phonemes mapped to it move to `phonemesGoTo`;
// without one, a removal that would leave phonemes unmapped is refused and lists them.
Document removeViseme(const Document& document, int index, const std::string& phonemesGoTo = {});

// --- frequencies ------------------------------------------------------------------------------
Document setVisemeFrequency(const Document& document, int viseme, double value); // direct tables only
Document setPhonemeFrequency(const Document& document, int phoneme, double value);
Document setPhonemeViseme(const Document& document, int phoneme, const std::string& viseme);
Document setFrequencies(const Document& document, FrequencySource source);

// --- weights ----------------------------------------------------------------------------------
// Painted mode starts from the weights shown before (weightsForPainting) unless weights were
// painted already.
Document setWeightMode(const Document& document, WeightMode mode);
Document setPaintedWeights(const Document& document, std::vector<double> painted); // mode becomes painted

// --- deformable face --------------------------------------------------------------------------
Document setFace(const Document& document, FaceModel face);
Document setParameter(const Document& document, int parameter, double value);
Document setParameters(const Document& document, std::vector<double> values);
Document applyVisemePreset(const Document& document, const std::string& viseme); // face.presets or Oculus
Document setInfluence(const Document& document, int stage, int influence, const InfluenceField& field);
// The same fields on another individual's base geometry (the paper's retargeting).
Document retarget(const Document& document, face::Individual individual);
// The face's display mesh (e.g. a refined (u,v) mesh); the visemes are not regenerated.
Document setFaceDomain(const Document& document, std::shared_ptr<const MeshData> domain);
// The face's visemes generated on its (u,v) mesh become the viseme set (embedded meshes); the
// frequency table, weight mode and target are kept when they still fit. A document without a viseme
// set before takes `phonemeTable` (e.g. the bundled en-us table with the Oculus map) when its map
// names only visemes of the new set, else equal frequencies.
Document generateVisemesFromFace(const Document& document, const FrequencySource* phonemeTable = nullptr);

// --- refinement and reduction -----------------------------------------------------------------
Document setRefinementSettings(const Document& document, const CriterionSettings& settings);
Document setTarget(const Document& document, int m);
// Pins, apart and together pairs by viseme name (checked: known names, no contradictions).
Document setConstraints(const Document& document, ConstraintNames constraints);
// The reduction model (free rest or the rest as a key) and the rest viseme (a viseme's name, or empty
// for sil / viseme_sil); InputError naming the rest viseme when the set has no such viseme. The
// target is clamped to the keys the model allows (documentMaxKeys).
Document setRest(const Document& document, RestChoice rest, const std::string& restViseme);

// --- speech ------------------------------------------------------------------------------------
// What the Say panel speaks (checkSpeechSettings; whether espeak-ng knows the voice is checked when
// it speaks).
Document setSpeech(const Document& document, SpeechSettings speech);
// --- avatar (core/document/AvatarDocument.h) -----------------------------------------------------
// The avatar's visemes selected by another target pattern (empty: the Oculus visemes), from the
// avatar in memory. Frequencies, painted weights, constraints and the target are kept where they
// still fit the new set; otherwise the defaults of documentFromAvatar (with `oculusTable`) apply.
// Refused (InputError naming the pattern) when it selects fewer than 2 visemes.
// The viseme set of an avatar document is the avatar's: addViseme and removeViseme refuse it, and
// setFrequencies reads viseme names by meaning (a table naming "aa" applies to "viseme_aa").
Document setAvatarPattern(const Document& document, const std::string& pattern,
                          const FrequencySource& oculusTable);
// An avatar whose visemes lack a rest viseme gains one (core/gltf/AvatarRest.h): "viseme_sil" when its
// visemes use that prefix, else "sil", with the base mesh's shape and no target. Frequencies still
// at the avatar's defaults become the defaults with it (an Oculus avatar: `oculusTable`, whose pause
// maps to it); a phoneme map of the designer's sends the silence phoneme to it; a direct table gives
// it frequency 1. A `name` given (one of kRestVisemeNames) replaces that choice. Refused (InputError)
// without an avatar, when the visemes have a rest viseme, or for another name.
Document addAvatarRestViseme(const Document& document, const FrequencySource& oculusTable,
                             const std::string& name = {});
// --- own face (issue 15) ------------------------------------------------------------------------
// The face built from the user's mesh and confirmed landmarks (face::buildFace) replaces the
// document's face: the bundled fields carried over to it, parameters at their defaults, presets and
// display mesh kept; the contour criterion's thresholds scale with the face's size (a face in metres
// gets thresholds in metres). Throws InputError naming the file and the missing landmarks, or what
// the build refuses. `report`, when given, receives what the build found (islands, holes, scale).
// The result closes the own-face step (Document::ownFace).
Document useOwnFace(const Document& document, const OwnFaceCandidate& candidate,
                    face::FaceBuildReport* report = nullptr);
// The own-face step: opened on a candidate (its mesh read, its landmarks suggested), one landmark
// placed at a (u,v) of the mesh's texture space (placeLandmark: InputError when it lies on no
// triangle, or when no step is open), closed without building.
Document beginOwnFace(const Document& document, OwnFaceCandidate candidate);
Document placeOwnFaceLandmark(const Document& document, face::Landmark landmark, const Vec2& uv);
Document cancelOwnFace(const Document& document);

} // namespace vl::edit
