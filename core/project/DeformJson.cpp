// The "deformation" section: the cascade (parameters with ranges and defaults, Constant/AddVector
// stages with their fields), the current parameter values, the visemes as parameter vectors and the
// face's (u,v) mesh (version 2).
// Stages name their parameter instead of using its index, so the file survives reordering.
#include "core/common/Error.h"
#include "core/common/Limits.h"
#include "core/common/TextParsing.h"
#include "core/project/FieldJson.h"
#include "core/project/ProjectJson.h"

#include <algorithm>
#include <set>

namespace vl {

namespace {

const char* stageKindName(StageKind kind) {
    return kind == StageKind::Constant ? "constant" : "addVector";
}

Json parameterToJson(const DeformParameter& p) {
    Json json = Json::object();
    json["name"] = p.name;
    json["min"] = p.min;
    json["max"] = p.max;
    json["default"] = p.defaultValue;
    return json;
}

std::string rangeText(const DeformParameter& p) {
    return "[" + formatDouble(p.min) + ", " + formatDouble(p.max) + "]";
}

DeformParameter parameterFromJson(const JsonNode& node) {
    node.allowOnly({"name", "min", "max", "default"});
    DeformParameter p;
    p.name = node["name"].nonEmptyString();
    p.min = node["min"].number();
    p.max = node["max"].number();
    if (p.min > p.max)
        node["max"].fail("max " + formatDouble(p.max) + " is below min " + formatDouble(p.min));
    const JsonNode value = node["default"];
    p.defaultValue = value.number();
    if (p.defaultValue < p.min || p.defaultValue > p.max)
        value.fail("default " + formatDouble(p.defaultValue) + " is outside " + rangeText(p));
    return p;
}

// A value of the parameter `name` in its range; `node` is the value in the document.
double parameterValueFromJson(const DeformationCascade& cascade, const std::string& name,
                              const JsonNode& node) {
    const int index = cascade.findParameter(name);
    if (index < 0) throwInputError(node.path(), "unknown parameter \"" + name + "\"");
    const DeformParameter& p = cascade.parameters[static_cast<std::size_t>(index)];
    const double value = node.number();
    if (value < p.min || value > p.max) node.fail(formatDouble(value) + " is outside " + rangeText(p));
    return value;
}

Json stageToJson(const DeformationCascade& cascade, std::size_t index) {
    const DeformationStage& stage = cascade.stages[index];
    Json json = Json::object();
    json["kind"] = stageKindName(stage.kind);
    json["name"] = stage.name;
    if (stage.kind == StageKind::AddVector) {
        if (stage.parameter >= cascade.parameters.size())
            throwInputError(jsonPathAppend("/deformation/cascade/stages", index),
                            "uses parameter index " + std::to_string(stage.parameter) + " but there are " +
                                std::to_string(cascade.parameters.size()) + " parameters");
        json["parameter"] = cascade.parameters[stage.parameter].name;
    }
    json["field"] = vectorFieldToJson(stage.field);
    return json;
}

DeformationStage stageFromJson(const JsonNode& node, const DeformationCascade& cascade) {
    node.allowOnly({"kind", "name", "parameter", "field"});
    DeformationStage stage;
    const JsonNode kind = node["kind"];
    const std::string kindName = kind.string();
    if (kindName == "constant")
        stage.kind = StageKind::Constant;
    else if (kindName == "addVector")
        stage.kind = StageKind::AddVector;
    else
        kind.fail("unknown stage kind \"" + kindName + "\" (expected constant or addVector)");
    stage.name = node["name"].string();
    if (stage.kind == StageKind::AddVector) {
        const JsonNode parameter = node["parameter"];
        const int index = cascade.findParameter(parameter.string());
        if (index < 0) parameter.fail("unknown parameter \"" + parameter.string() + "\"");
        stage.parameter = static_cast<std::size_t>(index);
    } else if (node.has("parameter")) {
        node["parameter"].fail("a constant stage has no parameter");
    }
    stage.field = vectorFieldFromJson(node["field"]);
    return stage;
}

Json cascadeToJson(const DeformationCascade& cascade) {
    Json json = Json::object();
    json["name"] = cascade.name;
    Json parameters = Json::array();
    for (const auto& p : cascade.parameters) parameters.push_back(parameterToJson(p));
    json["parameters"] = std::move(parameters);
    Json stages = Json::array();
    for (std::size_t k = 0; k < cascade.stages.size(); ++k) stages.push_back(stageToJson(cascade, k));
    json["stages"] = std::move(stages);
    return json;
}

DeformationCascade cascadeFromJson(const JsonNode& node) {
    node.allowOnly({"name", "parameters", "stages"});
    DeformationCascade cascade;
    cascade.name = node["name"].string();
    std::set<std::string> names;
    for (const JsonNode& p : node["parameters"].elements()) {
        cascade.parameters.push_back(parameterFromJson(p));
        if (!names.insert(cascade.parameters.back().name).second)
            p["name"].fail("duplicate parameter name \"" + cascade.parameters.back().name + "\"");
    }
    const JsonNode stages = node["stages"];
    if (stages.size() == 0) stages.fail("expected at least one stage (the constant base geometry)");
    for (const JsonNode& s : stages.elements()) cascade.stages.push_back(stageFromJson(s, cascade));
    if (cascade.stages.front().kind != StageKind::Constant)
        stages[0]["kind"].fail("the first stage must be a constant stage (the base geometry)");
    validateCascade(cascade); // the module's own rules as a backstop
    return cascade;
}

Json valuesToJson(const ProjectDeformation& deformation) {
    const auto& parameters = deformation.cascade.parameters;
    if (deformation.values.size() != parameters.size())
        throwInputError("/deformation/values", "expected one value per parameter (" +
                                                   std::to_string(parameters.size()) + "), found " +
                                                   std::to_string(deformation.values.size()));
    Json json = Json::object();
    for (std::size_t k = 0; k < parameters.size(); ++k) json[parameters[k].name] = deformation.values[k];
    return json;
}

Json visemeParametersToJson(const VisemeParameters& viseme) {
    Json values = Json::object();
    for (const auto& [name, value] : viseme.values) {
        if (values.contains(name))
            throwInputError("/deformation/visemes",
                            "viseme \"" + viseme.name + "\" sets parameter \"" + name + "\" twice");
        values[name] = value;
    }
    return Json{{"name", viseme.name}, {"values", std::move(values)}};
}

Json domainToJson(const MeshData& domain) {
    if (domain.uvs.size() != domain.positions.size() || domain.triangles.empty())
        throwInputError("/deformation/domain", "expected a (u,v) mesh: one (u,v) per vertex and triangles");
    for (std::size_t i = 0; i < domain.uvs.size(); ++i) {
        const Vec2& uv = domain.uvs[i];
        if (!(uv[0] >= 0.0 && uv[0] <= 1.0 && uv[1] >= 0.0 && uv[1] <= 1.0))
            throwInputError(jsonPathAppend("/deformation/domain/uvs", i), "(u,v) outside the unit square: (" +
                                                                              formatDouble(uv[0]) + ", " +
                                                                              formatDouble(uv[1]) + ")");
    }
    for (std::size_t k = 0; k < domain.triangles.size(); ++k)
        for (const std::uint32_t index : domain.triangles[k])
            if (index >= domain.uvs.size())
                throwInputError(jsonPathAppend("/deformation/domain/triangles", k),
                                "vertex index " + std::to_string(index) + " out of range");
    Json json = Json::object();
    json["uvs"] = uvArrayToJson(domain.uvs);
    json["triangles"] = trianglesToJson(domain.triangles);
    return json;
}

// Positions are (u, v, 0): the mesh is a triangulation of the face domain, not a shape.
MeshData domainFromJson(const JsonNode& node) {
    node.allowOnly({"uvs", "triangles"});
    const JsonNode uvs = node["uvs"];
    if (uvs.size() == 0) uvs.fail("expected at least one (u,v) pair");
    if (uvs.size() > limits::kMaxVisemeSetPositions)
        uvs.fail("more than " + std::to_string(limits::kMaxVisemeSetPositions) + " vertices");
    MeshData domain;
    domain.uvs.reserve(uvs.size());
    for (const JsonNode& e : uvs.elements()) {
        const Vec2 uv = e.vec2();
        if (uv[0] < 0.0 || uv[0] > 1.0 || uv[1] < 0.0 || uv[1] > 1.0)
            e.fail("(u,v) outside the unit square: (" + formatDouble(uv[0]) + ", " + formatDouble(uv[1]) +
                   ")");
        domain.uvs.push_back(uv);
        domain.positions.emplace_back(uv[0], uv[1], 0.0);
    }
    domain.triangles = trianglesFromJson(node["triangles"], domain.uvs.size());
    return domain;
}

} // namespace

int projectVersionFor(const Project& project) {
    if (project.avatar.isSet() && std::any_of(project.visemes.begin(), project.visemes.end(),
                                              [](const ProjectViseme& v) { return !v.positions.empty(); }))
        return 5; // a sculpted avatar viseme
    if (!project.avatar.addedRest.empty()) return 4;
    if (reductionNeedsVersion3(project.reduction)) return 3;
    return project.deformation.domain.positions.empty() ? 1 : 2;
}

Json deformationToJson(const ProjectDeformation& deformation) {
    if (!deformation.isSet()) {
        if (!deformation.values.empty() || !deformation.visemes.empty() ||
            !deformation.cascade.parameters.empty() || !deformation.domain.positions.empty())
            throwInputError(
                "/deformation",
                "parameters, values, visemes or a (u,v) mesh without a cascade (it has no stages)");
        return nullptr;
    }
    Json json = Json::object();
    json["cascade"] = cascadeToJson(deformation.cascade);
    json["values"] = valuesToJson(deformation);
    Json visemes = Json::array();
    for (const auto& v : deformation.visemes) visemes.push_back(visemeParametersToJson(v));
    json["visemes"] = std::move(visemes);
    if (!deformation.domain.positions.empty()) json["domain"] = domainToJson(deformation.domain);
    return json;
}

ProjectDeformation deformationFromJson(const JsonNode& node, const ProjectReadContext& context) {
    ProjectDeformation deformation;
    if (node.isNull()) return deformation;
    node.allowOnly({"cascade", "values", "visemes", "domain"});
    if (node.has("domain")) {
        if (context.version < 2)
            node["domain"].fail("a face (u,v) mesh needs project version 2 (this file says " +
                                std::to_string(context.version) + ")");
        deformation.domain = domainFromJson(node["domain"]);
    }
    deformation.cascade = cascadeFromJson(node["cascade"]);
    deformation.values = deformation.cascade.defaults(); // parameters not listed keep their default
    if (node.has("values"))
        for (const auto& [name, value] : node["values"].members()) {
            const double checked =
                parameterValueFromJson(deformation.cascade, name, value); // throws for unknown names
            deformation.values[static_cast<std::size_t>(deformation.cascade.findParameter(name))] = checked;
        }
    if (node.has("visemes")) {
        std::set<std::string> names;
        for (const JsonNode& v : node["visemes"].elements()) {
            v.allowOnly({"name", "values"});
            VisemeParameters viseme;
            viseme.name = v["name"].nonEmptyString();
            if (!names.insert(viseme.name).second)
                v["name"].fail("duplicate viseme name \"" + viseme.name + "\"");
            for (const auto& [name, value] : v["values"].members())
                viseme.values.emplace_back(name, parameterValueFromJson(deformation.cascade, name, value));
            deformation.visemes.push_back(std::move(viseme));
        }
    }
    return deformation;
}

} // namespace vl
