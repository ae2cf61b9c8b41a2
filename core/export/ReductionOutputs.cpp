#include "core/export/ReductionOutputs.h"

#include "core/export/KeyMeshFiles.h"
#include "core/export/MappingJson.h"
#include "core/gltf/AvatarReport.h"
#include "core/io/MeshIO.h"
#include "core/io/PlyKeyWriter.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <span>
#include <stdexcept>

namespace vl {

std::optional<KeyMeshFormats> keyMeshFormatsFromString(std::string_view text, std::size_t vertexCount) {
    if (text == "auto")
        return vertexCount > kBinaryKeyMeshVertices ? KeyMeshFormats{false, false, true} : KeyMeshFormats{};
    if (text == "obj+wrl") return KeyMeshFormats{};
    if (text == "obj") return KeyMeshFormats{true, false, false};
    if (text == "wrl") return KeyMeshFormats{false, true, false};
    if (text == "ply") return KeyMeshFormats{false, false, true};
    return std::nullopt;
}

namespace {

// The text pair: each key's positions formatted once for its OBJ and VRML.
void writeTextKeys(OutputSet& outputs, const ReducedModel& model, KeyMeshFormats formats,
                   std::vector<std::string>& written) {
    // The keys share the neutral mesh's topology: its faces and (u,v) are formatted once per format.
    // Positions as float32, what every consumer of key meshes stores (MeshIO.h, docs/export.md), each
    // key's formatted once for its OBJ and VRML; coordinates a key shares with the neutral (most of a
    // face does not move in a viseme) are formatted once for all keys.
    constexpr PositionPrecision kPrecision = PositionPrecision::Float32;
    const MeshTextFormatter obj("key.obj", model.neutral, kPrecision),
        wrl("key.wrl", model.neutral, kPrecision);
    std::vector<const MeshTextFormatter*> formatters;
    if (formats.obj) formatters.push_back(&obj);
    if (formats.wrl) formatters.push_back(&wrl);
    const PositionText neutral(model.neutral.positions, kPrecision);
    PositionText positions;
    std::string text; // every file's positions; its faces and (u,v) are written from the formatter's text
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        positions.assign(model.keys[k].positions, kPrecision, &neutral);
        for (const MeshTextFormatter* formatter : formatters) {
            written.push_back(keyFileName(model, k, formatter == &obj ? ".obj" : ".wrl"));
            const MeshTextFormatter::Parts file = formatter->parts(positions, text);
            outputs.add(written.back(), {file.head, file.middle, file.tail});
        }
    }
}

void writePlyKeys(OutputSet& outputs, const ReducedModel& model, std::vector<std::string>& written) {
    const PlyKeyWriter ply(model.neutral);
    std::string bytes; // one key's positions at a time
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        written.push_back(keyFileName(model, k, ".ply"));
        outputs.add(written.back(), {ply.head(), ply.positions(model.keys[k].positions, bytes), ply.faces()});
    }
}

// Keys deferred (KeyPositions::Deferred): each merged from the set into one float32 buffer and written.
void writeDeferredPlyKeys(OutputSet& outputs, const ReduceOutcome& outcome, const SetShapes& set,
                          std::vector<std::string>& written) {
    const ReducedModel& model = outcome.model;
    const std::size_t vertices = set.shapes.empty() ? 0 : set.shapes[0].size();
    const PlyKeyWriter ply(vertices, set.neutral->triangles, set.neutral->uvs);
    const std::vector<int> groupOf = outcome.result.groupOf();
    std::vector<float> key(3 * vertices); // one key at a time, reused
    std::vector<int> members;
    std::string bytes;
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        members.clear();
        for (std::size_t i = 0; i < groupOf.size(); ++i)
            if (groupOf[i] == static_cast<int>(k)) members.push_back(static_cast<int>(i));
        mergeKeyInto(set.shapes, outcome.frequencies, members, key);
        written.push_back(keyFileName(model, k, ".ply"));
        outputs.add(written.back(),
                    {ply.head(), ply.positions(std::span<const float>(key), bytes), ply.faces()});
    }
}

std::vector<std::string> writeOutputs(OutputSet& outputs, const ReduceOutcome& outcome,
                                      KeyMeshFormats formats, const SetShapes* deferred) {
    const ReducedModel& model = outcome.model;
    std::vector<std::string> written;
    if (deferred) {
        if (formats.obj || formats.wrl)
            throw std::invalid_argument(
                "writeReductionOutputs: deferred keys are written as binary PLY only");
        writeDeferredPlyKeys(outputs, outcome, *deferred, written);
    } else {
        if (formats.obj || formats.wrl) writeTextKeys(outputs, model, formats, written);
        if (formats.ply) writePlyKeys(outputs, model, written);
    }
    std::vector<KeyFileField> fields;
    if (formats.obj) fields.push_back({"obj", ".obj"});
    if (formats.wrl) fields.push_back({"wrl", ".wrl"});
    if (formats.ply) fields.push_back({"ply", ".ply"});
    written.emplace_back("mapping.json");
    outputs.add(written.back(), formatMappingJson(model, fields));
    return written;
}

} // namespace

