#include "core/reduce/Weights.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <cmath>

namespace vl {

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

std::vector<double> weightsForPainting(WeightMode mode, const MeshData& neutral,
                                       const std::vector<double>& painted) {
    if (mode == WeightMode::Painted && painted.size() == neutral.positions.size()) return painted;
    std::vector<double> weights =
        computeWeights(mode == WeightMode::Painted ? WeightMode::Uniform : mode, neutral);
    const double largest = *std::max_element(weights.begin(), weights.end());
    for (double& w : weights) w /= largest; // validated: finite, >= 0, not all zero
    return weights;
}

// A painted weight at `where`: finite (the readers already refuse NaN/Inf) and not negative.
static double checkedWeight(double value, const std::string& where) {
    if (value < 0)
        throwInputError(where, "weight " + formatDouble(value) + " is negative; weights must be >= 0");
    return value;
}

static std::vector<double> weightsFromJson(const Json& doc, const std::string& source) {
    const Json* array = &doc;
    std::string path;
    if (doc.is_object()) {
        if (!doc.contains("weights")) throwInputError(source + ":/", "JSON object has no \"weights\" array");
        array = &doc["weights"];
        path = "/weights";
    }
    if (!array->is_array())
        throwInputError(source + ":" + (path.empty() ? "/" : path),
                        "expected an array of numbers, found " + jsonTypeName(*array));
    std::vector<double> weights;
    weights.reserve(array->size());
    for (std::size_t i = 0; i < array->size(); ++i) {
        const auto& value = (*array)[i];
        const std::string where = source + ":" + jsonPathAppend(path, i);
        if (!value.is_number()) throwInputError(where, "expected a number, found " + jsonTypeName(value));
        weights.push_back(checkedWeight(value.get<double>(), where));
    }
    return weights;
}

std::vector<double> loadWeightsFile(const std::filesystem::path& path) {
    const std::string text = readFileToString(path);
    const std::string source = path.string();
    if (isBlankText(text)) throwInputError(source, "empty weights file");
    if (path.extension() == ".json")
        return weightsFromJson(parseJsonStrict(stripUtf8Bom(text), source), source);
    // Plain text: numbers separated by newlines, commas or spaces; '#' starts a comment.
    const std::string_view body = stripUtf8Bom(text);
    std::vector<double> weights;
    std::size_t lineNumber = 0;
    std::size_t start = 0;
    while (start <= body.size()) {
        const auto end = std::min(body.find('\n', start), body.size());
        std::string line(body.substr(start, end - start));
        ++lineNumber;
        start = end + 1;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        for (auto& c : line)
            if (c == ',' || c == ';') c = ' ';
        const std::string where = fileLine(source, lineNumber);
        for (const auto token : splitWhitespace(line))
            weights.push_back(checkedWeight(parseFiniteDouble(token, where), where));
        if (end == body.size()) break;
    }
    if (weights.empty()) throwInputError(source, "no weights in file");
    return weights;
}

} // namespace vl
