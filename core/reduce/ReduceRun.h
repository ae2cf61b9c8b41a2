#pragma once
// One reduction run from user-level inputs (viseme set, frequencies, weight mode, target) to the
// merged meshes and the files the CLI and the editor write. Shared so both behave identically.
#include "core/common/OutputSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/VisemeSet.h"
#include "core/reduce/Weights.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

struct ReduceSettings {
    WeightMode weightMode = WeightMode::Uniform;
    std::vector<double> paintedWeights; // used when weightMode == Painted
    int target = 1;
    std::string paintedWeightsSource = "weights";  // the weights' file or JSON path, for messages
    ConstraintNames constraints{};                 // by viseme name
    std::string constraintsSource = "constraints"; // where errors about them point (a flag, a JSON path)
    ReductionOptions options{};                    // solver, time limit
    // Phoneme -> viseme maps whose grouping of the set's visemes (named by phoneme) is costed under
    // the same objective, to compare with the optimum (e.g. the standard Oculus, MPEG-4, Rhubarb maps).
    std::vector<PhonemeVisemeMap> compareMaps{};
};

// A map used as a grouping: the set's visemes the map sends to the same viseme share a group.
struct MapGrouping {
    std::string source;                   // the map's origin (file)
    std::vector<std::string> labels;      // the map's viseme of each group
    std::vector<std::vector<int>> groups; // member indices, each ascending, ordered by first member
    double cost = 0;                      // rho_f under the run's frequencies and weights
};

// The grouping of `visemeNames` by `map`. Every viseme must be a phoneme of the map (InputError at the
// map's origin listing all that are not); map entries for phonemes the set does not have are ignored.
MapGrouping groupingFromMap(const std::vector<std::string>& visemeNames, const PhonemeVisemeMap& map);

struct ReducedViseme {
    std::string name;                 // member names joined by '+', e.g. "FF+TH"
    std::vector<std::string> members; // original viseme names
    double frequency = 0;             // sum of the members' normalised frequencies
    std::vector<Vec3> positions;      // the frequency-weighted mean of the members
};

struct ReduceOutcome {
    std::vector<std::string> visemeNames;
    std::vector<double> frequencies; // normalised, one per original viseme
    std::vector<double> weights;     // one per vertex
    ReductionResult result;
    std::vector<ReducedViseme> reduced; // for the chosen target m
    // phoneme -> reduced index (empty when frequencies were given per viseme).
    std::vector<std::pair<std::string, int>> phonemeToReduced;
    ConstraintNames constraints;             // the constraints the run honoured
    std::vector<MapGrouping> comparedMaps{}; // settings.compareMaps, costed
};

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress = {});

struct ReduceTimings {
    double loadMs = 0, reduceMs = 0, writeMs = 0;
};

// Stages in `outputs` (an OutputSet of the output folder; the caller commits it, with the report):
// reduced_<i>_<name>.obj and .wrl per merged mesh and mapping.json (each original viseme and phoneme
// -> reduced index). Returns the staged file names (relative to the folder).
std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const VisemeSet& set,
                                               const ReduceOutcome& outcome);

// The JSON report: n, m, weights, method, optimal, cost, lower_bound, gap, groups, cost_curve (null where
// the constraints allow no grouping), lower_bound_curve, optimal_curve, groups_curve (every p's groups by
// name, null as cost_curve), constraints, frequencies,
// timing_ms, outputs, and compared_maps when maps were compared (each map's groups, cost, and the
// optimum for as many groups when p <= m).
std::string reductionReportJson(const ReduceOutcome& outcome, WeightMode mode, const ReduceTimings& timings,
                                const std::vector<std::string>& outputs);

} // namespace vl
