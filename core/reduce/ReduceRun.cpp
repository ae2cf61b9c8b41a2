#include "core/reduce/ReduceRun.h"

#include "core/reduce/MaxErrorSearch.h"

#include "core/common/Error.h"

#include <algorithm>

namespace vl {

MapGrouping groupingFromMap(const std::vector<std::string>& visemeNames, const PhonemeVisemeMap& map) {
    MapGrouping out;
    out.source = map.origin.text.empty() ? "map" : map.origin.text;
    std::string unmapped;
    for (std::size_t i = 0; i < visemeNames.size(); ++i) {
        const std::string* label = map.visemeOf(visemeNames[i]);
        if (!label) {
            unmapped += (unmapped.empty() ? "" : ", ") + visemeNames[i];
            continue;
        }
        const auto it = std::find(out.labels.begin(), out.labels.end(), *label);
        if (it == out.labels.end()) {
            out.labels.push_back(*label);
            out.groups.push_back({static_cast<int>(i)});
        } else {
            out.groups[static_cast<std::size_t>(it - out.labels.begin())].push_back(static_cast<int>(i));
        }
    }
    if (!unmapped.empty())
        throwInputError(out.source, "used as a grouping, it does not map these visemes: " + unmapped);
    return out;
}

int restVisemeIndex(const std::vector<std::string>& names, const std::string& named, std::string_view where) {
    const auto indexOf = [&](std::string_view name) {
        const auto it = std::find(names.begin(), names.end(), name);
        return it == names.end() ? -1 : static_cast<int>(it - names.begin());
    };
    if (!named.empty()) {
        const int index = indexOf(named);
        if (index < 0) throwInputError(where, "the set has no viseme '" + named + "'");
        return index;
    }
    for (const char* name : kRestVisemeNames)
        if (const int index = indexOf(name); index >= 0) return index;
    return -1;
}

bool restIsFree(RestChoice choice, int restViseme) {
    return choice == RestChoice::Free || (choice == RestChoice::Auto && restViseme >= 0);
}

namespace {

// The index of the lips-closed viseme settings.closure names (-1: no rule, or auto and none in the set).
int closureVisemeOf(const SetShapes& set, const ReduceSettings& settings) {
    if (settings.closure.empty()) return -1;
    if (settings.closure != kClosureAuto) {
        const int index = set.find(settings.closure);
        if (index < 0) throwInputError("--closure", "the set has no viseme '" + settings.closure + "'");
        return index;
    }
    for (const char* name : kClosureVisemeNames)
        if (const int index = set.find(name); index >= 0) return index;
    return -1;
}

bool mentions(const std::vector<std::pair<std::string, std::string>>& pairs, const std::string& name) {
    for (const auto& [a, b] : pairs)
        if (a == name || b == name) return true;
    return false;
}

// settings.constraints plus the closure pin (ReduceSettings::closure) when the rest is free and the
// designer left the closure viseme unconstrained; sets out.closureViseme or out.closureNote.
ConstraintNames constraintsWithClosure(const SetShapes& set, const ReduceSettings& settings, bool restFree,
                                       int restViseme, ReduceOutcome& out) {
    ConstraintNames names = settings.constraints;
    const int closure = closureVisemeOf(set, settings);
    if (closure < 0) return names;
    const std::string& name = set.names[static_cast<std::size_t>(closure)];
    const std::string leftAlone = ": " + name + " is left to the optimiser";
    if (!restFree)
        out.closureNote = "the rest is a key" + leftAlone;
    else if (closure == restViseme)
        out.closureNote = name + " is the rest viseme" + leftAlone;
    else if (std::find(names.pinned.begin(), names.pinned.end(), name) != names.pinned.end())
        out.closureViseme = name; // the designer pinned it already
    else if (mentions(names.together, name))
        out.closureNote = "--together names " + name + leftAlone;
    else {
        names.pinned.push_back(name);
        out.closureViseme = name;
    }
    return names;
}

// rho_f of a grouping from the meshes: the keys' spread plus f_i rho(A_i, neutral) of every resting viseme.
double costWithRest(const ShapeView& shapes, std::span<const Vec3> neutral, const ReduceOutcome& out,
                    const Grouping& grouping) {
    double cost = groupingCost(shapes, out.frequencies, out.weights, grouping.groups);
    for (const int i : grouping.rest) {
        double moved = 0;
        for (std::size_t v = 0; v < neutral.size(); ++v)
            moved += out.weights[v] * (shapes[static_cast<std::size_t>(i)][v] - neutral[v]).sqrnorm();
        cost += out.frequencies[static_cast<std::size_t>(i)] * moved;
    }
    return cost;
}

// `--max-error-mm`: the smallest number of keys that keeps every viseme within the bound
// (MaxErrorSearch.h), then the reduction at that m with the pairs the bound rules out kept apart (a
// relaxation: its optimum bounds every grouping that meets the bound). When that optimum meets the
// bound it is the proven optimum among them; otherwise the search's grouping is used, with the
// relaxation's optimum as its lower bound.
ReductionResult reduceWithinMaxError(const ShapeView& shapes, std::span<const Vec3> neutral,
                                     ReduceOutcome& out, const ReduceSettings& settings,
                                     const ReductionConstraints& constraints, const ConstraintUnits& units,
                                     const RestPose& rest, const ProgressCallback& progress) {
    if (!(settings.millimetresPerUnit > 0))
        throwInputError("--max-error-mm",
                        "the set's length unit is not known, so a bound in mm cannot be applied");
    MaxErrorProblem bound;
    bound.shapes = shapes;
    if (rest.free) bound.rest = neutral;
    bound.frequencies = out.frequencies;
    bound.weights = out.weights;
    bound.maxError = settings.maxErrorMm / settings.millimetresPerUnit;
    bound.units = units;
    if (rest.free && rest.viseme >= 0) bound.mustRest = {rest.viseme};
    bound.mustKey = constraints.pinned;
    const MaxErrorResult found = smallestKeysWithin(bound);
    ReductionConstraints relaxed = constraints;
    for (const auto& pair : maxErrorApartPairs(bound)) relaxed.apart.push_back(pair);
    ReductionResult result = reduceVisemes({shapes, out.frequencies, out.weights, found.keys, relaxed, rest},
                                           settings.options, progress);
    MaxErrorFinding finding{settings.maxErrorMm, found.keys, found.certified, false};
    if (withinMaxError(bound, result.groupOf())) {
        finding.optimalWithin = result.best().optimal;
    } else {
        Grouping within;
        within.lowerBound = result.best().lowerBound;
        std::vector<std::vector<int>> keys(static_cast<std::size_t>(found.keys));
        for (std::size_t i = 0; i < found.groupOf.size(); ++i) {
            if (found.groupOf[i] < 0)
                within.rest.push_back(static_cast<int>(i));
            else
                keys[static_cast<std::size_t>(found.groupOf[i])].push_back(static_cast<int>(i));
        }
        for (auto& key : keys)
            if (!key.empty()) within.groups.push_back(std::move(key));
        std::sort(within.groups.begin(), within.groups.end());
        within.cost = costWithRest(shapes, neutral, out, within);
        result.curve.back() = std::move(within);
    }
    out.maxError = finding;
    return result;
}

} // namespace

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress) {
    return runReduction(shapesOf(set), frequencies, settings, progress);
}

