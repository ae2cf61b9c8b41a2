// Project versions: the check of "format"/"version" and the upgrades of older layouts.
//
// Version 0 is the flat pre-release layout (docs/project-format.md, "Version 0"):
//   {"format": "visemelab-project", "version": 0,
//    "neutral": "neutral.obj", "visemes": {"aa": "aa.obj", ...},
//    "frequencies": {"aa": 0.1, ...}                       (direct viseme frequencies), or
//    "phonemes": {"AA": 0.02, ...}, "phoneme_map": {"AA": "aa", ...},
//    "weights": "uniform" | "area" | [w0, w1, ...],        (an array means painted weights)
//    "target": 10}
// Each upgrade checks the shape of the old layout with paths into the old document; values are
// validated by the reader of the current version afterwards.
#include "core/common/Error.h"
#include "core/project/ProjectJson.h"

#include <string>

namespace vl {

namespace {

Json migrateFromVersion0(const JsonNode& root) {
    root.allowOnly({"format", "version", "neutral", "visemes", "frequencies", "phonemes", "phoneme_map",
                    "weights", "target"});
    Json upgraded = Json::object();
    upgraded["format"] = kProjectFormat;
    upgraded["version"] = 1;
    upgraded["neutral"] = Json{{"file", root["neutral"].string()}};

    Json visemes = Json::array();
    for (const auto& [name, file] : root["visemes"].members())
        visemes.push_back(Json{{"name", name}, {"file", file.string()}});
    upgraded["visemes"] = std::move(visemes);

    Json frequencies = Json::object();
    if (root.has("frequencies")) {
        root["frequencies"].expectObject();
        frequencies["visemes"] = root["frequencies"].json();
    }
    if (root.has("phonemes")) {
        root["phonemes"].expectObject();
        frequencies["phonemes"] = root["phonemes"].json();
    }
    if (root.has("phoneme_map")) {
        root["phoneme_map"].expectObject();
        frequencies["map"] = root["phoneme_map"].json();
    }
    upgraded["frequencies"] = std::move(frequencies);

    if (root.has("weights")) {
        const JsonNode weights = root["weights"];
        if (weights.isArray())
            upgraded["weights"] = Json{{"mode", "painted"}, {"painted", weights.json()}};
        else
            upgraded["weights"] = Json{{"mode", weights.string()}};
    }
    upgraded["reduction"] = Json{{"target", root["target"].json()}, {"result", nullptr}};
    return upgraded;
}

} // namespace

int projectVersionOf(const JsonNode& root) {
    root.expectObject();
    const JsonNode format = root["format"];
    if (format.string() != kProjectFormat)
        format.fail("expected \"" + std::string(kProjectFormat) + "\", found \"" + format.string() +
                    "\" (not a VisemeLab project)");
    const JsonNode version = root["version"];
    const auto v = version.integer();
    if (v > kProjectVersion)
        version.fail("project version " + std::to_string(v) +
                     " is newer than this VisemeLab (supports up to " + std::to_string(kProjectVersion) +
                     "); open it with a newer VisemeLab");
    if (v < kOldestProjectVersion)
        version.fail("unknown project version " + std::to_string(v) + " (this VisemeLab reads versions " +
                     std::to_string(kOldestProjectVersion) + ".." + std::to_string(kProjectVersion) + ")");
    return static_cast<int>(v);
}

Json migrateProjectJson(const JsonNode& root, int fromVersion) {
    Json document = root.json();
    for (int version = fromVersion; version < kFirstLayoutVersion; ++version) {
        const JsonNode node(document, root.path());
        switch (version) {
        case 0:
            document = migrateFromVersion0(node);
            break;
        default:
            throwInputError("/version", "no migration from version " + std::to_string(version));
        }
    }
    return document;
}

} // namespace vl
