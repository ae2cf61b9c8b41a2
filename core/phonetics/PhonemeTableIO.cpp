#include "core/phonetics/PhonemeTableIO.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/phonetics/Arpabet.h"
#include "core/phonetics/PhonemeMaps.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace vl {

namespace {

std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

// Terminal columns a UTF-8 string takes: code points, less combining marks (n̩).
std::size_t displayWidth(std::string_view text) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c & 0xC0) == 0x80) continue;
        const bool combining =
            c == 0xCC || (c == 0xCD && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) < 0xB0);
        if (!combining) ++width;
    }
    return width;
}

std::string padRight(std::string text, std::size_t width) {
    const std::size_t have = displayWidth(text);
    if (have < width) text.append(width - have, ' ');
    return text;
}

std::string padLeft(const std::string& text, std::size_t width) {
    return text.size() < width ? std::string(width - text.size(), ' ') + text : text;
}

bool isJson(const std::filesystem::path& path) {
    return path.extension() == ".json";
}

} // namespace

std::vector<double> relativeFrequencies(const FrequencyTable& table, std::string_view where) {
    double total = 0;
    for (const auto& [phoneme, value] : table.entries) {
        if (!std::isfinite(value) || value < 0)
            throwInputError(where, "phoneme '" + phoneme + "': frequency must be a finite number >= 0");
        total += value;
    }
    if (!(total > 0)) throwInputError(where, "all phoneme frequencies are zero");
    std::vector<double> shares;
    for (const auto& [phoneme, value] : table.entries) shares.push_back(value / total);
    return shares;
}

std::string ipaOf(std::string_view phoneme) {
    const ArpabetPhoneme* arpabet = findArpabet(phoneme);
    return std::string(arpabet ? arpabet->ipa : phoneme);
}

std::string formatPhonemeTableCsv(const FrequencyTable& table) {
    const auto shares = relativeFrequencies(table, "phoneme table");
    std::string csv = "phoneme,count,frequency,ipa\n";
    for (std::size_t i = 0; i < table.entries.size(); ++i) {
        const auto& [phoneme, count] = table.entries[i];
        csv += phoneme + "," + formatDouble(count) + "," + fixed(shares[i], 6) + "," + ipaOf(phoneme) + "\n";
    }
    return csv;
}

std::string formatPhonemeTableJson(const FrequencyTable& table, const PhonemeTableInfo& info,
                                   const PhonemeVisemeMap* map) {
    relativeFrequencies(table, "phoneme table"); // refuses negative or all-zero tables
    using nlohmann::json;
    // Written by hand so that each [phoneme, count] pair and each map entry stays on one line.
    std::string text = "{\n  \"voice\": " + json(info.voice).dump() +
                       ",\n  \"source\": " + json(info.source).dump() +
                       ",\n  \"total\": " + formatDouble(table.total()) + ",\n  \"phonemes\": [";
    std::string ipa;
    for (std::size_t i = 0; i < table.entries.size(); ++i) {
        const auto& [phoneme, count] = table.entries[i];
        const std::string separator = i == 0 ? "\n    " : ",\n    ";
        text += separator + "[" + json(phoneme).dump() + ", " + formatDouble(count) + "]";
        ipa += separator + json(phoneme).dump() + ": " + json(ipaOf(phoneme)).dump();
    }
    text += "\n  ],\n  \"ipa\": {" + ipa + "\n  }";
    if (map) {
        text += ",\n  \"map\": {";
        for (std::size_t i = 0; i < map->entries.size(); ++i)
            text += (i == 0 ? "\n    " : ",\n    ") + json(map->entries[i].first).dump() + ": " +
                    json(map->entries[i].second).dump();
        text += "\n  }";
    }
    return text + "\n}\n";
}

std::string formatPhonemeTableText(const FrequencyTable& table) {
    const auto shares = relativeFrequencies(table, "phoneme table");
    std::string text = "phoneme  IPA        count  frequency\n";
    for (std::size_t i = 0; i < table.entries.size(); ++i) {
        const auto& [phoneme, count] = table.entries[i];
        text += padRight(phoneme, 9) + padRight(ipaOf(phoneme), 5) + padLeft(formatDouble(count), 11) +
                padLeft(fixed(100 * shares[i], 2) + " %", 11) + "\n";
    }
    return text;
}

void savePhonemeTable(const std::filesystem::path& path, const FrequencyTable& table,
                      const PhonemeTableInfo& info, const PhonemeVisemeMap* map) {
    const auto extension = path.extension();
    if (extension != ".csv" && extension != ".json")
        throwInputError(path.string(), "unknown table format: the file name must end in .csv or .json");
    if (map && !isJson(path))
        throwInputError(path.string(),
                        "a CSV table cannot hold the phoneme map; write .json, or keep the map "
                        "in its own file");
    writeFileAtomically(path, isJson(path) ? formatPhonemeTableJson(table, info, map)
                                           : formatPhonemeTableCsv(table));
}

FrequencyTable loadPhonemeTable(const std::filesystem::path& path) {
    FrequencySource source = loadFrequencyFile(path);
    return source.isPhonemeBased() ? std::move(source.phonemes) : std::move(source.visemeFrequencies);
}

FrequencySource loadPhonemeFrequencySource(const std::filesystem::path& tablePath,
                                           const std::filesystem::path& mapPath) {
    FrequencySource source = loadFrequencyFile(tablePath);
    if (!source.isPhonemeBased()) std::swap(source.phonemes, source.visemeFrequencies);
    if (!mapPath.empty()) source.map = loadPhonemeMapFile(mapPath);
    if (source.map.entries.empty())
        throwInputError(tablePath.string(),
                        "no phoneme -> viseme map: give a map file (assets/phonemes/map_*.csv)");
    std::vector<std::string> phonemes;
    for (const auto& [phoneme, value] : source.phonemes.entries) phonemes.push_back(phoneme);
    checkMapCovers(source.map, phonemes, (mapPath.empty() ? tablePath : mapPath).string());
    return source;
}

std::string formatPhonemeMapCsv(const PhonemeVisemeMap& map) {
    std::string csv = "phoneme,viseme\n";
    for (const auto& [phoneme, viseme] : map.entries) csv += phoneme + "," + viseme + "\n";
    return csv;
}

void savePhonemeMap(const std::filesystem::path& path, const PhonemeVisemeMap& map) {
    if (isJson(path)) {
        nlohmann::ordered_json mapping = nlohmann::ordered_json::object();
        for (const auto& [phoneme, viseme] : map.entries) mapping[phoneme] = viseme;
        writeFileAtomically(path, nlohmann::ordered_json{{"map", mapping}}.dump(2) + "\n");
        return;
    }
    writeFileAtomically(path, formatPhonemeMapCsv(map));
}

} // namespace vl
