#pragma once
// What one reduction runs on, whichever front end gathered it (CLI flags, a project file, the
// editor's document), the one policy for how long it may search, and the one place a reduced model
// comes from: a grouping already known for these inputs (a project's last result, the editor's
// curve), else a fresh reduction under the policy. `reduce`, `avatar reduce`, `say`, `export` and
// the editor's panel and exports all go through here.
#include "core/mesh/VisemeSet.h"
#include "core/reduce/ReduceRun.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace vl {

struct ReduceInputs {
    std::shared_ptr<const VisemeSet> set;
    FrequencySource frequencies; // as given: viseme table, or phoneme table + map
    ReduceSettings settings;     // settings.options.timeLimitSeconds is set by the policy
};

// A set the caller keeps alive for as long as the inputs live, viewed (not copied, not owned).
inline std::shared_ptr<const VisemeSet> viewedSet(const VisemeSet& set) {
    return std::shared_ptr<const VisemeSet>(std::shared_ptr<const VisemeSet>(), &set);
}

// A frequency table read with a phoneme -> viseme map given beside it: the table holds phoneme
// frequencies (a table read as per-viseme becomes the phoneme table), the map is `map`.
FrequencySource withPhonemeMap(FrequencySource table, PhonemeVisemeMap map);
// Throws InputError at `where` when `source` is a phoneme table without a map.
void requirePhonemeMap(const FrequencySource& source, std::string_view where);

// The batch front ends' limit (`reduce --time-limit` by default, `avatar reduce`, `say`, `export`).
inline constexpr double kBatchReduceSeconds = 60.0;
// The editor's limit for sets the exact solvers cannot take: a designer does not wait for a proof.
inline constexpr double kInteractiveReduceSeconds = 10.0;

// How long a reduction may search for a proof of optimality before it reports the best grouping
// found with its gap.
struct ReducePolicy {
    double timeLimitSeconds = kBatchReduceSeconds; // 0: no limit
    // Limit only sets of more than kMaxExactVisemes: smaller ones always get the exact answer.
    bool largeSetsOnly = false;

    static ReducePolicy batch(double seconds = kBatchReduceSeconds) { return {seconds, false}; }
    static ReducePolicy interactive() { return {kInteractiveReduceSeconds, true}; }
    // The time limit of a reduction of `visemeCount` visemes (0: none).
    double timeLimitFor(std::size_t visemeCount) const;
};

// `settings` with the policy's time limit for a set of `visemeCount` visemes.
ReduceSettings withPolicy(ReduceSettings settings, const ReducePolicy& policy, std::size_t visemeCount);

// The reduction of the inputs under the policy (runReduction).
ReduceOutcome reduce(const ReduceInputs& inputs, const ReducePolicy& policy,
                     const ProgressCallback& progress = {});

// The grouping a project recorded (Project::reduction.result) when it is one of these inputs: into
// exactly settings.target groups, of the same rest model and viseme count; else null.
const Grouping* recordedGrouping(const ReduceInputs& inputs, const std::optional<ReductionResult>& recorded);

// The grouping of the reduced model (groupOf per viseme, kRestGroup for resting ones): `known`'s
// (a recorded one, the editor's current one; may be null), else a fresh reduction's.
std::vector<int> reducedGrouping(const ReduceInputs& inputs, const Grouping* known,
                                 const ReducePolicy& policy);

// The reduced model (buildReducedModel: merged keys, phoneme -> key) of that grouping.
ReducedModel reducedModel(const ReduceInputs& inputs, const Grouping* known, const ReducePolicy& policy);
// Every viseme its own key (unreducedModel) with the inputs' frequencies.
ReducedModel unreducedModelOf(const ReduceInputs& inputs);

} // namespace vl
