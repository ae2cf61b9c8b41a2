#include "app/python/src/Options.h"

#include "app/python/src/Arrays.h"
#include "core/common/Error.h"

#include <pybind11/stl/filesystem.h>

namespace py = pybind11;

namespace vl::python {

void applyWeights(const py::object& weights, ReduceSettings& settings) {
    if (py::isinstance<py::str>(weights)) {
        const std::string text = weights.cast<std::string>();
        if (const auto mode = fromString<WeightMode>(text); mode && *mode != WeightMode::Painted) {
            settings.weightMode = *mode;
            return;
        }
        settings.weightMode = WeightMode::Painted;
        settings.paintedWeights = loadWeightsFile(text);
        settings.paintedWeightsSource = text;
        return;
    }
    settings.weightMode = WeightMode::Painted;
    settings.paintedWeights = valuesFrom(weights.cast<Float64Array>(), "weights");
    settings.paintedWeightsSource = "weights";
}

PhonemeVisemeMap phonemeMapFrom(const py::object& map) {
    if (!py::isinstance<py::dict>(map)) return loadPhonemeMapFile(map.cast<std::filesystem::path>());
    PhonemeVisemeMap phonemeMap;
    for (const auto& [phoneme, viseme] : map.cast<py::dict>())
        phonemeMap.entries.emplace_back(phoneme.cast<std::string>(), viseme.cast<std::string>());
    phonemeMap.origin = Provenance{"phoneme_map"};
    return phonemeMap;
}

RestChoice restChoiceFrom(const std::string& text, std::string_view where) {
    const auto choice = fromString<RestChoice>(text);
    if (!choice) throwInputError(where, "must be auto, free or key, not '" + quoteInput(text) + "'");
    return *choice;
}

} // namespace vl::python
