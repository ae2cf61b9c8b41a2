#include "core/reduce/ReduceRun.h"

namespace vl {

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress) {
    ReduceOutcome out;
    for (const auto& v : set.visemes) out.visemeNames.push_back(v.name);
    out.frequencies = visemeFrequencies(frequencies, out.visemeNames);
    out.weights = computeWeights(settings.weightMode, set.neutral, settings.paintedWeights,
                                 settings.paintedWeightsSource);
    requireKnownVisemes(set, frequencies); // before the reduction, not after it

    std::vector<std::span<const Vec3>> rows; // a view of the set's positions: no copy of the shapes
    for (const auto& v : set.visemes) rows.emplace_back(v.positions);
    const ShapeView shapes(rows);
    const ReductionConstraints constraints =
        resolveConstraints(settings.constraints, out.visemeNames, settings.constraintsSource);
    // Contradictions and a target they rule out are reported by viseme name, at the constraints' source.
    const ConstraintUnits units = constraintUnits(constraints, static_cast<int>(set.size()), out.visemeNames,
                                                  settings.constraintsSource);
    if (settings.target >= 1 && static_cast<std::size_t>(settings.target) <= set.size() &&
        !units.feasible(settings.target))
        throwInfeasibleTarget(units, settings.target, settings.constraintsSource);
    out.result = reduceVisemes({shapes, out.frequencies, out.weights, settings.target, constraints},
                               settings.options, progress);
    out.constraints = settings.constraints;

    out.model = buildReducedModel(set, out.frequencies, out.result.groupOf(), frequencies);
    return out;
}

} // namespace vl
