#include "core/reduce/Frequencies.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace vl {

double FrequencyTable::total() const {
    double sum = 0;
    for (const auto& [name, value] : entries) sum += value;
    return sum;
}

const double* FrequencyTable::find(std::string_view name) const {
    for (const auto& [key, value] : entries)
        if (key == name) return &value;
    return nullptr;
}

const std::string* PhonemeVisemeMap::visemeOf(std::string_view phoneme) const {
    for (const auto& [key, viseme] : entries)
        if (key == phoneme) return &viseme;
    return nullptr;
}

namespace {

// Splits a CSV line on commas (or semicolons/tabs), trimming fields; no quoting is needed for our names.
std::vector<std::string> csvFields(std::string_view line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= line.size(); ++i) {
        if (i == line.size() || line[i] == ',' || line[i] == ';' || line[i] == '\t') {
            fields.emplace_back(trim(line.substr(start, i - start)));
            start = i + 1;
        }
    }
    return fields;
}

bool looksNumeric(std::string_view text) {
    return !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' ||
                             text[0] == '+' || text[0] == '.');
}

// Calls `row(fields, where)` for each data line of a two-or-more-column CSV; skips blank lines, '#'
// comments and a header line (a first line whose second field is not a number).
template <typename RowFn>
void forEachCsvRow(std::string_view text, std::string_view source, bool secondColumnNumeric, RowFn row) {
    std::size_t lineNumber = 0;
    bool first = true;
    std::size_t start = 0;
    while (start < text.size()) {
        auto end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const auto line = trim(text.substr(start, end - start));
        start = end + 1;
        ++lineNumber;
        if (line.empty() || line[0] == '#') continue;
        const auto fields = csvFields(line);
        const std::string where = fileLine(source, lineNumber);
        if (fields.size() < 2)
            throwInputError(where, "expected two comma-separated columns, found '" + std::string(line) + "'");
        const bool header =
            first && (secondColumnNumeric ? !looksNumeric(fields[1]) : fields[0] == "phoneme");
        first = false;
        if (header) continue;
        if (fields[0].empty()) throwInputError(where, "empty name in first column");
        row(fields, where);
    }
}

void checkFrequency(double value, const std::string& where) {
    if (!std::isfinite(value) || value < 0) throwInputError(where, "frequency must be a finite number >= 0");
}

void addEntry(FrequencyTable& table, std::string name, double value, const std::string& where) {
    checkFrequency(value, where);
    if (table.find(name)) throwInputError(where, "'" + name + "' is listed twice");
    table.entries.emplace_back(std::move(name), value);
}

FrequencyTable tableFromJson(const nlohmann::ordered_json& node, const std::string& where) {
    FrequencyTable table;
    if (node.is_object()) {
        for (const auto& [key, value] : node.items()) {
            const std::string path = where + "/" + key;
            if (!value.is_number())
                throwInputError(path, "expected a non-negative number, found " + value.dump());
            addEntry(table, key, value.get<double>(), path);
        }
    } else if (node.is_array()) { // [[name, f], ...] keeps the file's order
        for (std::size_t i = 0; i < node.size(); ++i) {
            const auto& item = node[i];
            const std::string path = where + "/" + std::to_string(i);
            if (!item.is_array() || item.size() != 2 || !item[0].is_string() || !item[1].is_number())
                throwInputError(path, "expected [\"name\", number], found " + item.dump());
            addEntry(table, item[0].get<std::string>(), item[1].get<double>(), path);
        }
    } else {
        throwInputError(where, "expected an object or an array of [name, frequency] pairs");
    }
    return table;
}

PhonemeVisemeMap mapFromJson(const nlohmann::ordered_json& node, const std::string& where) {
    if (!node.is_object()) throwInputError(where, "expected an object {\"phoneme\": \"viseme\", ...}");
    PhonemeVisemeMap map;
    for (const auto& [key, value] : node.items()) {
        if (!value.is_string())
            throwInputError(where + "/" + key, "expected a viseme name, found " + value.dump());
        map.entries.emplace_back(key, value.get<std::string>());
    }
    return map;
}

nlohmann::ordered_json parseJsonFile(const std::string& text, const std::string& source) {
    try {
        return nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throwInputError(source, std::string("invalid JSON: ") + e.what());
    }
}

} // namespace

