// visemelab.VisemeSet, load_visemes and reduce_visemes: the reduction of `visemelab reduce` on arrays
// or mesh files, through the core's one reduction run (core/project/ReduceInputs.h).
#include "app/python/src/Arrays.h"
#include "app/python/src/Bindings.h"
#include "app/python/src/Options.h"
#include "core/common/Error.h"
#include "core/inspect/DistanceUnits.h"
#include "core/io/VisemeSetFiles.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/ReduceRun.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <set>

namespace py = pybind11;

namespace vl::python {

namespace {

using SetPtr = std::shared_ptr<VisemeSet>;

// Visemes given as a dict {name: (N, 3)} (its order is kept) or a sequence of (name, array) pairs.
std::vector<std::pair<std::string, Float64Array>> namedArrays(const py::object& visemes) {
    std::vector<std::pair<std::string, Float64Array>> named;
    if (py::isinstance<py::dict>(visemes)) {
        for (const auto& [name, array] : visemes.cast<py::dict>())
            named.emplace_back(name.cast<std::string>(), array.cast<Float64Array>());
    } else {
        for (const py::handle pair : visemes) {
            const auto [name, array] = pair.cast<std::pair<std::string, Float64Array>>();
            named.emplace_back(name, array);
        }
    }
    return named;
}

// The set the arrays describe, with the checks loadVisemeSet makes on files (names, n >= 2, sizes,
// values); errors name the argument ("visemes['AA']").
SetPtr setFromArrays(const Float64Array& neutral, const IndexArray& triangles, const py::object& visemes,
                     const std::optional<Float64Array>& uvs) {
    auto set = std::make_shared<VisemeSet>();
    set->neutral.positions = positionsFrom(neutral, "neutral");
    set->neutral.triangles = trianglesFrom(triangles, set->neutral.positions.size(), "triangles");
    if (uvs) {
        set->neutral.uvs = uvsFrom(*uvs, "uvs");
        if (set->neutral.uvs.size() != set->neutral.positions.size())
            throwInputError("uvs", std::to_string(set->neutral.uvs.size()) + " rows for " +
                                       std::to_string(set->neutral.positions.size()) + " vertices");
    }
    const auto named = namedArrays(visemes);
    if (named.size() < 2) throwInputError("visemes", "a viseme set needs at least 2 visemes");
    checkVisemeSetSize(named.size(), set->neutral.positions.size(), "visemes");
    std::set<std::string> seen;
    for (const auto& [name, array] : named) {
        const std::string where = "visemes['" + quoteInput(name) + "']";
        if (name.empty()) throwInputError("visemes", "a viseme has an empty name");
        if (!seen.insert(name).second) throwInputError(where, "duplicate viseme name");
        Viseme viseme{name, positionsFrom(array, where)};
        if (viseme.positions.size() != set->neutral.positions.size())
            throwInputError(where, "not interpolable: " + std::to_string(viseme.positions.size()) +
                                       " vertices, the neutral has " +
                                       std::to_string(set->neutral.positions.size()));
        set->visemes.push_back(std::move(viseme));
    }
    checkVisemeSetValues(*set, "visemes");
    return set;
}

// A folder (its neutral found by the one rule, findNeutralMesh), or a neutral file and {name: file}.
SetPtr setFromFiles(const std::optional<std::filesystem::path>& folder,
                    const std::optional<std::filesystem::path>& neutralFile, const py::object& files) {
    std::filesystem::path neutral = neutralFile.value_or(std::filesystem::path());
    std::vector<std::pair<std::string, std::filesystem::path>> named;
    if (folder) {
        if (!files.is_none()) throw py::value_error("give folder or files, not both");
        if (neutral.empty()) neutral = findNeutralMesh(*folder);
        named = listVisemeFolder(*folder, neutral);
    } else {
        if (neutral.empty() || files.is_none()) throw py::value_error("give folder, or neutral and files");
        if (py::isinstance<py::dict>(files))
            for (const auto& [name, file] : files.cast<py::dict>())
                named.emplace_back(name.cast<std::string>(), file.cast<std::filesystem::path>());
        else
            named = files.cast<std::vector<std::pair<std::string, std::filesystem::path>>>();
    }
    py::gil_scoped_release release;
    return std::make_shared<VisemeSet>(loadVisemeSet(neutral, named));
}

// Frequencies: None (equal, as `reduce` without --freq-file), a file (loadFrequencyFile), or a dict
// {viseme: f}; a phoneme_map (file or dict {phoneme: viseme}) makes the table a phoneme table.
FrequencySource frequencySource(const VisemeSet& set, const py::object& frequencies, const py::object& map) {
    FrequencySource source;
    if (frequencies.is_none()) {
        for (const auto& v : set.visemes) source.visemeFrequencies.entries.emplace_back(v.name, 1.0);
    } else if (py::isinstance<py::dict>(frequencies)) {
        for (const auto& [name, value] : frequencies.cast<py::dict>())
            source.visemeFrequencies.entries.emplace_back(name.cast<std::string>(), value.cast<double>());
        source.origin = Provenance{"frequencies"};
    } else {
        source = loadFrequencyFile(frequencies.cast<std::filesystem::path>());
    }
    if (!map.is_none()) source = withPhonemeMap(std::move(source), phonemeMapFrom(map));
    requirePhonemeMap(source, "frequencies");
    return source;
}

py::dict groupingDict(const Grouping& g, const std::vector<std::string>& names) {
    py::list groups;
    for (const auto& group : g.groups) {
        py::list members;
        for (const int i : group) members.append(names[static_cast<std::size_t>(i)]);
        groups.append(members);
    }
    py::list resting;
    for (const int i : g.rest) resting.append(names[static_cast<std::size_t>(i)]);
    py::dict d;
    d["groups"] = groups;
    d["resting"] = resting;
    d["cost"] = g.cost;
    d["lower_bound"] = g.lowerBound;
    d["optimal"] = g.optimal;
    return d;
}

py::dict outcomeDict(const ReduceOutcome& outcome) {
    py::dict d;
    const Grouping& best = outcome.result.best();
    d["visemes"] = outcome.visemeNames;
    d["frequencies"] = toArray(outcome.frequencies);
    d["weights"] = toArray(outcome.weights);
    const py::dict bestDict = groupingDict(best, outcome.visemeNames);
    d["groups"] = bestDict["groups"];
    d["resting"] = bestDict["resting"];
    d["cost"] = best.cost;
    d["optimal"] = best.optimal;
    d["group_of"] = outcome.result.groupOf();
    // The cost curve: the optimal (or best found) cost for p = 1..m keys.
    py::list curve, costs;
    for (const Grouping& g : outcome.result.curve) {
        curve.append(groupingDict(g, outcome.visemeNames));
        costs.append(g.cost);
    }
    d["cost_curve"] = costs;
    d["curve"] = curve;
    d["method"] = toString(outcome.result.method);
    d["rest_free"] = outcome.result.restFree;
    d["rest_viseme"] = outcome.restViseme;
    d["closure_viseme"] = outcome.closureViseme;
    py::list keys;
    for (const KeyMesh& key : outcome.model.keys) {
        py::dict k;
        k["name"] = key.name;
        k["members"] = key.members;
        k["frequency"] = key.frequency;
        k["positions"] = toArray(key.positions);
        keys.append(k);
    }
    d["keys"] = keys;
    d["neutral"] = toArray(outcome.model.neutral.positions);
    d["triangles"] = toArray(outcome.model.neutral.triangles);
    py::dict phonemeToKey;
    for (const auto& [phoneme, key] : outcome.model.phonemeToKey) phonemeToKey[py::str(phoneme)] = key;
    d["phoneme_to_key"] = phonemeToKey;
    if (outcome.maxError) {
        py::dict m;
        m["limit_mm"] = outcome.maxError->limitMm;
        m["keys"] = outcome.maxError->keys;
        m["certified"] = outcome.maxError->certified;
        d["max_error"] = m;
    }
    return d;
}

py::dict reduceVisemeSet(const SetPtr& set, int m, const py::object& frequencies, const py::object& map,
                         const py::object& weights, const std::vector<std::string>& pin,
                         const std::vector<std::pair<std::string, std::string>>& apart,
                         const std::vector<std::pair<std::string, std::string>>& together,
                         const std::string& rest, const std::string& restViseme, const std::string& closure,
                         double maxErrorMm, double timeLimit, const std::string& method) {
    if ((m > 0) == (maxErrorMm > 0)) throw py::value_error("give m (1..n) or max_error_mm, not both");
    if (!(timeLimit >= 0)) throw py::value_error("time_limit must be >= 0 seconds (0: no limit)");
    ReduceInputs inputs;
    inputs.set = set;
    inputs.frequencies = frequencySource(*set, frequencies, map);
    ReduceSettings& settings = inputs.settings;
    settings.target = m;
    applyWeights(weights, settings);
    settings.constraints = ConstraintNames{pin, apart, together};
    settings.constraintsSource = "pin/apart/together";
    settings.rest = restChoiceFrom(rest, "rest");
    settings.restViseme = restViseme;
    settings.restVisemeSource = "rest_viseme";
    settings.closure = closure;
    settings.maxErrorMm = maxErrorMm;
    settings.options.method = parseEnum<ReductionMethod>(method, "method");
    settings.millimetresPerUnit = guessMillimetresPerUnit(set->neutral.positions);
    ReduceOutcome outcome;
    {
        py::gil_scoped_release release;
        outcome = reduce(inputs, ReducePolicy::batch(timeLimit));
    }
    return outcomeDict(outcome);
}

py::dict visemesOf(const VisemeSet& set) {
    py::dict d;
    for (const Viseme& v : set.visemes) d[py::str(v.name)] = toArray(v.positions);
    return d;
}

} // namespace

void bindVisemes(py::module_& m) {
    py::class_<VisemeSet, SetPtr>(m, "VisemeSet",
                                  "An interpolable viseme set: a neutral mesh and n named visemes with the "
                                  "same vertices and triangles")
        .def(py::init(&setFromArrays), py::arg("neutral"), py::arg("triangles"), py::arg("visemes"),
             py::arg("uvs") = py::none(),
             "From arrays: neutral (N, 3), triangles (T, 3) vertex indices, visemes {name: (N, 3)} or "
             "[(name, (N, 3))], optional uvs (N, 2)")
        .def_property_readonly("names",
                               [](const VisemeSet& s) {
                                   std::vector<std::string> names;
                                   for (const auto& v : s.visemes) names.push_back(v.name);
                                   return names;
                               })
        .def_property_readonly("neutral", [](const VisemeSet& s) { return toArray(s.neutral.positions); })
        .def_property_readonly("triangles", [](const VisemeSet& s) { return toArray(s.neutral.triangles); })
        .def_property_readonly("uvs",
                               [](const VisemeSet& s) -> py::object {
                                   if (!s.neutral.hasUVs()) return py::none();
                                   return toArray(s.neutral.uvs);
                               })
        .def_property_readonly("visemes", &visemesOf, "{name: (N, 3) positions}, in set order")
        .def("__len__", &VisemeSet::size);

    m.def("load_visemes", &setFromFiles, py::kw_only(), py::arg("folder") = py::none(),
          py::arg("neutral") = py::none(), py::arg("files") = py::none(),
          "Loads a viseme set from mesh files (.obj, .ply, .wrl): a folder (as `reduce --visemes`), or a "
          "neutral file and {name: file}");
    m.def("reduce_visemes", &reduceVisemeSet, py::arg("visemes"), py::kw_only(), py::arg("m") = 0,
          py::arg("frequencies") = py::none(), py::arg("phoneme_map") = py::none(),
          py::arg("weights") = py::str("uniform"), py::arg("pin") = std::vector<std::string>{},
          py::arg("apart") = std::vector<std::pair<std::string, std::string>>{},
          py::arg("together") = std::vector<std::pair<std::string, std::string>>{}, py::arg("rest") = "auto",
          py::arg("rest_viseme") = "", py::arg("closure") = "", py::arg("max_error_mm") = 0.0,
          py::arg("time_limit") = kBatchReduceSeconds, py::arg("method") = "auto",
          "Reduces a VisemeSet to m keys (or the fewest within max_error_mm) as `visemelab reduce` does: "
          "the groups, the cost curve for p = 1..m, the merged keys as arrays and the phoneme -> key map");
}

} // namespace vl::python
