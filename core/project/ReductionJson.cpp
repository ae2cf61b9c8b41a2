// The "reduction" section: target m, the rest model and the last result (cost curve with the
// grouping for each p), groups written as viseme names so the file stays readable and survives
// reordering of the list.
#include "core/common/Error.h"
#include "core/project/ProjectJson.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace vl {

namespace {

Json namesToJson(const std::vector<int>& members, const std::vector<std::string>& visemeNames,
                 std::string_view path) {
    Json names = Json::array();
    for (const int member : members) {
        if (member < 0 || static_cast<std::size_t>(member) >= visemeNames.size())
            throwInputError(path, "group member " + std::to_string(member) + " is not a viseme index");
        names.push_back(visemeNames[static_cast<std::size_t>(member)]);
    }
    return names;
}

Json groupingToJson(const Grouping& grouping, const std::vector<std::string>& visemeNames,
                    std::string_view path) {
    if (!grouping.feasible()) return Json{{"infeasible", true}}; // the constraints rule this p out
    Json groups = Json::array();
    for (const auto& group : grouping.groups) groups.push_back(namesToJson(group, visemeNames, path));
    Json json = Json::object();
    json["cost"] = grouping.cost;
    json["groups"] = std::move(groups);
    // Resting visemes (rest-free model): in no key, written only when there are any.
    if (!grouping.rest.empty()) json["rests"] = namesToJson(grouping.rest, visemeNames, path);
    if (!grouping.optimal) { // results without a proof say so; proven ones keep the original layout
        json["optimal"] = false;
        json["lowerBound"] = grouping.lowerBound;
    }
    return json;
}

// Reads the grouping into p groups, checks that it is a partition of all visemes and puts it in the
// canonical order of ReductionResult (members ascending, groups by first member).
using NameIndex = std::unordered_map<std::string_view, std::size_t>;

// The viseme index of a member name; `groupOf` marks where each viseme went (-1: nowhere yet).
int memberIndex(const JsonNode& member, const NameIndex& indexOf, std::vector<int>& groupOf, int group) {
    const std::string name = member.string();
    const auto it = indexOf.find(name);
    if (it == indexOf.end()) member.fail("unknown viseme \"" + name + "\"");
    const std::size_t index = it->second;
    if (groupOf[index] != -1) member.fail("viseme \"" + name + "\" is in more than one group");
    groupOf[index] = group;
    return static_cast<int>(index);
}

constexpr int kResting = -2; // groupOf of a resting viseme while reading (-1: not seen)

Grouping groupingFromJson(const JsonNode& node, std::size_t p, const std::vector<std::string>& visemeNames,
                          const NameIndex& indexOf, bool restFree) {
    if (node.has("infeasible")) {
        node.allowOnly({"infeasible"});
        if (!node["infeasible"].boolean()) node["infeasible"].fail("expected true (or leave the key out)");
        const double inf = std::numeric_limits<double>::infinity();
        return {inf, inf, true, {}, {}};
    }
    node.allowOnly({"cost", "groups", "optimal", "lowerBound", "rests"});
    Grouping grouping;
    grouping.cost = node["cost"].nonNegativeNumber();
    grouping.optimal = !node.has("optimal") || node["optimal"].boolean();
    grouping.lowerBound = grouping.cost;
    if (!grouping.optimal && node.has("lowerBound")) {
        grouping.lowerBound = node["lowerBound"].nonNegativeNumber();
        if (grouping.lowerBound > grouping.cost)
            node["lowerBound"].fail("the lower bound exceeds the cost of the grouping");
    } else if (!grouping.optimal) {
        grouping.lowerBound = 0;
    }
    const JsonNode groups = node["groups"];
    if (groups.size() != p)
        groups.fail("expected " + std::to_string(p) + " groups (entry " + std::to_string(p) +
                    " of the cost curve), found " + std::to_string(groups.size()));
    std::vector<int> groupOf(visemeNames.size(), -1);
    for (const JsonNode& group : groups.elements()) {
        if (group.size() == 0) group.fail("empty group");
        std::vector<int> members;
        const int g = static_cast<int>(grouping.groups.size());
        for (const JsonNode& member : group.elements())
            members.push_back(memberIndex(member, indexOf, groupOf, g));
        std::sort(members.begin(), members.end());
        grouping.groups.push_back(std::move(members));
    }
    if (node.has("rests")) {
        const JsonNode rests = node["rests"];
        if (!restFree) rests.fail("resting visemes need a rest-free result (\"restFree\": true)");
        for (const JsonNode& member : rests.elements())
            grouping.rest.push_back(memberIndex(member, indexOf, groupOf, kResting));
        std::sort(grouping.rest.begin(), grouping.rest.end());
    }
    for (std::size_t i = 0; i < visemeNames.size(); ++i)
        if (groupOf[i] == -1)
            groups.fail("viseme \"" + visemeNames[i] + "\" is in no group" +
                        (restFree ? " and does not rest" : ""));
    std::sort(grouping.groups.begin(), grouping.groups.end(),
              [](const std::vector<int>& a, const std::vector<int>& b) { return a.front() < b.front(); });
    return grouping;
}

} // namespace

