#include "core/document/PhonemeMapCommands.h"

#include "core/common/Error.h"
#include "core/document/CommandSupport.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <unordered_map>

namespace vl::edit {
namespace {

using detail::checked;
using detail::requireSet;

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

double tableTotal(const FrequencyTable& table) {
    double total = 0.0;
    for (const auto& entry : table.entries) total += entry.second;
    return total;
}

void requirePhonemeBased(const Document& document, std::string_view what) {
    if (!document.frequencies.isPhonemeBased())
        throwInputError(what, "the frequencies are direct: start a phoneme map first");
}

} // namespace

std::vector<std::string> phonemesMappedTo(const FrequencySource& source, const std::string& viseme) {
    std::vector<std::string> phonemes;
    if (!source.isPhonemeBased()) return phonemes;
    for (const auto& [phoneme, value] : source.phonemes.entries)
        if (const std::string* mapped = source.map.visemeOf(phoneme); mapped && *mapped == viseme)
            phonemes.push_back(phoneme);
    return phonemes;
}

std::string phonemeList(const FrequencySource& source, const std::vector<std::string>& phonemes) {
    double mass = 0.0;
    for (const std::string& phoneme : phonemes)
        if (const double* value = source.phonemes.find(phoneme)) mass += *value;
    const double total = tableTotal(source.phonemes);
    char share[48];
    std::snprintf(share, sizeof share, " (%.1f %% of the phonemes)",
                  total > 0.0 ? 100.0 * mass / total : 0.0);
    return joined(phonemes) + share;
}

std::vector<MapAssignment> suggestMapAssignment(const Document& document, const FrequencyTable& table,
                                                const PhonemeVisemeMap& start) {
    const std::vector<std::string> names = visemeNames(document);
    std::unordered_map<std::string, std::string> byLowercase;
    for (const std::string& name : names) byLowercase.emplace(lowercase(name), name);
    const double total = tableTotal(table);
    std::vector<MapAssignment> rows;
    const auto rowOf = [&](const std::string& from) -> MapAssignment& {
        const auto it =
            std::find_if(rows.begin(), rows.end(), [&](const auto& row) { return row.from == from; });
        if (it != rows.end()) return *it;
        MapAssignment row{from, {}, 0.0, {}};
        if (from != kPhonemesNotInMap) {
            if (std::find(names.begin(), names.end(), from) != names.end())
                row.to = from;
            else if (const auto match = byLowercase.find(lowercase(from)); match != byLowercase.end())
                row.to = match->second;
        }
        rows.push_back(std::move(row));
        return rows.back();
    };
    // Per row, how much of its phoneme mass the document's current map gives each viseme.
    std::vector<std::map<std::string, double>> currentMass; // ordered: ties resolve by name
    const FrequencySource& current = document.frequencies;
    for (const auto& [phoneme, value] : table.entries) {
        const std::string* mapped = start.visemeOf(phoneme);
        MapAssignment& row = rowOf(mapped ? *mapped : std::string(kPhonemesNotInMap));
        row.phonemes.push_back(phoneme);
        row.share += total > 0.0 ? value / total : 0.0;
        currentMass.resize(rows.size());
        if (const std::string* now = current.isPhonemeBased() ? current.map.visemeOf(phoneme) : nullptr)
            currentMass[static_cast<std::size_t>(&row - rows.data())][*now] += value;
    }
    // Rows no name matched take the viseme the current map gives most of their phonemes.
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (!rows[r].to.empty()) continue;
        double best = 0.0;
        for (const auto& [viseme, mass] : currentMass[r])
            if (mass > best && std::find(names.begin(), names.end(), viseme) != names.end()) {
                best = mass;
                rows[r].to = viseme;
            }
    }
    // The phonemes the map does not list come last.
    std::stable_partition(rows.begin(), rows.end(),
                          [](const auto& row) { return row.from != kPhonemesNotInMap; });
    return rows;
}

