// The optional "constraints" object of the "reduction" section: {"pin": [names], "apart": [[a, b], ...],
// "together": [[a, b], ...]}, every key optional. Names must be visemes of the project; whether the
// constraints allow the target m is checked when the reduction runs.
#include "core/project/ProjectJson.h"

#include <algorithm>

namespace vl {

namespace {

std::string visemeName(const JsonNode& node, const std::vector<std::string>& visemeNames) {
    const std::string name = node.nonEmptyString();
    if (std::find(visemeNames.begin(), visemeNames.end(), name) == visemeNames.end())
        node.fail("unknown viseme \"" + name + "\"");
    return name;
}

std::vector<std::pair<std::string, std::string>> pairsFromJson(const JsonNode& node,
                                                               const std::vector<std::string>& visemeNames) {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const JsonNode& pair : node.elements()) {
        pair.expectSize(2);
        auto names = std::pair{visemeName(pair[0], visemeNames), visemeName(pair[1], visemeNames)};
        if (names.first == names.second) pair.fail("\"" + names.first + "\" is paired with itself");
        pairs.push_back(std::move(names));
    }
    return pairs;
}

Json pairsToJson(const std::vector<std::pair<std::string, std::string>>& pairs) {
    Json json = Json::array();
    for (const auto& [a, b] : pairs) json.push_back(Json::array({a, b}));
    return json;
}

} // namespace

Json constraintsToJson(const ConstraintNames& constraints) {
    Json json = Json::object();
    if (!constraints.pinned.empty()) json["pin"] = constraints.pinned;
    if (!constraints.apart.empty()) json["apart"] = pairsToJson(constraints.apart);
    if (!constraints.together.empty()) json["together"] = pairsToJson(constraints.together);
    return json;
}

ConstraintNames constraintsFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames) {
    node.expectObject();
    node.allowOnly({"pin", "apart", "together"});
    ConstraintNames constraints;
    if (node.has("pin"))
        for (const JsonNode& name : node["pin"].elements())
            constraints.pinned.push_back(visemeName(name, visemeNames));
    if (node.has("apart")) constraints.apart = pairsFromJson(node["apart"], visemeNames);
    if (node.has("together")) constraints.together = pairsFromJson(node["together"], visemeNames);
    return constraints;
}

} // namespace vl
