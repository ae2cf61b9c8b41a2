#include "core/project/ReduceInputs.h"

#include "core/common/Error.h"

namespace vl {

namespace {

std::vector<std::string> namesOf(const VisemeSet& set) {
    std::vector<std::string> names;
    for (const Viseme& viseme : set.visemes) names.push_back(viseme.name);
    return names;
}

} // namespace

FrequencySource withPhonemeMap(FrequencySource table, PhonemeVisemeMap map) {
    if (!table.isPhonemeBased()) {
        table.phonemes = std::move(table.visemeFrequencies);
        table.visemeFrequencies = {};
    }
    table.map = std::move(map);
    return table;
}

void requirePhonemeMap(const FrequencySource& source, std::string_view where) {
    if (source.isPhonemeBased() && source.map.entries.empty())
        throwInputError(where, "a phoneme frequency table needs a phoneme -> viseme map (--map FILE)");
}

double ReducePolicy::timeLimitFor(std::size_t visemeCount) const {
    if (largeSetsOnly && visemeCount <= static_cast<std::size_t>(kMaxExactVisemes)) return 0.0;
    return timeLimitSeconds;
}

ReduceSettings withPolicy(ReduceSettings settings, const ReducePolicy& policy, std::size_t visemeCount) {
    settings.options.timeLimitSeconds = policy.timeLimitFor(visemeCount);
    return settings;
}

ReduceOutcome reduce(const ReduceInputs& inputs, const ReducePolicy& policy,
                     const ProgressCallback& progress) {
    return runReduction(*inputs.set, inputs.frequencies,
                        withPolicy(inputs.settings, policy, inputs.set->size()), progress);
}

const Grouping* recordedGrouping(const ReduceInputs& inputs, const std::optional<ReductionResult>& recorded) {
    if (!recorded || recorded->curve.empty() ||
        static_cast<int>(recorded->curve.size()) != inputs.settings.target)
        return nullptr;
    // A result of the other rest model (the choice changed since) is not of these inputs.
    const ReduceSettings& settings = inputs.settings;
    const int restViseme =
        restVisemeIndex(namesOf(*inputs.set), settings.restViseme, settings.restVisemeSource);
    if (recorded->restFree != restIsFree(settings.rest, restViseme)) return nullptr;
    const Grouping& best = recorded->best();
    return best.groupOf().size() == inputs.set->size() ? &best : nullptr;
}

std::vector<int> reducedGrouping(const ReduceInputs& inputs, const Grouping* known,
                                 const ReducePolicy& policy) {
    return known ? known->groupOf() : reduce(inputs, policy).result.groupOf();
}

ReducedModel reducedModel(const ReduceInputs& inputs, const Grouping* known, const ReducePolicy& policy) {
    if (!known) return reduce(inputs, policy).model;
    return buildReducedModel(*inputs.set, visemeFrequencies(inputs.frequencies, namesOf(*inputs.set)),
                             known->groupOf(), inputs.frequencies);
}

ReducedModel unreducedModelOf(const ReduceInputs& inputs) {
    return unreducedModel(*inputs.set, visemeFrequencies(inputs.frequencies, namesOf(*inputs.set)),
                          inputs.frequencies);
}

} // namespace vl
