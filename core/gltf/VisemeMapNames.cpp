#include "core/gltf/VisemeMapNames.h"

#include "core/gltf/AvatarScan.h"
#include "core/gltf/TargetNames.h"

#include <algorithm>
#include <utility>

namespace vl {
namespace {

using Translation = std::optional<std::string> (*)(std::string_view);

// The set's name for `name`: itself, else the viseme with the same join key.
std::optional<std::string> setNameOf(const std::string& name, const std::vector<std::string>& visemes) {
    if (std::find(visemes.begin(), visemes.end(), name) != visemes.end()) return name;
    const std::string key = visemeJoinKey(name);
    for (const std::string& viseme : visemes)
        if (visemeJoinKey(viseme) == key) return viseme;
    return std::nullopt;
}

bool everyNameTranslates(const PhonemeVisemeMap& map, Translation translation) {
    return !map.entries.empty() && std::all_of(map.entries.begin(), map.entries.end(), [&](const auto& e) {
        return translation(e.second).has_value();
    });
}

std::optional<std::string>
lookUp(std::string_view name, std::initializer_list<std::pair<std::string_view, std::string_view>> table) {
    for (const auto& [from, to] : table)
        if (from == name) return std::string(to);
    return std::nullopt;
}

} // namespace

std::optional<std::string> oculusVisemeOfRhubarbShape(std::string_view shape) {
    // docs of Rhubarb Lip Sync, "Mouth shapes": A closed (M B P), B clenched teeth (K S T EE),
    // C open (EH AE), D wide open (AA), E slightly rounded (AO ER), F puckered (UW OW W),
    // G upper teeth on lower lip (F V), H long L, X idle.
    return lookUp(shape, {{"A", "PP"},
                          {"B", "SS"},
                          {"C", "E"},
                          {"D", "aa"},
                          {"E", "oh"},
                          {"F", "ou"},
                          {"G", "FF"},
                          {"H", "nn"},
                          {"X", "sil"}});
}

std::optional<std::string> oculusVisemeOfMpeg4(std::string_view name) {
    // The Oculus visemes are MPEG-4's; only the spelling differs.
    return lookUp(name, {{"none", "sil"},
                         {"p_b_m", "PP"},
                         {"f_v", "FF"},
                         {"T_D", "TH"},
                         {"t_d", "DD"},
                         {"k_g", "kk"},
                         {"tS_dZ_S", "CH"},
                         {"s_z", "SS"},
                         {"n_l", "nn"},
                         {"r", "RR"},
                         {"A", "aa"},
                         {"e", "E"},
                         {"I", "ih"},
                         {"Q", "oh"},
                         {"O", "oh"},
                         {"U", "ou"}});
}

PhonemeVisemeMap mapOntoVisemes(PhonemeVisemeMap map, const std::vector<std::string>& visemes) {
    const bool direct = std::all_of(map.entries.begin(), map.entries.end(),
                                    [&](const auto& e) { return setNameOf(e.second, visemes).has_value(); });
    Translation translation = nullptr;
    if (!direct) {
        if (everyNameTranslates(map, oculusVisemeOfRhubarbShape))
            translation = oculusVisemeOfRhubarbShape;
        else if (everyNameTranslates(map, oculusVisemeOfMpeg4))
            translation = oculusVisemeOfMpeg4;
    }
    for (auto& [phoneme, viseme] : map.entries) {
        const std::string meaning = translation ? *translation(viseme) : viseme;
        if (auto name = setNameOf(meaning, visemes)) viseme = std::move(*name);
    }
    return map;
}

FrequencySource frequenciesOntoVisemes(FrequencySource source, const std::vector<std::string>& visemes) {
    for (auto& [name, value] : source.visemeFrequencies.entries)
        if (auto matched = setNameOf(name, visemes)) name = std::move(*matched);
    source.map = mapOntoVisemes(std::move(source.map), visemes);
    return source;
}

} // namespace vl