std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const ReduceOutcome& outcome,
                                               KeyMeshFormats formats) {
    return writeOutputs(outputs, outcome, formats, nullptr);
}

std::vector<std::string> writeReductionOutputs(OutputSet& outputs, const ReduceOutcome& outcome,
                                               KeyMeshFormats formats, const SetShapes& set) {
    return writeOutputs(outputs, outcome, formats, &set);
}

namespace {

std::vector<std::string> namesOf(const ReduceOutcome& outcome, const std::vector<int>& indices) {
    std::vector<std::string> names;
    for (const int i : indices) names.push_back(outcome.visemeNames[static_cast<std::size_t>(i)]);
    return names;
}

} // namespace

namespace {

double largestDisplacementMm(std::span<const Vec3> shape, std::span<const Vec3> neutral) {
    double largest = 0;
    for (std::size_t v = 0; v < shape.size(); ++v)
        largest = std::max(largest, (shape[v] - neutral[v]).norm());
    return 1000 * largest;
}

} // namespace

std::vector<VisemeMotion> visemeMotions(const VisemeSet& set, const ReduceOutcome& outcome) {
    const std::vector<int> groupOf = outcome.result.groupOf();
    std::vector<VisemeMotion> motions;
    for (std::size_t i = 0; i < set.visemes.size(); ++i) {
        VisemeMotion motion{set.visemes[i].name, "",
                            largestDisplacementMm(set.visemes[i].positions, set.neutral.positions), 0.0};
        if (groupOf[i] != kRestGroup) {
            const KeyMesh& key = outcome.model.keys[static_cast<std::size_t>(groupOf[i])];
            motion.key = key.name;
            motion.afterMm = largestDisplacementMm(key.positions, set.neutral.positions);
        }
        motions.push_back(std::move(motion));
    }
    return motions;
}

std::string formatVisemeMotion(const VisemeMotion& motion) {
    char text[256];
    if (motion.key.empty())
        std::snprintf(text, sizeof text, "moves 0 mm (rests; %.3g mm before)", motion.beforeMm);
    else
        std::snprintf(text, sizeof text, "moves %.3g of %.3g mm (key %s)", motion.afterMm, motion.beforeMm,
                      motion.key.c_str());
    return motion.viseme + " " + text;
}

std::string maxErrorSummary(const MaxErrorFinding& finding) {
    char text[320];
    std::snprintf(
        text, sizeof text,
        "Max error %g mm: %d keys is the fewest that keep every viseme within it (%s); the grouping "
        "is %s",
        finding.limitMm, finding.keys, finding.certified ? "proved" : "not proved: search stopped",
        finding.optimalWithin ? "the optimum among those (proved)"
                              : "one that meets it (not proved optimal)");
    return text;
}

namespace {

struct ErrorScale {
    double factor;    // model units -> shown unit
    const char* unit; // "mm" or "model units"
};

ErrorScale errorScale(const ReduceOutcome& outcome) {
    return outcome.millimetresPerUnit > 0 ? ErrorScale{outcome.millimetresPerUnit, "mm"}
                                          : ErrorScale{1.0, "model units"};
}

double percentOf(const VisemeError& e) {
    return e.largestDisplacement > 0 ? 100 * e.max / e.largestDisplacement : 0.0;
}

} // namespace

std::string visemeErrorTable(const ReduceOutcome& outcome) {
    const ErrorScale scale = errorScale(outcome);
    std::string text =
        std::string("Per viseme error (") + scale.unit + "): max, RMS, max as % of its own motion\n";
    for (std::size_t i = 0; i < outcome.visemeErrors.size() && i < outcome.visemeNames.size(); ++i) {
        const VisemeError& e = outcome.visemeErrors[i];
        char line[256];
        std::snprintf(line, sizeof line, "  %-16s %10.4g %10.4g %8.1f %%\n", outcome.visemeNames[i].c_str(),
                      e.max * scale.factor, e.rms * scale.factor, percentOf(e));
        text += line;
    }
    return text;
}

