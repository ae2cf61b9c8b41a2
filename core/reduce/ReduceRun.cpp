#include "core/reduce/ReduceRun.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/MeshIO.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace vl {

namespace {

std::string joinNames(const std::vector<std::string>& names, char separator) {
    std::string text;
    for (const auto& name : names) text += (text.empty() ? "" : std::string(1, separator)) + name;
    return text;
}

// File-system safe form of a viseme name.
std::string fileSafe(std::string name) {
    for (auto& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '+') c = '_';
    return name;
}

} // namespace

MapGrouping groupingFromMap(const std::vector<std::string>& visemeNames, const PhonemeVisemeMap& map) {
    MapGrouping out;
    out.source = map.origin.text.empty() ? "map" : map.origin.text;
    std::string unmapped;
    for (std::size_t i = 0; i < visemeNames.size(); ++i) {
        const std::string* label = map.visemeOf(visemeNames[i]);
        if (!label) {
            unmapped += (unmapped.empty() ? "" : ", ") + visemeNames[i];
            continue;
        }
        const auto it = std::find(out.labels.begin(), out.labels.end(), *label);
        if (it == out.labels.end()) {
            out.labels.push_back(*label);
            out.groups.push_back({static_cast<int>(i)});
        } else {
            out.groups[static_cast<std::size_t>(it - out.labels.begin())].push_back(static_cast<int>(i));
        }
    }
    if (!unmapped.empty())
        throwInputError(out.source, "used as a grouping, it does not map these visemes: " + unmapped);
    return out;
}

ReduceOutcome runReduction(const VisemeSet& set, const FrequencySource& frequencies,
                           const ReduceSettings& settings, const ProgressCallback& progress) {
    ReduceOutcome out;
    for (const auto& v : set.visemes) out.visemeNames.push_back(v.name);
    out.frequencies = visemeFrequencies(frequencies, out.visemeNames);
    out.weights = computeWeights(settings.weightMode, set.neutral, settings.paintedWeights,
                                 settings.paintedWeightsSource);

    std::vector<std::span<const Vec3>> rows; // a view of the set's positions: no copy of the shapes
    for (const auto& v : set.visemes) rows.emplace_back(v.positions);
    const ShapeView shapes(rows);
    const ReductionConstraints constraints =
        resolveConstraints(settings.constraints, out.visemeNames, settings.constraintsSource);
    // Contradictions and a target they rule out are reported by viseme name, at the constraints' source.
    const ConstraintUnits units = constraintUnits(constraints, static_cast<int>(set.size()), out.visemeNames,
                                                  settings.constraintsSource);
    if (settings.target >= 1 && static_cast<std::size_t>(settings.target) <= set.size() &&
        !units.feasible(settings.target))
        throwInfeasibleTarget(units, settings.target, settings.constraintsSource);
    out.result = reduceVisemes({shapes, out.frequencies, out.weights, settings.target, constraints},
                               settings.options, progress);
    out.constraints = settings.constraints;
    if (!settings.compareMaps.empty()) {
        std::vector<std::vector<std::vector<int>>> groupings;
        for (const auto& map : settings.compareMaps) {
            out.comparedMaps.push_back(groupingFromMap(out.visemeNames, map));
            groupings.push_back(out.comparedMaps.back().groups);
        }
        const auto costs = evaluateGroupings(shapes, out.frequencies, out.weights, groupings);
        for (std::size_t k = 0; k < costs.size(); ++k) out.comparedMaps[k].cost = costs[k];
    }

    for (const auto& group : out.result.best().groups) {
        ReducedViseme reduced;
        for (const int i : group) {
            reduced.members.push_back(out.visemeNames[static_cast<std::size_t>(i)]);
            reduced.frequency += out.frequencies[static_cast<std::size_t>(i)];
        }
        reduced.name = joinNames(reduced.members, '+');
        reduced.positions = mergeGroup(shapes, out.frequencies, group);
        out.reduced.push_back(std::move(reduced));
    }
    if (frequencies.isPhonemeBased()) {
        const auto groupOf = out.result.groupOf();
        for (const auto& [phoneme, viseme] : frequencies.map.entries) {
            const int index = set.find(viseme);
            if (index >= 0)
                out.phonemeToReduced.emplace_back(phoneme, groupOf[static_cast<std::size_t>(index)]);
        }
    }
    return out;
}

std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const VisemeSet& set,
                                               const ReduceOutcome& outcome) {
    std::vector<std::string> written;
    nlohmann::ordered_json reducedList = nlohmann::ordered_json::array();
    MeshData mesh = set.neutral;
    for (std::size_t g = 0; g < outcome.reduced.size(); ++g) {
        const auto& reduced = outcome.reduced[g];
        const std::string stem = "reduced_" + std::to_string(g) + "_" + fileSafe(reduced.name);
        mesh.positions = reduced.positions;
        outputs.add(stem + ".obj", formatObj(mesh));
        outputs.add(stem + ".wrl", formatVrml(mesh));
        written.push_back(stem + ".obj");
        written.push_back(stem + ".wrl");
        reducedList.push_back({{"index", g},
                               {"name", reduced.name},
                               {"members", reduced.members},
                               {"frequency", reduced.frequency},
                               {"obj", stem + ".obj"},
                               {"wrl", stem + ".wrl"}});
    }
    nlohmann::ordered_json mapping;
    mapping["format"] = "visemelab-mapping";
    mapping["version"] = 1;
    const auto groupOf = outcome.result.groupOf();
    nlohmann::ordered_json visemes = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < outcome.visemeNames.size(); ++i) visemes[outcome.visemeNames[i]] = groupOf[i];
    mapping["visemes"] = visemes;
    nlohmann::ordered_json phonemes = nlohmann::ordered_json::object();
    for (const auto& [phoneme, index] : outcome.phonemeToReduced) phonemes[phoneme] = index;
    mapping["phonemes"] = phonemes;
    mapping["reduced"] = reducedList;
    outputs.add("mapping.json", mapping.dump(2) + "\n");
    written.push_back("mapping.json");
    return written;
}

