#pragma once
// The files of one reduction run (`visemelab reduce`, `visemelab avatar reduce`): the merged key
// meshes, mapping.json and the JSON report. core/reduce computes the run (ReduceRun.h), core/gltf
// an avatar's (AvatarReduce.h); writing them lives here with the other writers of reduced models.
#include "core/common/OutputSet.h"
#include "core/gltf/AvatarReduce.h"
#include "core/reduce/ReduceRun.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct ReduceTimings {
    double loadMs = 0, reduceMs = 0, writeMs = 0;
};

// Which files each key mesh gets: OBJ and VRML text (XfaceEd, Blender) and/or binary PLY (float32
// positions: 12 bytes a vertex, no formatting; for large meshes, docs/performance.md issue 33).
struct KeyMeshFormats {
    bool obj = true, wrl = true, ply = false;
};
// Above this many vertices `reduce --format auto` writes binary PLY only: the text pair costs about
// 60 bytes and two float formattings a vertex per key.
inline constexpr std::size_t kBinaryKeyMeshVertices = 200'000;
// "obj+wrl", "obj", "wrl", "ply", or "auto" (obj+wrl up to kBinaryKeyMeshVertices vertices, ply above);
// nothing for any other text.
std::optional<KeyMeshFormats> keyMeshFormatsFromString(std::string_view text, std::size_t vertexCount);

// Stages in `outputs` (an OutputSet of the output folder; the caller commits it, with the report):
// reduced_<k>_<name>.obj / .wrl / .ply per key of the outcome's model as `formats` asks
// (core/export/KeyMeshFiles.h names) and mapping.json (core/export/MappingJson.h, each key's "obj",
// "wrl" and "ply" as written). Returns the staged file names (relative to the folder).
std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const ReduceOutcome& outcome,
                                               KeyMeshFormats formats = {});
// The same for an outcome of runReduction(set, ..., KeyPositions::Deferred): each key is merged from
// `set` (mergeKeyInto) into one float32 buffer as it is written, so no key is held as doubles; the
// bytes equal those of the merged model's PLY. Binary PLY only (formats.ply; obj or wrl throw).
std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const ReduceOutcome& outcome,
                                               KeyMeshFormats formats, const SetShapes& set);

// How far one viseme moves after the reduction (the largest vertex displacement from the neutral,
// in mm for a glTF avatar in metres), against before: its key's shape, or nothing when it rests.
struct VisemeMotion {
    std::string viseme;
    std::string key; // "" when it rests
    double beforeMm = 0, afterMm = 0;
};
std::vector<VisemeMotion> visemeMotions(const VisemeSet& set, const ReduceOutcome& outcome);
// "viseme_sil moves 0 mm (rests)", "viseme_PP moves 4.8 of 6.5 mm (key viseme_PP+viseme_sil)".
std::string formatVisemeMotion(const VisemeMotion& motion);

// "Max error 2 mm: 6 keys is the fewest that keep every viseme within it (proved); the grouping is the
// optimum among those (proved)".
std::string maxErrorSummary(const MaxErrorFinding& finding);
// One line per viseme: its largest and RMS vertex error after the reduction, in mm when the set's unit
// is known (else model units), and the largest as a percentage of its own largest displacement.
std::string visemeErrorTable(const ReduceOutcome& outcome);

// One line on the reduction model that ran: "Rest: free (...); resting: sil, ..." or "Rest: key (...)".
std::string restSummary(const ReduceOutcome& outcome);

// The JSON report: n, m, weights, method, optimal, cost, lower_bound, gap, groups, rest (model "free" or
// "key", viseme: the rest viseme or null, resting: the resting visemes of the best grouping), cost_curve
// (null where the constraints allow no grouping), lower_bound_curve, optimal_curve, groups_curve (every p's
// groups by name, null as cost_curve), rest_curve (every p's resting visemes, with a free rest), constraints,
// frequencies, timing_ms, outputs, and compared_maps when maps were compared (each map's groups, cost, and
// the optimum for as many groups when p <= m), viseme_errors (per viseme: max and RMS error, unit "mm" or
// "model units", percent of its own largest displacement) and max_error with --max-error-mm.
std::string reductionReportJson(const ReduceOutcome& outcome, WeightMode mode, const ReduceTimings& timings,
                                const std::vector<std::string>& outputs);

// The report of `visemelab avatar reduce`: the keys of `visemelab reduce` (n, m, weights, cost, groups,
// cost_curve, frequencies, timing_ms, outputs, and whatever the reduction adds) plus "avatar" (input, output,
// names, target_normals, notes, sizes), "meshes" (the meshes touched: targets before/after, keys) and "scan"
// (core/gltf/AvatarReport), and "viseme_motion" (visemeMotions: viseme, key or null when it rests, before_mm,
// after_mm).
std::string avatarReductionReport(const AvatarReduction& reduction, const AvatarScan& scan,
                                  const ReduceSettings& settings, const AvatarWriteOptions& write,
                                  const ReduceTimings& timings, const std::string& input,
                                  const std::string& output);

} // namespace vl