std::string restSummary(const ReduceOutcome& outcome) {
    const std::string viseme =
        outcome.restViseme.empty() ? "no rest viseme" : "rest viseme " + outcome.restViseme;
    std::string line;
    if (!outcome.result.restFree) {
        line = "Rest: key (the rest is a key like any other; " + viseme + ")";
    } else {
        line = "Rest: free (the neutral is a free key; " + viseme + "); resting:";
        const auto& resting = outcome.model.resting;
        if (resting.empty()) line += " none";
        for (std::size_t i = 0; i < resting.size(); ++i) line += (i ? ", " : " ") + resting[i];
    }
    if (!outcome.closureViseme.empty())
        line += "\nLip closure: " + outcome.closureViseme +
                " keeps a key of its own (P, B, M close the lips; --closure none leaves it to the optimiser)";
    else if (!outcome.closureNote.empty())
        line += "\nLip closure: " + outcome.closureNote;
    return line;
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
    for (const KeyMesh& key : outcome.model.keys) groups.push_back(key.members);
    report["groups"] = groups;
    report["rest"] = {{"model", outcome.result.restFree ? "free" : "key"},
                      {"viseme", outcome.restViseme.empty() ? nlohmann::ordered_json()
                                                            : nlohmann::ordered_json(outcome.restViseme)},
                      {"resting", outcome.model.resting}};
    if (!outcome.closureViseme.empty() || !outcome.closureNote.empty())
        report["closure"] = {{"viseme", outcome.closureViseme.empty()
                                            ? nlohmann::ordered_json()
                                            : nlohmann::ordered_json(outcome.closureViseme)},
                             {"note", outcome.closureNote}};
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
        for (const auto& group : grouping.groups) entry.push_back(namesOf(outcome, group));
        groupsCurve.push_back(entry);
    }
    report["cost_curve"] = curve;
    report["lower_bound_curve"] = bounds;
    report["optimal_curve"] = optimal;
    report["groups_curve"] = groupsCurve;
    if (outcome.result.restFree) {
        nlohmann::ordered_json restCurve = nlohmann::ordered_json::array();
        for (const auto& grouping : outcome.result.curve)
            restCurve.push_back(grouping.feasible() ? nlohmann::ordered_json(namesOf(outcome, grouping.rest))
                                                    : nlohmann::ordered_json());
        report["rest_curve"] = restCurve;
    }
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
    const ErrorScale scale = errorScale(outcome);
    nlohmann::ordered_json errors = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < outcome.visemeErrors.size() && i < outcome.visemeNames.size(); ++i) {
        const VisemeError& e = outcome.visemeErrors[i];
        errors.push_back({{"viseme", outcome.visemeNames[i]},
                          {"max", e.max * scale.factor},
                          {"rms", e.rms * scale.factor},
                          {"percent_of_motion", percentOf(e)}});
    }
    report["viseme_errors"] = {{"unit", scale.unit}, {"visemes", errors}};
    if (const auto& bound = outcome.maxError)
        report["max_error"] = {{"limit_mm", bound->limitMm},
                               {"keys", bound->keys},
                               {"certified", bound->certified},
                               {"optimal_within", bound->optimalWithin}};
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

std::string avatarReductionReport(const AvatarReduction& reduction, const AvatarScan& scan,
                                  const ReduceSettings& settings, const AvatarWriteOptions& write,
                                  const ReduceTimings& timings, const std::string& input,
                                  const std::string& output) {
    nlohmann::ordered_json report = nlohmann::ordered_json::parse(
        reductionReportJson(reduction.outcome, settings.weightMode, timings, {output}));
    nlohmann::ordered_json meshes = nlohmann::ordered_json::array();
    for (const AvatarMeshChange& m : reduction.summary.meshes)
        meshes.push_back({{"index", m.mesh},
                          {"name", m.name},
                          {"targets_before", m.targetsBefore},
                          {"targets_after", m.targetsAfter},
                          {"viseme_targets", m.visemeTargets},
                          {"keys", m.keys}});
    report["meshes"] = meshes;
    nlohmann::ordered_json motions = nlohmann::ordered_json::array();
    for (const VisemeMotion& m : visemeMotions(scan.set, reduction.outcome))
        motions.push_back({{"viseme", m.viseme},
                           {"key", m.key.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(m.key)},
                           {"before_mm", m.beforeMm},
                           {"after_mm", m.afterMm}});
    report["viseme_motion"] = motions;
    nlohmann::ordered_json phonemes = nlohmann::ordered_json::object();
    for (const auto& [phoneme, key] : reduction.outcome.model.phonemeToKey) phonemes[phoneme] = key;
    report["phoneme_to_key"] = phonemes;
    report["avatar"] = {{"input", input},
                        {"output", output},
                        {"names", toString(write.names)},
                        {"target_normals", write.targetNormals},
                        {"accessors_before", reduction.summary.accessorsBefore},
                        {"accessors_after", reduction.summary.accessorsAfter},
                        {"binary_bytes_before", reduction.summary.binaryBytesBefore},
                        {"binary_bytes_after", reduction.summary.binaryBytesAfter},
                        {"notes", reduction.summary.notes}};
    report["scan"] = avatarReportJson(scan);
    return report.dump(2) + "\n";
}

} // namespace vl
