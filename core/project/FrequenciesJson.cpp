// The "frequencies" section: direct viseme frequencies, or a phoneme table plus phoneme -> viseme map.
#include "core/common/Error.h"
#include "core/project/ProjectJson.h"

#include <set>
#include <unordered_set>

namespace vl {

namespace {

// JSON objects cannot hold a key twice: a duplicate in memory would be lost silently on save.
template <typename Entries>
void checkUniqueKeys(const Entries& entries, std::string_view path, std::string_view what) {
    std::set<std::string> seen;
    for (const auto& entry : entries)
        if (!seen.insert(entry.first).second)
            throwInputError(jsonPathAppend(path, entry.first), "duplicate " + std::string(what));
}

Json tableToJson(const FrequencyTable& table, std::string_view path, std::string_view what) {
    checkUniqueKeys(table.entries, path, what);
    Json object = Json::object();
    for (const auto& [name, value] : table.entries) object[name] = value;
    return object;
}

FrequencyTable tableFromJson(const JsonNode& node, std::string_view what) {
    FrequencyTable table;
    for (const auto& [name, value] : node.members()) {
        if (name.empty()) value.fail("empty " + std::string(what) + " name");
        table.entries.emplace_back(name, value.nonNegativeNumber());
    }
    return table;
}

} // namespace

Json frequenciesToJson(const FrequencySource& frequencies) {
    Json json = Json::object();
    // Everything present is written, so an inconsistent state fails validation instead of losing data.
    if (!frequencies.visemeFrequencies.entries.empty() || !frequencies.isPhonemeBased())
        json["visemes"] = tableToJson(frequencies.visemeFrequencies, "/frequencies/visemes", "viseme");
    if (frequencies.isPhonemeBased() || !frequencies.map.entries.empty()) {
        json["phonemes"] = tableToJson(frequencies.phonemes, "/frequencies/phonemes", "phoneme");
        checkUniqueKeys(frequencies.map.entries, "/frequencies/map", "phoneme");
        Json map = Json::object();
        for (const auto& [phoneme, viseme] : frequencies.map.entries) map[phoneme] = viseme;
        json["map"] = std::move(map);
    }
    return json;
}

FrequencySource frequenciesFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames) {
    node.allowOnly({"visemes", "phonemes", "map"});
    FrequencySource source;
    const bool direct = node.has("visemes");
    const bool phonemeBased = node.has("phonemes") || node.has("map");
    if (direct && phonemeBased) node.fail("give either \"visemes\" or \"phonemes\" with \"map\", not both");

    // Hash sets keep every check linear in the number of entries.
    const std::unordered_set<std::string_view> known(visemeNames.begin(), visemeNames.end());
    if (direct || !phonemeBased) {
        if (!direct) return source; // no frequencies yet
        const JsonNode table = node["visemes"];
        source.visemeFrequencies = tableFromJson(table, "viseme");
        for (const auto& [name, value] : source.visemeFrequencies.entries)
            if (!known.contains(name))
                throwInputError(jsonPathAppend(table.path(), name), "unknown viseme \"" + name + "\"");
        return source;
    }

    // node[...] reports the one of "phonemes" / "map" that is missing.
    const JsonNode phonemes = node["phonemes"];
    const JsonNode map = node["map"];
    source.phonemes = tableFromJson(phonemes, "phoneme");
    std::unordered_set<std::string_view> listed;
    for (const auto& entry : source.phonemes.entries) listed.insert(entry.first);
    for (const auto& [phoneme, visemeNode] : map.members()) {
        const std::string viseme = visemeNode.nonEmptyString();
        if (!listed.contains(phoneme))
            throwInputError(visemeNode.path(),
                            "phoneme \"" + phoneme + "\" is not listed in /frequencies/phonemes");
        if (!known.contains(viseme)) visemeNode.fail("unknown viseme \"" + viseme + "\"");
        source.map.entries.emplace_back(phoneme, viseme);
    }
    std::unordered_set<std::string_view> mapped;
    for (const auto& entry : source.map.entries) mapped.insert(entry.first);
    for (const auto& [phoneme, value] : source.phonemes.entries)
        if (!mapped.contains(phoneme)) map.fail("phoneme \"" + phoneme + "\" has no viseme");
    return source;
}

} // namespace vl
