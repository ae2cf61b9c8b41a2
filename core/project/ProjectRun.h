#pragma once
// Turning a project into work: loading the meshes it references and running its reduction, so the
// CLI (`visemelab reduce --project`) and the editor do exactly the same thing.
#include "core/export/Export.h"
#include "core/mesh/VisemeSet.h"
#include "core/project/Project.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/ReduceRun.h"

namespace vl {

// Reads the neutral mesh and every viseme (of an avatar project: the avatar's viseme set, checked
// against the names the project lists) (files resolved against the project's folder, or
// embedded data) and checks interpolability. Errors name the JSON path and the file, e.g.
// "/visemes/3/file (mouth/aa.obj): not interpolable: 1499 vertices (the neutral mesh ... has 1500)".
VisemeSet loadProjectVisemeSet(const Project& project);

// An avatar project's visemes are the avatar's, in its order: throws InputError naming /visemes
// when the avatar file (read with the project's pattern) now yields others.
void checkAvatarVisemeNames(const Project& project, const std::vector<std::string>& avatarVisemes);

// The reduction settings the project holds (weight mode, painted weights, target, constraints, rest
// model and rest viseme).
ReduceSettings projectReduceSettings(const Project& project);

// The project's reduction inputs over its loaded meshes (loadProjectVisemeSet). Throws InputError
// naming the project's JSON paths: fewer than 2 visemes, a target outside 1..n, painted weights of
// another size.
ReduceInputs projectReduceInputs(const Project& project, std::shared_ptr<const VisemeSet> set);

// Runs the reduction of `set` (normally loadProjectVisemeSet(project)) with the project's
// frequencies, weights and target under `policy`. Errors name the project's JSON paths where they can.
ReduceOutcome reduceProject(const Project& project, const VisemeSet& set,
                            const ProgressCallback& progress = {},
                            const ReducePolicy& policy = ReducePolicy::batch());

// The project's reduced model (buildReducedModel): its meshes, frequencies and phoneme map, grouped
// by the stored last result when it matches the viseme count, target and rest model
// (recordedGrouping), else by a fresh reduction with the project's settings under `policy`.
// `unreduced` makes every original viseme its own key instead.
ReducedModel projectReducedModel(const Project& project, bool unreduced = false,
                                 const ReducePolicy& policy = ReducePolicy::batch());
// The same with the project's meshes already loaded (loadProjectVisemeSet).
ReducedModel projectReducedModel(const Project& project, const VisemeSet& set, bool unreduced = false,
                                 const ReducePolicy& policy = ReducePolicy::batch());

// Exports the project's reduced model (projectReducedModel; every viseme its own key with
// `unreduced`) in `format` to `out`: `visemelab export` and the editor's Export.
struct ProjectExport {
    std::size_t keys = 0;                     // key meshes exported
    std::vector<std::filesystem::path> files; // written
};
ProjectExport exportProjectModel(const Project& project, const VisemeSet& set, ExportFormat format,
                                 const std::filesystem::path& out, const ExportOptions& options = {},
                                 bool unreduced = false, const ReducePolicy& policy = ReducePolicy::batch());

// Stores the outcome as the project's last result.
void storeReductionResult(Project& project, const ReduceOutcome& outcome);

} // namespace vl
