// The "reduction" section: target m and the last result (cost curve with the grouping for each p),
// groups written as viseme names so the file stays readable and survives reordering of the list.
#include "core/common/Error.h"
#include "core/project/ProjectJson.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace vl {

namespace {

Json groupingToJson(const Grouping& grouping, const std::vector<std::string>& visemeNames,
                    std::string_view path) {
    if (!grouping.feasible()) return Json{{"infeasible", true}}; // the constraints rule this p out
    Json groups = Json::array();
    for (const auto& group : grouping.groups) {
        Json names = Json::array();
        for (const int member : group) {
            if (member < 0 || static_cast<std::size_t>(member) >= visemeNames.size())
                throwInputError(path, "group member " + std::to_string(member) + " is not a viseme index");
            names.push_back(visemeNames[static_cast<std::size_t>(member)]);
        }
        groups.push_back(std::move(names));
    }
    Json json = Json::object();
    json["cost"] = grouping.cost;
    json["groups"] = std::move(groups);
    if (!grouping.optimal) { // results without a proof say so; proven ones keep the original layout
        json["optimal"] = false;
        json["lowerBound"] = grouping.lowerBound;
    }
    return json;
}

// Reads the grouping into p groups, checks that it is a partition of all visemes and puts it in the
// canonical order of ReductionResult (members ascending, groups by first member).
using NameIndex = std::unordered_map<std::string_view, std::size_t>;

Grouping groupingFromJson(const JsonNode& node, std::size_t p, const std::vector<std::string>& visemeNames,
                          const NameIndex& indexOf) {
    if (node.has("infeasible")) {
        node.allowOnly({"infeasible"});
        if (!node["infeasible"].boolean()) node["infeasible"].fail("expected true (or leave the key out)");
        const double inf = std::numeric_limits<double>::infinity();
        return {inf, inf, true, {}, {}};
    }
    node.allowOnly({"cost", "groups", "optimal", "lowerBound"});
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
        for (const JsonNode& member : group.elements()) {
            const std::string name = member.string();
            const auto it = indexOf.find(name);
            if (it == indexOf.end()) member.fail("unknown viseme \"" + name + "\"");
            const std::size_t index = it->second;
            if (groupOf[index] >= 0) member.fail("viseme \"" + name + "\" is in more than one group");
            groupOf[index] = static_cast<int>(grouping.groups.size());
            members.push_back(static_cast<int>(index));
        }
        std::sort(members.begin(), members.end());
        grouping.groups.push_back(std::move(members));
    }
    for (std::size_t i = 0; i < visemeNames.size(); ++i)
        if (groupOf[i] < 0) groups.fail("viseme \"" + visemeNames[i] + "\" is in no group");
    std::sort(grouping.groups.begin(), grouping.groups.end(),
              [](const std::vector<int>& a, const std::vector<int>& b) { return a.front() < b.front(); });
    return grouping;
}

} // namespace

Json reductionToJson(const ProjectReduction& reduction, const std::vector<std::string>& visemeNames) {
    Json json = Json::object();
    json["target"] = reduction.target;
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
    return json;
}

ProjectReduction reductionFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames) {
    node.allowOnly({"target", "constraints", "result"});
    ProjectReduction reduction;
    const auto n = static_cast<std::int64_t>(visemeNames.size());
    // With no visemes yet any m >= 1 is kept; it is checked again once visemes exist.
    reduction.target = static_cast<int>(node["target"].integerInRange(1, n > 0 ? n : kMaxReductionVisemes));
    if (node.has("constraints"))
        reduction.constraints = constraintsFromJson(node["constraints"], visemeNames);
    if (!node.has("result") || node["result"].isNull()) return reduction;

    const JsonNode result = node["result"];
    result.allowOnly({"curve", "method"});
    const JsonNode curve = result["curve"];
    if (curve.size() == 0 || curve.size() > visemeNames.size())
        curve.fail("expected 1.." + std::to_string(visemeNames.size()) + " entries (p = 1..m), found " +
                   std::to_string(curve.size()));
    NameIndex indexOf; // names are unique (checked by the caller): one hash lookup per member
    for (std::size_t i = 0; i < visemeNames.size(); ++i) indexOf.emplace(visemeNames[i], i);
    ReductionResult parsed;
    if (result.has("method")) {
        const std::string method = result["method"].string();
        if (method != "dp" && method != "bnb" && method != "lp")
            result["method"].fail("expected \"dp\", \"bnb\" or \"lp\", found \"" + method + "\"");
        parsed.method = method == "bnb"  ? ReductionMethod::BranchAndBound
                        : method == "lp" ? ReductionMethod::ColumnGeneration
                                         : ReductionMethod::SubsetDp;
    }
    for (std::size_t p = 0; p < curve.size(); ++p)
        parsed.curve.push_back(groupingFromJson(curve[p], p + 1, visemeNames, indexOf));
    reduction.result = std::move(parsed);
    return reduction;
}

} // namespace vl
