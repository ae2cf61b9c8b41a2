#pragma once
// Phoneme frequency tables on disk, in the formats core/reduce/Frequencies reads:
//   CSV   "phoneme,count,frequency,ipa" with a header; the reducer's CSV reader takes the first
//         two columns (phoneme, count), the others are for people.
//   JSON  {"voice": ..., "source": ..., "total": N, "phonemes": [["AH", 1234], ...],
//          "ipa": {"AH": "ʌ", ...}, "map": {"AH": "aa", ...}}   ("map" optional)
// A JSON table with a map is what `visemelab reduce --freq-file` takes on its own.
#include "core/reduce/Frequencies.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct PhonemeTableInfo {
    std::string voice;  // espeak-ng voice that transcribed the corpus
    std::string source; // what was counted (file name, citation)
};

// Each entry's share of the total. Throws InputError at `where` for a negative or non-finite
// value (naming the phoneme) or an all-zero table.
std::vector<double> relativeFrequencies(const FrequencyTable& table, std::string_view where);

// IPA of a phoneme: the ARPAbet table's for the 39, the name itself otherwise (IPA tables).
std::string ipaOf(std::string_view phoneme);

std::string formatPhonemeTableCsv(const FrequencyTable& table);
std::string formatPhonemeTableJson(const FrequencyTable& table, const PhonemeTableInfo& info,
                                   const PhonemeVisemeMap* map = nullptr);
// Aligned columns phoneme, IPA, count, relative frequency (%) for a terminal.
std::string formatPhonemeTableText(const FrequencyTable& table);

// Writes CSV or JSON by the extension (.csv / .json), atomically. A map needs JSON.
void savePhonemeTable(const std::filesystem::path& path, const FrequencyTable& table,
                      const PhonemeTableInfo& info, const PhonemeVisemeMap* map = nullptr);

// Reads a table written by savePhonemeTable (or any "phoneme,frequency" CSV / phoneme JSON).
FrequencyTable loadPhonemeTable(const std::filesystem::path& path);

// A phoneme table plus a separate phoneme -> viseme map file, ready for visemeFrequencies().
// When `mapPath` is empty the table file must be a JSON table that holds its map.
FrequencySource loadPhonemeFrequencySource(const std::filesystem::path& tablePath,
                                           const std::filesystem::path& mapPath);

// The map as CSV "phoneme,viseme" with a header, and its atomic save (the editor's map editor).
std::string formatPhonemeMapCsv(const PhonemeVisemeMap& map);
void savePhonemeMap(const std::filesystem::path& path, const PhonemeVisemeMap& map);

} // namespace vl
