#include "core/reduce/Frequencies.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/common/TextParsing.h"

#include <cmath>
#include <unordered_map>
#include <unordered_set>

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
    text = stripUtf8Bom(text);
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
            throwInputError(where, "expected two comma-separated columns, found '" + quoteInput(line) + "'");
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

// Builds a table while refusing a name listed twice (a hash set: linear time for any length).
class TableBuilder {
  public:
    void add(std::string name, double value, const std::string& where) {
        checkFrequency(value, where);
        if (name.empty()) throwInputError(where, "empty name");
        if (!seen_.insert(name).second) throwInputError(where, "'" + quoteInput(name) + "' is listed twice");
        table_.entries.emplace_back(std::move(name), value);
    }
    FrequencyTable take() { return std::move(table_); }

  private:
    FrequencyTable table_;
    std::unordered_set<std::string> seen_;
};

// "file:/path" for messages about a JSON element of a file.
std::string jsonWhere(const std::string& source, std::string_view path) {
    return source + ":" + std::string(path.empty() ? "/" : path);
}

FrequencyTable tableFromJson(const Json& node, const std::string& source, const std::string& path) {
    TableBuilder table;
    if (node.is_object()) {
        for (const auto& [key, value] : node.items()) {
            const std::string where = jsonWhere(source, jsonPathAppend(path, key));
            if (!value.is_number())
                throwInputError(where, "expected a non-negative number, found " + quoteJson(value));
            table.add(key, value.get<double>(), where);
        }
    } else if (node.is_array()) { // [[name, f], ...] keeps the file's order
        for (std::size_t i = 0; i < node.size(); ++i) {
            const auto& item = node[i];
            const std::string where = jsonWhere(source, jsonPathAppend(path, i));
            if (!item.is_array() || item.size() != 2 || !item[0].is_string() || !item[1].is_number())
                throwInputError(where, "expected [\"name\", number], found " + jsonTypeName(item));
            table.add(item[0].get<std::string>(), item[1].get<double>(), where);
        }
    } else {
        throwInputError(jsonWhere(source, path), "expected an object or an array of [name, frequency] pairs");
    }
    return table.take();
}

PhonemeVisemeMap mapFromJson(const Json& node, const std::string& source, const std::string& path) {
    if (!node.is_object())
        throwInputError(jsonWhere(source, path), "expected an object {\"phoneme\": \"viseme\", ...}");
    PhonemeVisemeMap map;
    map.origin.text = jsonWhere(source, path);
    for (const auto& [key, value] : node.items()) {
        const std::string where = jsonWhere(source, jsonPathAppend(path, key));
        if (!value.is_string() || value.get_ref<const std::string&>().empty())
            throwInputError(where,
                            "expected a viseme name, found " +
                                (value.is_string() ? std::string("an empty string") : jsonTypeName(value)));
        if (key.empty()) throwInputError(where, "empty phoneme name");
        map.entries.emplace_back(key, value.get<std::string>());
    }
    return map;
}

} // namespace

FrequencyTable parseFrequencyCsv(std::string_view text, std::string_view source) {
    TableBuilder builder;
    forEachCsvRow(text, source, true, [&](const std::vector<std::string>& fields, const std::string& where) {
        builder.add(fields[0], parseFiniteDouble(fields[1], where), where);
    });
    FrequencyTable table = builder.take();
    if (table.entries.empty()) throwInputError(source, "no frequencies in file");
    return table;
}

FrequencySource loadFrequencyFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (isBlankText(text)) throwInputError(source, "empty frequency file");
    FrequencySource result;
    result.origin.text = source;
    if (path.extension() != ".json") {
        result.visemeFrequencies = parseFrequencyCsv(text, source);
        return result;
    }
    const Json doc = parseJsonStrict(stripUtf8Bom(text), source);
    if (!doc.is_object()) throwInputError(source, "expected a JSON object, found " + jsonTypeName(doc));
    if (doc.contains("phonemes")) {
        result.phonemes = tableFromJson(doc["phonemes"], source, "/phonemes");
        if (doc.contains("map")) result.map = mapFromJson(doc["map"], source, "/map");
        if (result.phonemes.entries.empty()) throwInputError(source + ":/phonemes", "no phonemes listed");
    } else {
        const bool nested = doc.contains("visemes");
        result.visemeFrequencies =
            tableFromJson(nested ? doc["visemes"] : doc, source, nested ? "/visemes" : "");
        if (result.visemeFrequencies.entries.empty()) throwInputError(source, "no frequencies listed");
    }
    return result;
}