FrequencyTable parseFrequencyCsv(std::string_view text, std::string_view source) {
    FrequencyTable table;
    forEachCsvRow(text, source, true, [&](const std::vector<std::string>& fields, const std::string& where) {
        addEntry(table, fields[0], parseFiniteDouble(fields[1], where), where);
    });
    if (table.entries.empty()) throwInputError(source, "no frequencies in file");
    return table;
}

FrequencySource loadFrequencyFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (trim(text).empty()) throwInputError(source, "empty frequency file");
    FrequencySource result;
    if (path.extension() != ".json") {
        result.visemeFrequencies = parseFrequencyCsv(text, source);
        return result;
    }
    const auto doc = parseJsonFile(text, source);
    if (!doc.is_object()) throwInputError(source, "expected a JSON object");
    if (doc.contains("phonemes")) {
        result.phonemes = tableFromJson(doc["phonemes"], source + ":/phonemes");
        if (doc.contains("map")) result.map = mapFromJson(doc["map"], source + ":/map");
        if (result.phonemes.entries.empty()) throwInputError(source + ":/phonemes", "no phonemes listed");
    } else {
        result.visemeFrequencies = tableFromJson(doc.contains("visemes") ? doc["visemes"] : doc,
                                                 source + (doc.contains("visemes") ? ":/visemes" : ":"));
        if (result.visemeFrequencies.entries.empty()) throwInputError(source, "no frequencies listed");
    }
    return result;
}

PhonemeVisemeMap loadPhonemeMapFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (trim(text).empty()) throwInputError(source, "empty phoneme map file");
    if (path.extension() == ".json") {
        const auto doc = parseJsonFile(text, source);
        return mapFromJson(doc.contains("map") ? doc["map"] : doc,
                           source + ":" + (doc.contains("map") ? "/map" : ""));
    }
    PhonemeVisemeMap map;
    forEachCsvRow(text, source, false, [&](const std::vector<std::string>& fields, const std::string& where) {
        if (map.visemeOf(fields[0])) throwInputError(where, "phoneme '" + fields[0] + "' is mapped twice");
        if (fields[1].empty()) throwInputError(where, "phoneme '" + fields[0] + "' has an empty viseme name");
        map.entries.emplace_back(fields[0], fields[1]);
    });
    if (map.entries.empty()) throwInputError(source, "no phoneme -> viseme entries in file");
    return map;
}

std::vector<double> visemeFrequencies(const FrequencySource& source,
                                      const std::vector<std::string>& visemeNames, std::string_view where) {
    const std::string place(where);
    std::vector<double> freq(visemeNames.size(), 0.0);
    auto indexOf = [&](const std::string& name) -> int {
        for (std::size_t i = 0; i < visemeNames.size(); ++i)
            if (visemeNames[i] == name) return static_cast<int>(i);
        return -1;
    };
    if (source.isPhonemeBased()) {
        std::string unmapped;
        for (const auto& [phoneme, value] : source.phonemes.entries) {
            checkFrequency(value, place + ": phoneme '" + phoneme + "'");
            const std::string* viseme = source.map.visemeOf(phoneme);
            if (!viseme) {
                unmapped += (unmapped.empty() ? "" : ", ") + phoneme;
                continue;
            }
            const int index = indexOf(*viseme);
            if (index < 0)
                throwInputError(place, "phoneme '" + phoneme + "' maps to viseme '" + *viseme +
                                           "', which is not in the viseme set");
            freq[static_cast<std::size_t>(index)] += value;
        }
        if (!unmapped.empty()) throwInputError(place, "phonemes not mapped to any viseme: " + unmapped);
    } else {
        for (const auto& [name, value] : source.visemeFrequencies.entries) {
            checkFrequency(value, place + ": viseme '" + name + "'");
            const int index = indexOf(name);
            if (index < 0) throwInputError(place, "frequency given for unknown viseme '" + name + "'");
            freq[static_cast<std::size_t>(index)] = value;
        }
        for (std::size_t i = 0; i < visemeNames.size(); ++i)
            if (!source.visemeFrequencies.find(visemeNames[i]))
                throwInputError(place, "no frequency given for viseme '" + visemeNames[i] + "'");
    }
    double total = 0;
    for (const double f : freq) total += f;
    if (!(total > 0)) throwInputError(place, "all viseme frequencies are zero");
    for (double& f : freq) f /= total;
    return freq;
}

} // namespace vl
