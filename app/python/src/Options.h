#pragma once
// Options the Python functions share, read from Python values into the core's settings.
#include "core/reduce/ReduceRun.h"

#include <pybind11/pybind11.h>

namespace vl::python {

// Weights: "uniform", "area", a file of painted weights, or an array of one weight per vertex.
void applyWeights(const pybind11::object& weights, ReduceSettings& settings);

// A phoneme -> viseme map: a file (CSV or JSON) or a dict {phoneme: viseme}.
PhonemeVisemeMap phonemeMapFrom(const pybind11::object& map);

// The rest model by name (auto, free, key); InputError naming `where` otherwise.
RestChoice restChoiceFrom(const std::string& text, std::string_view where);

} // namespace vl::python
