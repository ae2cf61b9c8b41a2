#pragma once
// A VisemeLab project: everything a designer edits, saved as one JSON document ("format":
// "visemelab-project", "version": the file format's version, kProjectVersion; docs/project-format.md
// describes every field). Versions number the file format only; what counts a document's changes is
// a revision (core/document/DocumentInputs.h).
// The state is plain data from the core modules; this module only reads, validates and writes it.
#include "core/adaptive/Criteria.h"
#include "core/deform/DeformationCascade.h"
#include "core/deform/Visemes.h"
#include "core/mesh/Mesh.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReduceRun.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/Weights.h"
#include "core/speech/SpeechSettings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl {

// The newest version this VisemeLab reads and writes; newer versions are refused. Version 2 only adds
// /deformation/domain, version 3 the reduction's rest model (/reduction/rest, restViseme, resting
// visemes), version 4 an avatar's added rest viseme (/avatar/addedRest): a project without them is
// still written as the lowest version that holds it, so VisemeLabs that read it keep opening it.
constexpr int kProjectVersion = 5;
constexpr int kOldestProjectVersion = 0; // older versions load through a migration
inline constexpr const char* kProjectFormat = "visemelab-project";

// The neutral mesh: a file (relative to the project file's folder, or absolute) or embedded data.
struct ProjectNeutral {
    std::filesystem::path file; // empty when embedded
    MeshData embedded;          // used when file is empty; no positions = the project has no neutral yet
    bool isEmbedded() const { return file.empty() && !embedded.positions.empty(); }
    bool isSet() const { return !file.empty() || !embedded.positions.empty(); }
    bool operator==(const ProjectNeutral&) const = default;
};

// A viseme: a name plus a file, or embedded positions (it shares the neutral's topology and (u,v)).
struct ProjectViseme {
    std::string name;
    std::filesystem::path file;  // empty when embedded
    std::vector<Vec3> positions; // used when file is empty
    bool isEmbedded() const { return file.empty(); }
    bool operator==(const ProjectViseme&) const = default;
};

struct ProjectWeights {
    WeightMode mode = WeightMode::Uniform;
    std::vector<double> painted; // one per vertex; kept when another mode is selected
    bool operator==(const ProjectWeights&) const = default;
};

// The rest model new projects start with (`project new`, the editor's New, avatars): rest-free when
// the set has a rest viseme. A file without /reduction/rest ran the keyed model and keeps it.
inline constexpr RestChoice kNewProjectRest = RestChoice::Auto;

struct ProjectReduction {
    int target = 1;                        // m, in 1..n
    ConstraintNames constraints;           // pins, apart and together pairs by viseme name
    RestChoice rest = RestChoice::Key;     // what files without "rest" (versions 0..2) ran
    std::string restViseme;                // a viseme's name; empty: sil or viseme_sil when present
    std::optional<ReductionResult> result; // the last run (groups ordered and canonical), if any
    bool operator==(const ProjectReduction&) const = default;
};

// The deformable face (paper "Adaptive Deformable Models"): its cascade of fields, the current
// slider values, and visemes as named parameter vectors. No stages = the project has no face model.
struct ProjectDeformation {
    DeformationCascade cascade;
    std::vector<double> values;            // one per cascade parameter (empty when there is no cascade)
    std::vector<VisemeParameters> visemes; // parameters not listed keep their default
    // The (u,v) mesh the face is shown and its visemes are generated on: a refined mesh, or the one
    // `face build` made. Positions are (u, v, 0). Empty = the editor's default face domain mesh.
    MeshData domain;

    bool isSet() const { return !cascade.stages.empty(); }
    bool operator==(const ProjectDeformation&) const = default;
};

// Cheap editor state that is worth restoring when a project is reopened.
struct ProjectEditorState {
    std::string selectedViseme; // empty = none
    bool operator==(const ProjectEditorState&) const = default;
};

// An avatar the viseme meshes come from (the editor's File > Import avatar...): the neutral and every
// viseme are read from the file (core/gltf/AvatarScan.h); the project's visemes only name them, in
// the avatar's order.
struct ProjectAvatar {
    std::filesystem::path file; // relative to the project file's folder, or absolute; empty = none
    std::string targets;        // glob selecting the viseme targets; empty = the Oculus visemes
    // The rest viseme added after the avatar's (sil / viseme_sil, the neutral's shape, no target:
    // core/gltf/AvatarRest.h); empty = none. Version 4.
    std::string addedRest{};
    bool isSet() const { return !file.empty(); }
    bool operator==(const ProjectAvatar&) const = default;
};

struct Project {
    // The project file this state belongs to. Not stored in the file; relative mesh paths resolve
    // against its folder. Empty for a project that has never been saved.
    std::filesystem::path path;

    ProjectNeutral neutral;
    std::vector<ProjectViseme> visemes;
    FrequencySource frequencies; // direct viseme frequencies, or phoneme table + phoneme->viseme map
    ProjectWeights weights;
    ProjectDeformation deformation;
    CriterionSettings refinement; // adaptive mesh: criterion and the thresholds of every criterion
    ProjectReduction reduction;
    SpeechSettings speech; // what the editor's Say speaks; the file's "speech" section (optional)
    ProjectEditorState editor;
    ProjectAvatar avatar; // set: neutral is unset and every viseme has only its name

    int findViseme(std::string_view name) const; // index or -1
    // Every field, compared exactly (doubles by value: NaN is never equal); where a table was read
    // from (Provenance) is not part of the value.
    bool operator==(const Project&) const = default;
};

// The version saveProject writes: the lowest that holds the project (2 only with a face (u,v) mesh,
// /deformation/domain; 3 with the rest model; 4 with an avatar's added rest viseme).
int projectVersionFor(const Project& project);

// Reads, migrates (older versions) and validates a project file. Every problem is an InputError
// "<file>: <JSON path>: <what>", e.g. "p.vlproj: /visemes/3/file: file not found (…/aa.obj)".
// Referenced mesh files must exist; their contents are read by loadProjectVisemeSet.
Project loadProject(const std::filesystem::path& file);

// Validates the project (the same checks as loading, except that mesh files need not exist) and
// writes it atomically: on any error the previous file is left untouched. Mesh paths are written
// relative to `file` (see rebaseProject).
void saveProject(const std::filesystem::path& file, const Project& project);

// The project as the JSON text saveProject writes (after validation).
std::string projectToJsonText(const Project& project);

// Parses and validates project JSON text as if it were the file `projectFile` (relative mesh paths
// resolve against its folder); `checkFiles` verifies that referenced mesh files exist.
Project projectFromJsonText(std::string_view text, const std::filesystem::path& projectFile,
                            bool checkFiles = true);

// The same project with path = newFile and every mesh path (relative to project.path's folder or
// absolute) rewritten relative to the folder of `newFile`, pointing to the same files.
Project rebaseProject(const Project& project, const std::filesystem::path& newFile);

// How a project saved as `projectFile` refers to `file`: relative to the project's folder when both
// are on the same root (e.g. "meshes/aa.obj", "../shared/aa.obj"), otherwise absolute.
std::filesystem::path projectRelativePath(const std::filesystem::path& projectFile,
                                          const std::filesystem::path& file);

// Absolute (or working-directory-relative) location of a mesh file the project references.
std::filesystem::path resolveProjectFile(const Project& project, const std::filesystem::path& file);

} // namespace vl