bool reductionNeedsVersion3(const ProjectReduction& reduction) {
    return reduction.rest != RestChoice::Key || !reduction.restViseme.empty() ||
           (reduction.result && reduction.result->restFree);
}

Json reductionToJson(const ProjectReduction& reduction, const std::vector<std::string>& visemeNames) {
    Json json = Json::object();
    json["target"] = reduction.target;
    // Written only from version 3 on, so keyed projects keep the layout older VisemeLabs read.
    if (reductionNeedsVersion3(reduction)) {
        json["rest"] = toString(reduction.rest);
        if (!reduction.restViseme.empty()) json["restViseme"] = reduction.restViseme;
    }
    if (!reduction.constraints.empty()) json["constraints"] = constraintsToJson(reduction.constraints);
    if (!reduction.result) {
        json["result"] = nullptr;
        return json;
    }
    Json curve = Json::array();
    for (std::size_t p = 0; p < reduction.result->curve.size(); ++p)
        curve.push_back(groupingToJson(reduction.result->curve[p], visemeNames,
                                       jsonPathAppend("/reduction/result/curve", p)));
    json["result"] = Json{{"curve", std::move(curve)}};
    // The solver that ran; absent means the subset DP (the only one of older projects).
    if (reduction.result->method != ReductionMethod::SubsetDp)
        json["result"]["method"] = toString(reduction.result->method);
    if (reduction.result->restFree) json["result"]["restFree"] = true;
    return json;
}

ProjectReduction reductionFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames,
                                   const ProjectReadContext& context) {
    node.allowOnly({"target", "rest", "restViseme", "constraints", "result"});
    // The rest model came with version 3; an older file holding it was not written by VisemeLab.
    const auto requireVersion3 = [&](const JsonNode& field) {
        if (context.version < 3)
            field.fail("the rest model needs project version 3 (this file says " +
                       std::to_string(context.version) + ")");
    };
    ProjectReduction reduction;
    if (node.has("rest")) {
        const JsonNode rest = node["rest"];
        requireVersion3(rest);
        const auto choice = fromString<RestChoice>(rest.string());
        if (!choice)
            rest.fail("unknown rest model \"" + rest.string() +
                      "\" (expected \"free\", \"key\" or \"auto\")");
        reduction.rest = *choice;
    }
    if (node.has("restViseme")) {
        const JsonNode restViseme = node["restViseme"];
        requireVersion3(restViseme);
        reduction.restViseme = restViseme.nonEmptyString();
        if (std::find(visemeNames.begin(), visemeNames.end(), reduction.restViseme) == visemeNames.end())
            restViseme.fail("unknown viseme \"" + reduction.restViseme +
                            "\" (the rest viseme must be one of /visemes)");
    }
    const auto n = static_cast<std::int64_t>(visemeNames.size());
    // With no visemes yet any m >= 1 is kept; it is checked again once visemes exist.
    reduction.target = static_cast<int>(node["target"].integerInRange(1, n > 0 ? n : kMaxReductionVisemes));
    if (node.has("constraints"))
        reduction.constraints = constraintsFromJson(node["constraints"], visemeNames);
    if (!node.has("result") || node["result"].isNull()) return reduction;

    const JsonNode result = node["result"];
    result.allowOnly({"curve", "method", "restFree"});
    const JsonNode curve = result["curve"];
    if (curve.size() == 0 || curve.size() > visemeNames.size())
        curve.fail("expected 1.." + std::to_string(visemeNames.size()) + " entries (p = 1..m), found " +
                   std::to_string(curve.size()));
    NameIndex indexOf; // names are unique (checked by the caller): one hash lookup per member
    for (std::size_t i = 0; i < visemeNames.size(); ++i) indexOf.emplace(visemeNames[i], i);
    ReductionResult parsed;
    if (result.has("method")) {
        // A recorded result names the solver that ran: never "auto".
        const std::string method = result["method"].string();
        const auto ran = fromString<ReductionMethod>(method);
        if (!ran || *ran == ReductionMethod::Auto)
            result["method"].fail("expected \"dp\", \"bnb\" or \"lp\", found \"" + method + "\"");
        parsed.method = *ran;
    }
    if (result.has("restFree")) {
        const JsonNode restFree = result["restFree"];
        requireVersion3(restFree);
        if (!restFree.boolean()) restFree.fail("expected true (or leave the key out)");
        parsed.restFree = true;
    }
    for (std::size_t p = 0; p < curve.size(); ++p)
        parsed.curve.push_back(groupingFromJson(curve[p], p + 1, visemeNames, indexOf, parsed.restFree));
    reduction.result = std::move(parsed);
    return reduction;
}

} // namespace vl