Document startPhonemeMap(const Document& document, FrequencyTable table, const PhonemeVisemeMap& start,
                         const std::vector<MapAssignment>& assignment) {
    requireSet(document, "phoneme map");
    if (table.entries.empty()) throwInputError("phoneme map", "the phoneme table is empty");
    std::unordered_map<std::string, std::string> target;
    for (const MapAssignment& row : assignment) target[row.from] = row.to;
    // Rows still unassigned, with their phonemes, in table order (for one message naming all).
    std::vector<std::pair<std::string, std::vector<std::string>>> unassigned;
    FrequencySource source;
    for (const auto& [phoneme, value] : table.entries) {
        const std::string* mapped = start.visemeOf(phoneme);
        const std::string from = mapped ? *mapped : std::string(kPhonemesNotInMap);
        const auto to = target.find(from);
        if (to != target.end() && document.visemes->find(to->second) >= 0) {
            source.map.entries.emplace_back(phoneme, to->second);
            continue;
        }
        auto row = std::find_if(unassigned.begin(), unassigned.end(),
                                [&](const auto& r) { return r.first == from; });
        if (row == unassigned.end()) row = unassigned.insert(unassigned.end(), {from, {}});
        row->second.push_back(phoneme);
    }
    if (!unassigned.empty()) {
        std::vector<std::string> rows;
        for (const auto& [from, phonemes] : unassigned) rows.push_back(from + " (" + joined(phonemes) + ")");
        throwInputError("phoneme map", "assign a viseme of the set to " + joined(rows));
    }
    source.phonemes = std::move(table);
    source.map.origin = start.origin;
    Document next = document;
    next.frequencies = std::move(source);
    return checked(std::move(next));
}

PhonemeVisemeMap phonemePerVisemeMap(const FrequencyTable& table) {
    PhonemeVisemeMap map;
    for (const auto& entry : table.entries) map.entries.emplace_back(entry.first, entry.first);
    return map;
}

Document movePhonemes(const Document& document, const std::string& from, const std::string& to) {
    requirePhonemeBased(document, "move phonemes");
    if (!document.visemes || document.visemes->find(to) < 0)
        throwInputError("move phonemes of " + from, "'" + to + "' is not a viseme of the set");
    if (phonemesMappedTo(document.frequencies, from).empty())
        throwInputError("move phonemes of " + from, "no phoneme maps to it");
    if (from == to) throwInputError("move phonemes of " + from, "they map to it already");
    Document next = document;
    for (auto& [phoneme, viseme] : next.frequencies.map.entries)
        if (viseme == from) viseme = to;
    return checked(std::move(next));
}

Document useDirectFrequencies(const Document& document) {
    requireSet(document, "direct frequencies");
    requirePhonemeBased(document, "direct frequencies");
    const std::vector<double> frequencies = documentFrequencies(document);
    Document next = document;
    next.frequencies = {};
    for (std::size_t i = 0; i < frequencies.size(); ++i)
        next.frequencies.visemeFrequencies.entries.emplace_back(document.visemes->visemes[i].name,
                                                                frequencies[i]);
    return checked(std::move(next));
}

MapCoverage mapCoverage(const Document& document) {
    MapCoverage coverage;
    const std::size_t n = document.visemeCount();
    coverage.phonemesOf.resize(n);
    coverage.share.assign(n, 0.0);
    const FrequencySource& source = document.frequencies;
    if (!source.isPhonemeBased()) return coverage;
    const double total = tableTotal(source.phonemes);
    for (const auto& [phoneme, value] : source.phonemes.entries) {
        const std::string* mapped = source.map.visemeOf(phoneme);
        const int index = mapped ? document.visemes->find(*mapped) : -1;
        if (index < 0) continue; // a valid document has none
        coverage.phonemesOf[static_cast<std::size_t>(index)].push_back(phoneme);
        coverage.share[static_cast<std::size_t>(index)] += total > 0.0 ? value / total : 0.0;
    }
    for (std::size_t i = 0; i < n; ++i)
        if (coverage.phonemesOf[i].empty()) coverage.visemesWithoutPhoneme.push_back(static_cast<int>(i));
    return coverage;
}

} // namespace vl::edit
