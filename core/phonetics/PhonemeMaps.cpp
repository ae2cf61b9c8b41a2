#include "core/phonetics/PhonemeMaps.h"

#include "core/common/Error.h"
#include "core/phonetics/Arpabet.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "core/speech/Utterance.h"

#include <algorithm>
#include <unordered_set>

namespace vl {

namespace {

// At most 30 names, then how many more: a message stays readable for a table of any length.
std::string joinList(const std::vector<std::string>& names) {
    constexpr std::size_t kShown = 30;
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < kShown; ++i) text += (i == 0 ? "" : ", ") + names[i];
    if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
    return text;
}

} // namespace

void checkMapCovers(const PhonemeVisemeMap& map, std::span<const std::string> phonemes,
                    std::string_view where) {
    std::unordered_set<std::string_view> mapped;
    for (const auto& entry : map.entries) mapped.insert(entry.first);
    std::vector<std::string> unmapped;
    for (const auto& phoneme : phonemes)
        if (!mapped.contains(phoneme)) unmapped.push_back(phoneme);
    if (unmapped.empty()) return;
    const bool silence = std::find(unmapped.begin(), unmapped.end(), kSilencePhoneme) != unmapped.end();
    throwInputError(where, std::to_string(unmapped.size()) + " phoneme" + (unmapped.size() == 1 ? "" : "s") +
                               " not mapped to any viseme: " + joinList(unmapped) +
                               (silence ? " (sil is the pause at punctuation: map it to the viseme of "
                                          "the mouth at rest, e.g. 'sil,sil')"
                                        : ""));
}

void checkMapVisemes(const PhonemeVisemeMap& map, std::span<const std::string> visemeNames,
                     std::string_view where) {
    const std::unordered_set<std::string_view> known(visemeNames.begin(), visemeNames.end());
    std::vector<std::string> unknown;
    for (const auto& viseme : mapVisemeNames(map))
        if (!known.contains(viseme)) unknown.push_back(viseme);
    if (!unknown.empty())
        throwInputError(where, "the map names visemes that are not in the viseme set: " + joinList(unknown) +
                                   " (the set has " + joinList({visemeNames.begin(), visemeNames.end()}) +
                                   ")");
}

void checkArpabetMap(const PhonemeVisemeMap& map, std::string_view where) {
    std::vector<std::string> foreign;
    for (const auto& [phoneme, viseme] : map.entries)
        if (!findArpabet(phoneme) && phoneme != kSilencePhoneme) foreign.push_back(phoneme);
    if (!foreign.empty())
        throwInputError(where, "not ARPAbet phonemes (see docs/phonemes.md): " + joinList(foreign));
    checkMapCovers(map, arpabetSymbols(), where);
}

std::vector<std::string> mapVisemeNames(const PhonemeVisemeMap& map) {
    std::vector<std::string> names;
    std::unordered_set<std::string_view> seen;
    for (const auto& [phoneme, viseme] : map.entries)
        if (seen.insert(viseme).second) names.push_back(viseme);
    return names;
}

std::vector<BundledPhonemeMap> bundledPhonemeMaps(const std::filesystem::path& assetsDir) {
    const auto dir = assetsDir / "phonemes";
    return {
        {"oculus", "Oculus / Meta 15 visemes", dir / "map_oculus.csv"},
        {"mpeg4", "MPEG-4 FBA visemes (15 incl. none)", dir / "map_mpeg4.csv"},
        {"rhubarb", "Preston Blair / Rhubarb mouth shapes A-H, X", dir / "map_rhubarb.csv"},
        {"sample-face", "Bundled sample face (Oculus names)", dir / "map_sample_face.csv"},
    };
}

std::filesystem::path defaultPhonemeTablePath(const std::filesystem::path& assetsDir) {
    return assetsDir / "phonemes" / "en-us_frequencies.csv";
}

FrequencySource bundledPhonemeFrequencies(const std::filesystem::path& assetsDir, const std::string& mapId) {
    for (const BundledPhonemeMap& map : bundledPhonemeMaps(assetsDir))
        if (map.id == mapId) return loadPhonemeFrequencySource(defaultPhonemeTablePath(assetsDir), map.file);
    throwInputError("phoneme map", "no bundled map '" + mapId + "'");
}

} // namespace vl
