#pragma once
// Viseme frequencies f_i: given directly, or derived from a phoneme frequency table and a
// phoneme -> viseme map (a viseme's frequency is the sum of its phonemes').
#include "core/common/Provenance.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vl {

// Ordered (name, value) pairs; order is kept for display and output.
struct FrequencyTable {
    std::vector<std::pair<std::string, double>> entries;
    double total() const;
    const double* find(std::string_view name) const;
    bool operator==(const FrequencyTable&) const = default;
};

// phoneme -> viseme name, in table order.
struct PhonemeVisemeMap {
    std::vector<std::pair<std::string, std::string>> entries;
    Provenance origin; // the file (or project JSON path) it was read from, for messages
    const std::string* visemeOf(std::string_view phoneme) const;
    bool operator==(const PhonemeVisemeMap&) const = default;
};

// What a frequency file holds: either viseme frequencies directly, or a phoneme table plus a map.
struct FrequencySource {
    FrequencyTable visemeFrequencies; // used when phonemes is empty
    FrequencyTable phonemes;
    PhonemeVisemeMap map;
    Provenance origin; // the file (or project JSON path) it was read from, for messages
    bool isPhonemeBased() const { return !phonemes.entries.empty(); }
    bool operator==(const FrequencySource&) const = default;
};

// CSV "name,frequency" lines (a header line and '#' comments allowed) or JSON: either
// {"name": f, ...}, or {"phonemes": {...} | [[p,f],...], "map": {"phoneme": "viseme", ...}}.
// Negative, NaN, overflowing (1e999) or non-numeric values and names listed twice are errors
// naming file and line / JSON path. Duplicate checks take linear time however long the table.
FrequencySource loadFrequencyFile(const std::filesystem::path& path);
FrequencyTable parseFrequencyCsv(std::string_view text, std::string_view source);
PhonemeVisemeMap loadPhonemeMapFile(const std::filesystem::path& path); // CSV "phoneme,viseme" or JSON object

// The table as CSV: "viseme,frequency" lines, or for a phoneme table "phoneme,frequency,viseme"
// (the map's viseme, empty when unmapped), under a header line.
std::string formatFrequencyCsv(const FrequencySource& source);

// Frequencies per viseme of `visemeNames` (same order). Direct: every viseme must be listed and
// unknown names are errors. Phoneme-based: every phoneme must be mapped to a known viseme (the
// error lists all unmapped phonemes); visemes no phoneme maps to get 0. All must be >= 0 and not
// all zero. Frequencies are normalised to sum to 1. Errors name `where`, or when it is empty the
// source's origin (the map's for mapping errors), else "frequencies".
std::vector<double> visemeFrequencies(const FrequencySource& source,
                                      const std::vector<std::string>& visemeNames,
                                      std::string_view where = {});

} // namespace vl