PhonemeVisemeMap loadPhonemeMapFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (isBlankText(text)) throwInputError(source, "empty phoneme map file");
    if (path.extension() == ".json") {
        const Json doc = parseJsonStrict(stripUtf8Bom(text), source);
        const bool nested = doc.is_object() && doc.contains("map");
        PhonemeVisemeMap map = mapFromJson(nested ? doc["map"] : doc, source, nested ? "/map" : "");
        if (map.entries.empty()) throwInputError(map.origin.text, "no phoneme -> viseme entries");
        return map;
    }
    PhonemeVisemeMap map;
    map.origin.text = source;
    std::unordered_set<std::string> mapped;
    forEachCsvRow(text, source, false, [&](const std::vector<std::string>& fields, const std::string& where) {
        if (!mapped.insert(fields[0]).second)
            throwInputError(where, "phoneme '" + quoteInput(fields[0]) + "' is mapped twice");
        if (fields[1].empty())
            throwInputError(where, "phoneme '" + quoteInput(fields[0]) + "' has an empty viseme name");
        map.entries.emplace_back(fields[0], fields[1]);
    });
    if (map.entries.empty()) throwInputError(source, "no phoneme -> viseme entries in file");
    return map;
}

std::vector<double> visemeFrequencies(const FrequencySource& source,
                                      const std::vector<std::string>& visemeNames, std::string_view where) {
    const auto placeOr = [&](const std::string& origin) {
        return std::string(!where.empty()    ? where
                           : !origin.empty() ? std::string_view(origin)
                                             : "frequencies");
    };
    const std::string place = placeOr(source.origin.text);
    std::unordered_map<std::string_view, std::size_t> indexOf;
    for (std::size_t i = 0; i < visemeNames.size(); ++i) indexOf.emplace(visemeNames[i], i);
    std::vector<double> freq(visemeNames.size(), 0.0);
    if (source.isPhonemeBased()) {
        std::unordered_map<std::string_view, const std::string*> visemeOfPhoneme;
        for (const auto& [phoneme, viseme] : source.map.entries) visemeOfPhoneme.emplace(phoneme, &viseme);
        const std::string mapPlace =
            placeOr(source.map.origin.text.empty() ? source.origin.text : source.map.origin.text);
        std::string unmapped;
        for (const auto& [phoneme, value] : source.phonemes.entries) {
            checkFrequency(value, place + ": phoneme '" + quoteInput(phoneme) + "'");
            const auto mapped = visemeOfPhoneme.find(phoneme);
            if (mapped == visemeOfPhoneme.end()) {
                unmapped += (unmapped.empty() ? "" : ", ") + phoneme;
                continue;
            }
            const auto index = indexOf.find(*mapped->second);
            if (index == indexOf.end())
                throwInputError(mapPlace, "phoneme '" + quoteInput(phoneme) + "' maps to viseme '" +
                                              *mapped->second + "', which is not in the viseme set");
            freq[index->second] += value;
        }
        if (!unmapped.empty()) throwInputError(mapPlace, "phonemes not mapped to any viseme: " + unmapped);
    } else {
        std::vector<bool> given(visemeNames.size(), false);
        for (const auto& [name, value] : source.visemeFrequencies.entries) {
            checkFrequency(value, place + ": viseme '" + quoteInput(name) + "'");
            const auto index = indexOf.find(name);
            if (index == indexOf.end())
                throwInputError(place, "frequency given for unknown viseme '" + quoteInput(name) + "'");
            freq[index->second] = value;
            given[index->second] = true;
        }
        for (std::size_t i = 0; i < visemeNames.size(); ++i)
            if (!given[i])
                throwInputError(place, "no frequency given for viseme '" + quoteInput(visemeNames[i]) + "'");
    }
    double total = 0;
    for (const double f : freq) total += f;
    if (!(total > 0)) throwInputError(place, "all viseme frequencies are zero");
    for (double& f : freq) f /= total;
    return freq;
}

std::string formatFrequencyCsv(const FrequencySource& source) {
    std::string text;
    if (source.isPhonemeBased()) {
        text = "phoneme,frequency,viseme\n";
        for (const auto& [phoneme, f] : source.phonemes.entries) {
            const std::string* viseme = source.map.visemeOf(phoneme);
            text += phoneme + "," + formatDouble(f) + "," + (viseme ? *viseme : std::string()) + "\n";
        }
    } else {
        text = "viseme,frequency\n";
        for (const auto& [name, f] : source.visemeFrequencies.entries)
            text += name + "," + formatDouble(f) + "\n";
    }
    return text;
}

} // namespace vl
