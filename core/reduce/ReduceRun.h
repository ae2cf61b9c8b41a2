#pragma once
// One reduction run from user-level inputs (viseme set, frequencies, weight mode, target) to the
// reduced model (buildReducedModel). Shared by the CLI, projects and avatars so all behave
// identically; its files and report are written by core/export/ReductionOutputs.h.
#include "core/common/EnumNames.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/SetShapes.h"
#include "core/reduce/VisemeErrors.h"
#include "core/reduce/Weights.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// Which reduction model runs (Reduction.h RestPose): Free, the rest pose is a free extra key;
// Key, the rest is a key like any other (the model before issue 29); Auto, Free when the set has a
// rest viseme, else Key.
enum class RestChoice { Auto, Free, Key };
template <> struct EnumNames<RestChoice> {
    static constexpr const char* what = "rest model";
    static constexpr EnumName<RestChoice> names[] = {
        {RestChoice::Auto, "auto"}, {RestChoice::Free, "free"}, {RestChoice::Key, "key"}};
};

// The rest viseme names a set may use, in order of preference (the sample's and the Oculus one).
inline constexpr const char* kRestVisemeNames[] = {"sil", "viseme_sil"};

// The lips-closed viseme names (P, B, M), in order of preference (the sample's and the Oculus one).
inline constexpr const char* kClosureVisemeNames[] = {"PP", "viseme_PP"};
// ReduceSettings::closure value that picks the first of kClosureVisemeNames the set has.
inline constexpr const char* kClosureAuto = "auto";

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
    // Key keeps projects and the editor on the model they were saved with (their files store no rest
    // groups); the CLI passes Auto.
    RestChoice rest = RestChoice::Key;
    std::string restViseme{}; // the rest viseme's name; empty: the first of kRestVisemeNames in the set
    // With the rest free, the lips-closed viseme keeps a key of its own (an implicit pin) unless the
    // designer constrained it: a bilabial that does not close reads as wrong lip-sync whatever its
    // squared error, yet on avatars whose closure is a small motion the frequency-weighted cost
    // prefers to rest it or average it away. "" (default): no such rule; kClosureAuto: the first of
    // kClosureVisemeNames in the set (none: no rule); else a viseme's name (InputError when absent).
    // Dropped, with ReduceOutcome::closureNote saying why, where the target or the designer's
    // constraints leave no room for it.
    std::string closure{};
    std::string restVisemeSource = "--rest-viseme"; // where errors about it point (a flag, a JSON path)
    // The set's length unit in millimetres (1000 for glTF's metres); 0 when unknown. Per-viseme errors
    // are reported in mm only when it is known.
    double millimetresPerUnit = 0;
    // > 0 (`--max-error-mm`): the target becomes the smallest number of keys for which no viseme moves
    // any vertex more than this from its own shape (MaxErrorSearch.h; needs millimetresPerUnit).
    double maxErrorMm = 0;
};

// The index in `names` of the rest viseme: `named` (InputError at `where` when no viseme has that
// name), else the first of kRestVisemeNames present, else -1.
int restVisemeIndex(const std::vector<std::string>& names, const std::string& named, std::string_view where);
// Whether `choice` runs the rest-free model for a set whose rest viseme is `restViseme` (-1: none).
bool restIsFree(RestChoice choice, int restViseme);

// What `--max-error-mm` found.
struct MaxErrorFinding {
    double limitMm = 0;
    int keys = 0;               // the smallest number of keys that meets the bound (the run's m)
    bool certified = false;     // no grouping with fewer keys meets it (proven)
    bool optimalWithin = false; // the run's grouping is the proven optimum among those meeting it
};

// A map used as a grouping: the set's visemes the map sends to the same viseme share a group.
struct MapGrouping {
    std::string source;                   // the map's origin (file)
    std::vector<std::string> labels;      // the map's viseme of each group
    std::vector<std::vector<int>> groups; // member indices, each ascending, ordered by first member
    double cost = 0; // rho_f under the run's model, frequencies and weights (rest-free: the group
                     // holding the rest viseme rests)
};

// The grouping of `visemeNames` by `map`. Every viseme must be a phoneme of the map (InputError at the
// map's origin listing all that are not); map entries for phonemes the set does not have are ignored.
MapGrouping groupingFromMap(const std::vector<std::string>& visemeNames, const PhonemeVisemeMap& map);

struct ReduceOutcome {
    std::vector<std::string> visemeNames;
    std::vector<double> frequencies; // normalised, one per original viseme
    std::vector<double> weights;     // one per vertex
    ReductionResult result;
    // The merged keys of the best grouping for the target m and the phoneme -> key map
    // (buildReducedModel: map entries naming a viseme the set lacks are an error).
    ReducedModel model;
    ConstraintNames constraints;             // the constraints the run honoured
    std::string restViseme;                  // the set's rest viseme ("" without one)
    std::string closureViseme;               // the viseme settings.closure pinned ("" none)
    std::string closureNote;                 // why settings.closure pinned nothing ("" when it did)
    std::vector<VisemeError> visemeErrors;   // per viseme, model units (VisemeErrors.h)
    double millimetresPerUnit = 0;           // settings.millimetresPerUnit
    std::optional<MaxErrorFinding> maxError; // with settings.maxErrorMm
    std::vector<MapGrouping> comparedMaps{}; // settings.compareMaps, costed
};

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress = {});
// The same on a view of the set (a VisemeSet or a FloatVisemeSet). With KeyPositions::Deferred the
// model's keys have names but no positions (a writer merges each as it writes it, mergeKeyInto) and
// its neutral is empty (the set's serves): a large set's keys are never held as doubles.
ReduceOutcome runReduction(const SetShapes& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress = {},
                           KeyPositions keyPositions = KeyPositions::Merged);

} // namespace vl