std::string reductionReportJson(const ReduceOutcome& outcome, WeightMode mode, const ReduceTimings& timings,
                                const std::vector<std::string>& outputs) {
    nlohmann::ordered_json report;
    report["n"] = outcome.visemeNames.size();
    report["m"] = outcome.result.curve.size();
    report["weights"] = toString(mode);
    const Grouping& best = outcome.result.best();
    report["method"] = toString(outcome.result.method);
    report["optimal"] = best.optimal;
    report["cost"] = best.cost;
    report["lower_bound"] = best.lowerBound;
    report["gap"] = best.gap();
    nlohmann::ordered_json groups = nlohmann::ordered_json::array();
    for (const auto& reduced : outcome.reduced) groups.push_back(reduced.members);
    report["groups"] = groups;
    // Entries p the constraints rule out are null.
    nlohmann::ordered_json curve = nlohmann::ordered_json::array(), bounds = nlohmann::ordered_json::array(),
                           optimal = nlohmann::ordered_json::array();
    for (const auto& grouping : outcome.result.curve) {
        curve.push_back(grouping.feasible() ? nlohmann::ordered_json(grouping.cost)
                                            : nlohmann::ordered_json());
        bounds.push_back(grouping.feasible() ? nlohmann::ordered_json(grouping.lowerBound)
                                             : nlohmann::ordered_json());
        optimal.push_back(grouping.optimal);
    }
    // The groups of every p, by name (null where the constraints rule p out).
    nlohmann::ordered_json groupsCurve = nlohmann::ordered_json::array();
    for (const auto& grouping : outcome.result.curve) {
        if (!grouping.feasible()) {
            groupsCurve.push_back(nullptr);
            continue;
        }
        nlohmann::ordered_json entry = nlohmann::ordered_json::array();
        for (const auto& group : grouping.groups) {
            std::vector<std::string> names;
            for (const int i : group) names.push_back(outcome.visemeNames[static_cast<std::size_t>(i)]);
            entry.push_back(names);
        }
        groupsCurve.push_back(entry);
    }
    report["cost_curve"] = curve;
    report["lower_bound_curve"] = bounds;
    report["optimal_curve"] = optimal;
    report["groups_curve"] = groupsCurve;
    nlohmann::ordered_json pairs = nlohmann::ordered_json::object();
    pairs["pin"] = outcome.constraints.pinned;
    auto pairList = [](const std::vector<std::pair<std::string, std::string>>& list) {
        nlohmann::ordered_json json = nlohmann::ordered_json::array();
        for (const auto& [a, b] : list) json.push_back({a, b});
        return json;
    };
    pairs["apart"] = pairList(outcome.constraints.apart);
    pairs["together"] = pairList(outcome.constraints.together);
    report["constraints"] = pairs;
    nlohmann::ordered_json freq = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < outcome.visemeNames.size(); ++i)
        freq[outcome.visemeNames[i]] = outcome.frequencies[i];
    report["frequencies"] = freq;
    if (!outcome.comparedMaps.empty()) {
        nlohmann::ordered_json maps = nlohmann::ordered_json::array();
        for (const auto& given : outcome.comparedMaps) {
            nlohmann::ordered_json entry;
            entry["map"] = given.source;
            entry["groups"] = given.groups.size();
            entry["cost"] = given.cost;
            // The optimum for as many groups, when this run solved that p.
            const std::size_t p = given.groups.size();
            if (p <= outcome.result.curve.size() && outcome.result.curve[p - 1].feasible()) {
                const Grouping& opt = outcome.result.curve[p - 1];
                entry["optimal_cost"] = opt.cost;
                entry["optimal_lower_bound"] = opt.lowerBound;
                entry["optimal_proved"] = opt.optimal;
                entry["excess"] = opt.cost > 0 ? given.cost / opt.cost - 1.0 : 0.0;
            }
            nlohmann::ordered_json members = nlohmann::ordered_json::object();
            for (std::size_t g = 0; g < given.groups.size(); ++g) {
                std::vector<std::string> names;
                for (const int i : given.groups[g])
                    names.push_back(outcome.visemeNames[static_cast<std::size_t>(i)]);
                members[given.labels[g]] = names;
            }
            entry["grouping"] = members;
            maps.push_back(entry);
        }
        report["compared_maps"] = maps;
    }
    report["timing_ms"] = {
        {"load", timings.loadMs}, {"reduce", timings.reduceMs}, {"write", timings.writeMs}};
    report["outputs"] = outputs;
    return report.dump(2) + "\n";
}

} // namespace vl
