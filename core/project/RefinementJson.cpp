// The "refinement" section: the adaptive mesh's criterion and the thresholds of every criterion
// (all kept, so switching criteria in the editor does not lose the others' settings).
#include "core/project/ProjectJson.h"

#include <climits>

namespace vl {

Json refinementToJson(const CriterionSettings& s) {
    Json json = Json::object();
    json["criterion"] = toString(s.kind);
    json["maxDepth"] = s.maxDepth;
    json["depth"] = Json{{"depth", s.depth.depth}};
    json["normals"] =
        Json{{"dihedralAngleDeg", s.normals.dihedralAngleDeg}, {"normalAngleDeg", s.normals.normalAngleDeg}};
    json["contour"] = Json{{"averageError", s.contour.averageError},
                           {"maximumError", s.contour.maximumError},
                           {"samplesPerSide", s.contour.samplesPerSide}};
    return json;
}

CriterionSettings refinementFromJson(const JsonNode& node) {
    node.allowOnly({"criterion", "maxDepth", "depth", "normals", "contour"});
    CriterionSettings s;
    const JsonNode criterion = node["criterion"];
    s.kind = parseEnum<CriterionKind>(criterion.string(), criterion.path());
    s.maxDepth = static_cast<int>(node["maxDepth"].integerInRange(0, 30));
    if (node.has("depth")) {
        const JsonNode depth = node["depth"];
        depth.allowOnly({"depth"});
        s.depth.depth = static_cast<int>(depth["depth"].integerInRange(0, INT_MAX));
    }
    if (node.has("normals")) {
        const JsonNode normals = node["normals"];
        normals.allowOnly({"dihedralAngleDeg", "normalAngleDeg"});
        s.normals.dihedralAngleDeg = normals["dihedralAngleDeg"].nonNegativeNumber();
        s.normals.normalAngleDeg = normals["normalAngleDeg"].nonNegativeNumber();
    }
    if (node.has("contour")) {
        const JsonNode contour = node["contour"];
        contour.allowOnly({"averageError", "maximumError", "samplesPerSide"});
        s.contour.averageError = contour["averageError"].nonNegativeNumber();
        s.contour.maximumError = contour["maximumError"].nonNegativeNumber();
        s.contour.samplesPerSide = static_cast<int>(contour["samplesPerSide"].integerInRange(1, 32));
    }
    validateCriterionSettings(s); // the module's own rules as a backstop
    return s;
}

} // namespace vl