ReduceOutcome runReduction(const SetShapes& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress,
                           KeyPositions keyPositions) {
    ReduceOutcome out;
    out.visemeNames = set.names;
    out.frequencies = visemeFrequencies(frequencies, out.visemeNames);
    const MeshData& neutral = *set.neutral;
    out.weights =
        computeWeights(settings.weightMode, neutral, settings.paintedWeights, settings.paintedWeightsSource);
    requireKnownVisemes(set, frequencies); // before the reduction, not after it

    const ShapeView& shapes = set.shapes;
    // The rest pose of a morph-target runtime is the neutral mesh: the rest-free model's free key.
    const int restViseme = restVisemeIndex(out.visemeNames, settings.restViseme, settings.restVisemeSource);
    const RestPose rest{restIsFree(settings.rest, restViseme), restViseme, neutral.positions};
    const bool restFree = rest.free;
    const bool targetGiven = settings.target >= 1 && static_cast<std::size_t>(settings.target) <= set.size();
    ConstraintNames constraintNames = constraintsWithClosure(set, settings, restFree, restViseme, out);
    if (!out.closureViseme.empty() && constraintNames.pinned.size() > settings.constraints.pinned.size()) {
        // The implicit pin yields to a target it would rule out (e.g. m = n - 1 with every other key pinned).
        const ReductionConstraints withPin =
            resolveConstraints(constraintNames, out.visemeNames, settings.constraintsSource);
        if (targetGiven && !keyUnits(withPin, static_cast<int>(set.size()), rest, out.visemeNames,
                                     settings.constraintsSource)
                                .feasible(settings.target)) {
            out.closureNote = "the designer's constraints leave no room for " + out.closureViseme +
                              " as a key of its own at m = " + std::to_string(settings.target) +
                              ": it is left to the optimiser";
            out.closureViseme.clear();
            constraintNames = settings.constraints;
        }
    }
    const ReductionConstraints constraints =
        resolveConstraints(constraintNames, out.visemeNames, settings.constraintsSource);
    // Contradictions and a target they rule out are reported by viseme name, at the constraints' source.
    const ConstraintUnits units = constraintUnits(constraints, static_cast<int>(set.size()), out.visemeNames,
                                                  settings.constraintsSource);
    if (targetGiven) {
        const ConstraintUnits keys = keyUnits(constraints, static_cast<int>(set.size()), rest,
                                              out.visemeNames, settings.constraintsSource);
        if (!keys.feasible(settings.target))
            throwInfeasibleTarget(keys, settings.target, settings.constraintsSource);
    }
    if (restViseme >= 0) out.restViseme = set.names[static_cast<std::size_t>(restViseme)];
    out.millimetresPerUnit = settings.millimetresPerUnit;
    if (settings.maxErrorMm > 0) {
        out.result = reduceWithinMaxError(shapes, neutral.positions, out, settings, constraints, units, rest,
                                          progress);
    } else {
        out.result = reduceVisemes({shapes, out.frequencies, out.weights, settings.target, constraints, rest},
                                   settings.options, progress);
    }
    out.constraints = settings.constraints;
    if (!settings.compareMaps.empty()) {
        std::vector<std::vector<std::vector<int>>> groupings;
        for (const auto& map : settings.compareMaps) {
            out.comparedMaps.push_back(groupingFromMap(out.visemeNames, map));
            groupings.push_back(out.comparedMaps.back().groups);
        }
        const auto costs = evaluateGroupings(shapes, out.frequencies, out.weights, groupings, rest);
        for (std::size_t k = 0; k < costs.size(); ++k) out.comparedMaps[k].cost = costs[k];
    }

    const std::vector<int> groupOf = out.result.groupOf();
    out.model = buildReducedModel(set, out.frequencies, groupOf, frequencies, keyPositions);
    if (keyPositions == KeyPositions::Deferred) {
        // The keys merged one at a time for their members' errors (memory for one key, as doubles).
        out.visemeErrors = visemeErrors(shapes, neutral.positions, out.frequencies, out.weights, groupOf);
        return out;
    }
    // Errors against the model's own key meshes: the keys are merged once, not again here.
    std::vector<std::span<const Vec3>> keyRows;
    for (const KeyMesh& key : out.model.keys) keyRows.emplace_back(key.positions);
    out.visemeErrors = visemeErrors(shapes, neutral.positions, out.weights, groupOf, ShapeView(keyRows));
    return out;
}

} // namespace vl
