#pragma once
// What every exporter takes: the neutral mesh, the key meshes (merged visemes of a reduction, or
// the original visemes for an unreduced export), and the phoneme -> key map. Built from a VisemeSet,
// its frequencies and a grouping, so the CLI, the project and the editor all export the same way.
#include "core/mesh/Mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace vl {

struct VisemeSet;
struct FrequencySource;

struct KeyMesh {
    std::string name;                 // e.g. "f+th" for a merged group, or the viseme's own name
    std::vector<std::string> members; // original viseme names merged into it
    double frequency = 0.0;           // summed (normalised) frequency of the members
    std::vector<Vec3> positions;      // one per neutral vertex
};

struct ReducedModel {
    MeshData neutral;
    std::vector<KeyMesh> keys;
    std::vector<std::pair<std::string, int>> phonemeToKey;          // every phoneme -> index into keys
    std::vector<std::pair<std::string, double>> phonemeFrequencies; // empty unless phoneme-based

    int findKey(std::string_view name) const;
};

// The name of a merged key: its members joined by '+'.
std::string mergedKeyName(const std::vector<std::string>& members);

// Key k merges the visemes i with groupOf[i] == k (groups numbered 0..m-1, each non-empty), its
// positions are the frequency-weighted mean (mergeGroup). Phonemes come from the source's
// phoneme -> viseme map when it is phoneme-based; otherwise every viseme name stands for itself.
ReducedModel buildReducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                               const std::vector<int>& groupOf, const FrequencySource& source);

// The unreduced set as a model: one key per viseme (groupOf = identity).
ReducedModel unreducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                            const FrequencySource& source);

// Throws InputError naming `where` when keys are empty, unnamed, duplicated, of the wrong vertex
// count or non-finite, or a phoneme maps outside the keys or is listed twice.
void validateReducedModel(const ReducedModel& model, std::string_view where);

} // namespace vl
