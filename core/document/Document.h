#pragma once
// The editor's document: everything a designer edits, as one immutable value. Every edit makes a
// new Document (core/document/Commands.h); the heavy parts (meshes, painted weights, the face's
// cascade and (u,v) mesh, preview colours) are shared immutable pointers, so an undo step costs
// what changed and two documents compare equal part by part in O(parts), shared parts by identity.
//
// A Project (core/project) is the file form of a document: documentFromProject loads the meshes it
// names, projectFromDocument writes what the document holds (embedded geometry from memory, never
// re-read from disk). What is derived from a document (the weights and frequencies of
// DocumentInputs, the reduction curve, the adaptive mesh a refinement works on, GPU samples) lives in
// the services that compute it, keyed by the document's inputs. A refined (u,v) mesh the designer
// adopts is not derived data: edit::setFaceDomain makes it the face's mesh (FaceModel::domain), the
// project saves it (ProjectDeformation::domain) and the visemes are generated on it.
#include "core/adaptive/Criteria.h"
#include "core/deform/DeformationCascade.h"
#include "core/deform/Visemes.h"
#include "core/document/DocumentAvatar.h"
#include "core/document/OwnFace.h"
#include "core/face/BundledFace.h"
#include "core/mesh/VisemeSet.h"
#include "core/project/Project.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/ReductionConstraints.h"
#include "core/reduce/Weights.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl {

// (u,v) mesh resolution of a face model's display and viseme mesh (cells per side).
inline constexpr int kFaceDomainResolution = 40;

// The deformable face (paper "Adaptive Deformable Models"): the cascade of fields, the (u,v) mesh
// it is shown and refined on, the current slider values and the visemes as parameter vectors.
struct FaceModel {
    std::shared_ptr<const DeformationCascade> cascade; // null = the document has no face
    face::Individual individual = face::Individual::Bundled;
    // The (u,v) triangulation the face is shown and its visemes are generated on (positions unused):
    // the default grid, the one `face build` made, or an adopted refined mesh; saved with the project.
    std::shared_ptr<const MeshData> domain;
    std::vector<double> parameters;        // one value per cascade parameter
    std::vector<VisemeParameters> presets; // empty = the Oculus presets (oculusVisemes())

    bool operator==(const FaceModel&) const = default;
};

struct DocumentWeights {
    WeightMode mode = WeightMode::Uniform;
    std::shared_ptr<const std::vector<double>> painted; // one per vertex, or null; kept in other modes

    const std::vector<double>& paintedOrEmpty() const;
    bool operator==(const DocumentWeights&) const = default;
};

struct Document {
    // The viseme set (null until one is loaded) and where each of its meshes comes from: an
    // absolute file path, or empty when the geometry exists only here (generated, imported from
    // glTF, or embedded in the project file), in which case a save embeds it.
    std::shared_ptr<const VisemeSet> visemes;
    std::filesystem::path neutralFile;
    std::vector<std::filesystem::path> visemeFiles; // one per viseme
    // Per-vertex preview colours (lips, eyes, brows) when the visemes lie in the face's (u,v) space.
    std::shared_ptr<const std::vector<Vec3>> visemeColours;

    FrequencySource frequencies; // direct viseme frequencies, or phoneme table + phoneme -> viseme map
    DocumentWeights weights;
    FaceModel face;
    CriterionSettings refinement;
    int target = 1;              // m, the number of merged visemes the reduction keeps
    ConstraintNames constraints; // pins, apart and together pairs, by viseme name
    // The reduction model: new documents are rest-free when the set has a rest viseme; an opened
    // project keeps the model its file records (keyed for files older than version 3).
    RestChoice rest = kNewProjectRest;
    std::string restViseme; // a viseme's name; empty: sil or viseme_sil when the set has one
    SpeechSettings speech;  // what the Say panel speaks (text, voice, rate)
    // Set when the viseme set was read from an avatar (core/document/AvatarDocument.h): the set is
    // the avatar's visemes over the concatenated world-space geometry of the meshes carrying them.
    DocumentAvatar avatar;
    // The own-face step under way (Deformation > Use my mesh...): the user's mesh and its landmarks
    // awaiting confirmation, edited by undoable commands (edit::placeOwnFaceLandmark) so that the
    // numeric fields and the dots in the 3D view read the same landmarks; null when no step is open.
    // Not saved: a project records the face built from it.
    std::shared_ptr<const OwnFaceCandidate> ownFace;

