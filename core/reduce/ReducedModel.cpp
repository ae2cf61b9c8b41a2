#include "core/reduce/ReducedModel.h"

#include "core/common/Error.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/SetShapes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>

namespace vl {

int ReducedModel::findKey(std::string_view name) const {
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (keys[k].name == name) return static_cast<int>(k);
    return -1;
}

std::string mergedKeyName(const std::vector<std::string>& members) {
    std::string name;
    for (const std::string& m : members) name += (name.empty() ? "" : "+") + m;
    return name;
}

void requireKnownVisemes(const VisemeSet& set, const FrequencySource& source) {
    requireKnownVisemes(shapesOf(set), source);
}

// Every map entry whose viseme the set lacks, as one error: "unknown viseme 'x' (phonemes A, B)".
void requireKnownVisemes(const SetShapes& set, const FrequencySource& source) {
    if (!source.isPhonemeBased()) return;
    std::map<std::string, std::string> unknown; // viseme -> its phonemes, joined
    for (const auto& [phoneme, viseme] : source.map.entries)
        if (set.find(viseme) < 0) {
            std::string& phonemes = unknown[viseme];
            phonemes += (phonemes.empty() ? "" : ", ") + phoneme;
        }
    if (unknown.empty()) return;
    std::string list;
    for (const auto& [viseme, phonemes] : unknown)
        list += (list.empty() ? "" : "; ") + ("unknown viseme '" + viseme + "' (phonemes " + phonemes + ")");
    const std::string& origin = !source.map.origin.text.empty() ? source.map.origin.text : source.origin.text;
    throwInputError(origin.empty() ? "phoneme map" : origin,
                    "the phoneme map names visemes the set does not have: " + list);
}

ReducedModel buildReducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                               const std::vector<int>& groupOf, const FrequencySource& source) {
    return buildReducedModel(shapesOf(set), frequencies, groupOf, source);
}

ReducedModel buildReducedModel(const SetShapes& set, const std::vector<double>& frequencies,
                               const std::vector<int>& groupOf, const FrequencySource& source,
                               KeyPositions positions) {
    const std::size_t n = set.size();
    if (frequencies.size() != n || groupOf.size() != n)
        throwInputError("reduced model", "frequencies and grouping must have one entry per viseme");
    int groupCount = 0;
    for (int g : groupOf) {
        if (g != kRestGroup && (g < 0 || g >= static_cast<int>(n)))
            throwInputError("reduced model", "group index out of range");
        groupCount = std::max(groupCount, g + 1);
    }
    requireKnownVisemes(set, source);
    std::vector<std::vector<int>> members(static_cast<std::size_t>(groupCount));
    for (std::size_t i = 0; i < n; ++i)
        if (groupOf[i] != kRestGroup)
            members[static_cast<std::size_t>(groupOf[i])].push_back(static_cast<int>(i));

    ReducedModel model;
    if (positions == KeyPositions::Merged) model.neutral = *set.neutral; // deferred: the set's serves
    for (std::size_t i = 0; i < n; ++i)
        if (groupOf[i] == kRestGroup) model.resting.push_back(set.names[i]);
    for (std::size_t g = 0; g < members.size(); ++g) {
        if (members[g].empty())
            throwInputError("reduced model", "group " + std::to_string(g) + " has no member");
        KeyMesh key;
        for (int i : members[g]) {
            key.members.push_back(set.names[static_cast<std::size_t>(i)]);
            key.frequency += frequencies[static_cast<std::size_t>(i)];
        }
        key.name = mergedKeyName(key.members);
        if (positions == KeyPositions::Merged && members[g].size() == 1) {
            const ShapeRow own = set.shapes[static_cast<std::size_t>(members[g][0])];
            key.positions.reserve(own.size()); // its own shape, bit for bit (a sum would turn -0 into 0)
            for (std::size_t v = 0; v < own.size(); ++v) key.positions.push_back(own[v]);
        } else if (positions == KeyPositions::Merged) {
            key.positions = mergeGroup(set.shapes, frequencies, members[g]);
        }
        model.keys.push_back(std::move(key));
    }

    if (source.isPhonemeBased()) {
        for (const auto& [phoneme, viseme] : source.map.entries)
            model.phonemeToKey.emplace_back(phoneme, groupOf[static_cast<std::size_t>(set.find(viseme))]);
        model.phonemeFrequencies = source.phonemes.entries;
    } else {
        for (std::size_t i = 0; i < n; ++i) model.phonemeToKey.emplace_back(set.names[i], groupOf[i]);
    }
    if (positions == KeyPositions::Merged)
        validateReducedModel(model, "reduced model");
    else
        validateDeferredModel(model, "reduced model");
    return model;
}

ReducedModel unreducedModel(const VisemeSet& set, const std::vector<double>& frequencies,
                            const FrequencySource& source) {
    std::vector<int> identity(set.size());
    for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
    return buildReducedModel(set, frequencies, identity, source);
}

namespace {

void validate(const ReducedModel& model, std::string_view where, KeyPositions positions) {
    const std::size_t v = model.neutral.positions.size();
    if (positions == KeyPositions::Merged && (v == 0 || model.neutral.triangles.empty()))
        throwInputError(where, "the neutral mesh is empty");
    if (model.keys.empty()) throwInputError(where, "no key meshes");
    std::set<std::string> names;
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        const KeyMesh& key = model.keys[k];
        const std::string what = "key " + std::to_string(k) + " ('" + key.name + "')";
        if (key.name.empty()) throwInputError(where, "key " + std::to_string(k) + " has no name");
        if (!names.insert(key.name).second) throwInputError(where, what + ": duplicate name");
        if (positions == KeyPositions::Deferred) {
            if (!key.positions.empty()) throwInputError(where, what + ": positions given where deferred");
            continue;
        }
        if (key.positions.size() != v)
            throwInputError(where, what + ": " + std::to_string(key.positions.size()) +
                                       " positions, the neutral has " + std::to_string(v));
        for (const Vec3& p : key.positions)
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                throwInputError(where, what + ": non-finite position");
    }
    std::set<std::string> phonemes;
    for (const auto& [phoneme, key] : model.phonemeToKey) {
        if (phoneme.empty()) throwInputError(where, "empty phoneme name");
        if (!phonemes.insert(phoneme).second)
            throwInputError(where, "phoneme '" + phoneme + "' is listed twice");
        if (key != kRestingKey && (key < 0 || key >= static_cast<int>(model.keys.size())))
            throwInputError(where, "phoneme '" + phoneme + "' maps to key " + std::to_string(key) + " of " +
                                       std::to_string(model.keys.size()));
    }
}

} // namespace

void validateReducedModel(const ReducedModel& model, std::string_view where) {
    validate(model, where, KeyPositions::Merged);
}

void validateDeferredModel(const ReducedModel& model, std::string_view where) {
    validate(model, where, KeyPositions::Deferred);
}

} // namespace vl
