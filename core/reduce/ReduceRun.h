#pragma once
// One reduction run from user-level inputs (viseme set, frequencies, weight mode, target) to the
// reduced model (buildReducedModel). Shared by the CLI, projects and avatars so all behave
// identically; its files and report are written by core/export/ReductionOutputs.h.
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/VisemeSet.h"
#include "core/reduce/Weights.h"

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

struct ReduceOutcome {
    std::vector<std::string> visemeNames;
    std::vector<double> frequencies; // normalised, one per original viseme
    std::vector<double> weights;     // one per vertex
    ReductionResult result;
    // The merged keys of the best grouping for the target m and the phoneme -> key map
    // (buildReducedModel: map entries naming a viseme the set lacks are an error).
    ReducedModel model;
    ConstraintNames constraints; // the constraints the run honoured
};

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress = {});

} // namespace vl