    std::size_t visemeCount() const { return visemes ? visemes->size() : 0; }
    bool operator==(const Document&) const = default;
};

// The inputs of the reduction (meshes, frequencies, weights, constraints): documents with equal
// inputs share one reduction curve, whatever else differs.
bool sameReductionInputs(const Document& a, const Document& b);

// Viseme names in set order (empty without a set).
std::vector<std::string> visemeNames(const Document& document);

// The parts of a document an edit can change. Validation and derived data (DocumentInputs) are
// tagged with what changed and re-evaluate only what depends on it, as Blender's depsgraph does: a
// slider tick changes only FaceParameters and validates only the parameter values.
enum DocumentPart : unsigned {
    kVisemePart = 1u << 0,        // the set, its mesh sources and preview colours, the avatar
    kFrequencyPart = 1u << 1,     // the frequency table and phoneme map
    kWeightPart = 1u << 2,        // weight mode and painted weights
    kFaceParameterPart = 1u << 3, // the face's slider values
    kFacePart = 1u << 4,          // the face's cascade, individual and presets
    kReductionPart = 1u << 5,     // constraints, rest model and rest viseme (the curve's settings)
    kTargetPart = 1u << 6,        // m: which grouping of the curve, not the curve
    kOtherPart = 1u << 7,         // refinement thresholds, speech settings, the own-face step
    kFaceMeshPart = 1u << 8,      // the face's (u,v) display mesh (a refinement changes only it)
    kAllDocumentParts = (1u << 9) - 1,
};
using DocumentParts = unsigned;

// The parts in which `after` differs from `before` (shared parts compared by identity).
DocumentParts changedParts(const Document& before, const Document& after);

// Checks what the reduction needs (frequencies resolve for every viseme, weights valid); throws
// InputError naming the culprit. Every command runs it, so no edit can break the reduction.
// `changed` limits the checks to those that depend on the changed parts (the others held before).
void validateDocument(const Document& document, DocumentParts changed = kAllDocumentParts);
// How many validations so far checked the reduction's inputs (frequencies, weights, constraints,
// target): the document-wide part a slider tick must not run (tests count it).
std::uint64_t reductionInputValidations();

// The per-vertex weights of the metric (throws InputError when invalid; empty without a set).
std::vector<double> documentWeights(const Document& document);

// Normalised frequency of every viseme (throws InputError when the table does not resolve).
std::vector<double> documentFrequencies(const Document& document);

// The rest pose the document's reduction runs with (Reduction.h): free or keyed, its rest viseme
// (document.restViseme, else sil / viseme_sil, else none) and the set's neutral (a view into
// document.visemes, valid while it lives). Throws InputError when restViseme names no viseme.
RestPose documentRestPose(const Document& document);
// The most keys a reduction of the document can have: the viseme count, one less when the rest
// viseme rests (rest-free model), fewer when the constraints allow fewer groups.
int documentMaxKeys(const Document& document);

// A loaded project: the document, plus what the file held that is not document state.
struct LoadedProject {
    Document document;
    std::optional<ReductionResult> reduction; // the last result the file recorded, if any
    std::string selectedViseme;               // editor state the file restores
};

// Reads the meshes a (validated) project names, builds its face model, and checks the result
// (InputError naming the JSON path and file). Mesh paths become absolute.
LoadedProject documentFromProject(const Project& project);

// The project a save writes: mesh paths absolute (saveProject makes them relative to its file),
// embedded geometry taken from the document, the face model's cascade, values and presets.
Project projectFromDocument(const Document& document, const std::optional<ReductionResult>& reduction = {},
                            const std::string& selectedViseme = {});

// The form a face's (u,v) mesh is saved in (ProjectDeformation::domain): (u,v) and triangles with
// positions (u, v, 0); empty when it is the default mesh (kFaceDomainResolution, mouth density), which
// loading regenerates.
MeshData storedFaceDomain(const MeshData& domain);

// A fresh face model of the given individual on its (u,v) display mesh.
FaceModel makeFaceModel(face::Individual individual, int resolution = kFaceDomainResolution);

} // namespace vl
