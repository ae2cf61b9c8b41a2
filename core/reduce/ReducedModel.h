#pragma once
// The reduced model: the neutral mesh, the key meshes (merged visemes of a reduction, or the
// original visemes for an unreduced model) and the phoneme -> key map. buildReducedModel is the one
// way every front end (CLI reduce and export, the editor's merged view and export, avatars, speech)
// turns a viseme set, its frequencies and a grouping into merged keys and that map, so all of them
// name, merge and map identically. Writers of the model live in core/export.
#include "core/mesh/Mesh.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vl {

struct VisemeSet;
struct SetShapes;
struct FrequencySource;

struct KeyMesh {
    std::string name;                 // members joined by '+' (mergedKeyName), e.g. "f+th"
    std::vector<std::string> members; // original viseme names merged into it
    double frequency = 0.0;           // summed (normalised) frequency of the members
    std::vector<Vec3> positions;      // one per neutral vertex
};

// A phoneme or viseme of the rest-free model's rest (Reduction.h RestPose): no key, all weights 0,
// the neutral face. The same value as the speech tracks' kNeutralKey and, as unsigned, the runtime's
// kRestingKey.
inline constexpr int kRestingKey = -1;

struct ReducedModel {
    MeshData neutral;
    std::vector<KeyMesh> keys;
    std::vector<std::string> resting{}; // original visemes that rest (no key), in viseme order
    std::vector<std::pair<std::string, int>> phonemeToKey; // every phoneme -> index into keys or kRestingKey
    std::vector<std::pair<std::string, double>> phonemeFrequencies; // empty unless phoneme-based

    int findKey(std::string_view name) const;
};

// The name of a merged key: its members joined by '+'.
std::string mergedKeyName(const std::vector<std::string>& members);

// Key k merges the visemes i with groupOf[i] == k (groups numbered 0..m-1, each non-empty, members
// in viseme order; groupOf[i] == kRestGroup: viseme i rests, its phonemes map to kRestingKey); its positions
// are the frequency-weighted mean (mergeGroup), a single member's are its own. Phonemes come from the
// source's phoneme -> viseme map when it is phoneme-based; otherwise every viseme name stands for itself. One
// policy for names: a map entry naming a viseme the set lacks is an InputError (at the map's origin) that
// lists every such viseme and its phonemes; nothing is dropped silently. Malformed frequencies or groupings
// throw InputError too.
ReducedModel buildReducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                               const std::vector<int>& groupOf, const FrequencySource& source);

// Whether buildReducedModel merges the keys' positions, or leaves them and the model's neutral empty
// for a writer that merges each key from the set as it writes it (mergeKeyInto: `reduce` of large
// meshes holds no key as doubles and no second copy of the neutral).
enum class KeyPositions { Merged, Deferred };
// The same from a view of the set (SetShapes.h: a VisemeSet or a FloatVisemeSet).
ReducedModel buildReducedModel(const SetShapes& set, const std::vector<double>& frequencies,
                               const std::vector<int>& groupOf, const FrequencySource& source,
                               KeyPositions positions = KeyPositions::Merged);

// The name policy alone, for a caller that wants it before a long run: throws the InputError
// buildReducedModel would throw when the (phoneme-based) source maps a phoneme to a viseme the set lacks.
void requireKnownVisemes(const VisemeSet& set, const FrequencySource& source);
void requireKnownVisemes(const SetShapes& set, const FrequencySource& source);

// The unreduced set as a model: one key per viseme (groupOf = identity).
ReducedModel unreducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                            const FrequencySource& source);

// Throws InputError naming `where` when keys are empty, unnamed, duplicated, of the wrong vertex
// count or non-finite, or a phoneme maps outside the keys or is listed twice.
void validateReducedModel(const ReducedModel& model, std::string_view where);
// The same for a model whose keys' positions and neutral are deferred (empty): names and phonemes only.
void validateDeferredModel(const ReducedModel& model, std::string_view where);

} // namespace vl
