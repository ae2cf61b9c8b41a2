#pragma once
// Checks of phoneme -> viseme maps against a phoneme inventory or table, and the maps bundled in
// assets/phonemes/ (docs/phonemes.md describes each).
#include "core/reduce/Frequencies.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// Throws InputError at `where` listing, in one message, every phoneme of `phonemes` the map
// does not map.
void checkMapCovers(const PhonemeVisemeMap& map, std::span<const std::string> phonemes,
                    std::string_view where);

// Throws InputError at `where` listing every viseme the map names that is not in `visemeNames`.
void checkMapVisemes(const PhonemeVisemeMap& map, std::span<const std::string> visemeNames,
                     std::string_view where);

// An ARPAbet map must map all 39 phonemes and nothing else but sil, the pause (a key outside the
// inventory is a typo).
void checkArpabetMap(const PhonemeVisemeMap& map, std::string_view where);

// The distinct viseme names of a map, in order of first appearance.
std::vector<std::string> mapVisemeNames(const PhonemeVisemeMap& map);

struct BundledPhonemeMap {
    std::string id;    // "oculus", "mpeg4", "rhubarb", "sample-face"
    std::string title; // for a menu
    std::filesystem::path file;
};

// The bundled maps under <assetsDir>/phonemes/.
std::vector<BundledPhonemeMap> bundledPhonemeMaps(const std::filesystem::path& assetsDir);

// The bundled American English phoneme frequency table (CSV).
std::filesystem::path defaultPhonemeTablePath(const std::filesystem::path& assetsDir);

// That table with the bundled map `mapId` (throws InputError for an unknown id).
FrequencySource bundledPhonemeFrequencies(const std::filesystem::path& assetsDir, const std::string& mapId);

} // namespace vl
