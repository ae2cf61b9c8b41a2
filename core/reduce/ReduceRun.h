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
};

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
    ConstraintNames constraints; // the constraints the run honoured
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
// the constraints allow no grouping), lower_bound_curve, optimal_curve, constraints, frequencies,
// timing_ms, outputs.
std::string reductionReportJson(const ReduceOutcome& outcome, WeightMode mode, const ReduceTimings& timings,
                                const std::vector<std::string>& outputs);

} // namespace vl
