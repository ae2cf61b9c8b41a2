#include "core/reduce/Weights.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace vl {

const char* toString(WeightMode mode) {
    switch (mode) {
    case WeightMode::Uniform:
        return "uniform";
    case WeightMode::Area:
        return "area";
    case WeightMode::Painted:
        return "painted";
    }
    return "uniform";
}

std::optional<WeightMode> weightModeFromString(std::string_view text) {
    if (text == "uniform") return WeightMode::Uniform;
    if (text == "area") return WeightMode::Area;
    if (text == "painted") return WeightMode::Painted;
    return std::nullopt;
}

static void validateWeights(const std::vector<double>& weights, std::size_t vertexCount,
                            std::string_view where) {
    if (weights.size() != vertexCount)
        throwInputError(where, std::to_string(weights.size()) + " weights for a mesh of " +
                                   std::to_string(vertexCount) + " vertices");
    bool anyPositive = false;
    for (std::size_t k = 0; k < weights.size(); ++k) {
        if (!std::isfinite(weights[k]) || weights[k] < 0)
            throwInputError(where, "weight of vertex " + std::to_string(k) + " is " +
                                       formatDouble(weights[k]) + "; weights must be finite and >= 0");
        anyPositive |= weights[k] > 0;
    }
    if (!anyPositive) throwInputError(where, "all weights are zero");
}

std::vector<double> computeWeights(WeightMode mode, const MeshData& neutral,
                                   const std::vector<double>& painted, std::string_view where) {
    std::vector<double> weights;
    switch (mode) {
    case WeightMode::Uniform:
        weights.assign(neutral.positions.size(), 1.0);
        break;
    case WeightMode::Area:
        weights = vertexAreas(neutral.positions, neutral.triangles);
        break;
    case WeightMode::Painted:
        weights = painted;
        break;
    }
    validateWeights(weights, neutral.positions.size(), where);
    return weights;
}

static std::vector<double> weightsFromJson(const nlohmann::json& doc, const std::string& source) {
    const nlohmann::json* array = &doc;
    std::string path;
    if (doc.is_object()) {
        if (!doc.contains("weights")) throwInputError(source, "JSON object has no \"weights\" array");
        array = &doc["weights"];
        path = "/weights";
    }
    if (!array->is_array())
        throwInputError(source + ":" + (path.empty() ? "/" : path), "expected an array of numbers");
    std::vector<double> weights;
    weights.reserve(array->size());
    for (std::size_t i = 0; i < array->size(); ++i) {
        const auto& value = (*array)[i];
        if (!value.is_number())
            throwInputError(source + ":" + path + "/" + std::to_string(i),
                            "expected a number, found " + value.dump());
        weights.push_back(value.get<double>());
    }
    return weights;
}

std::vector<double> loadWeightsFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (trim(text).empty()) throwInputError(source, "empty weights file");
    if (path.extension() == ".json") {
        nlohmann::json doc;
        try {
            doc = nlohmann::json::parse(text);
        } catch (const nlohmann::json::parse_error& e) {
            throwInputError(source, std::string("invalid JSON: ") + e.what());
        }
        return weightsFromJson(doc, source);
    }
    // Plain text: numbers separated by newlines, commas or spaces; '#' starts a comment.
    std::vector<double> weights;
    std::size_t lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        std::string line(text.substr(start, end - start));
        ++lineNumber;
        start = end + 1;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        for (auto& c : line)
            if (c == ',' || c == ';') c = ' ';
        for (const auto token : splitWhitespace(line))
            weights.push_back(parseFiniteDouble(token, fileLine(source, lineNumber)));
        if (end == text.size()) break;
    }
    return weights;
}

} // namespace vl
