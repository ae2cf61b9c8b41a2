#include "core/project/FieldJson.h"

#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/project/BuiltinGeometry.h"

#include <map>
#include <mutex>
#include <optional>

namespace vl {

namespace {

constexpr face::Individual kIndividuals[] = {face::Individual::Bundled, face::Individual::Retarget};
constexpr int kMaxGridSize = 4097; // face::makeFaceGeometry's limit, and plenty for a geometry image

// Built-in geometry images are generated once per (individual, size) and kept: saving compares
// against them and loading regenerates them.
const SampledField& builtinGeometry(face::Individual who, int size) {
    static std::mutex mutex;
    static std::map<std::pair<face::Individual, int>, SampledField> cache;
    const std::lock_guard lock(mutex);
    auto it = cache.find({who, size});
    if (it == cache.end()) it = cache.emplace(std::pair{who, size}, face::makeFaceGeometry(who, size)).first;
    return it->second;
}

std::optional<face::Individual> builtinOf(const SampledField& grid) {
    if (grid.width != grid.height || grid.width < 2 || grid.width > kMaxGridSize) return std::nullopt;
    if (grid.samples.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height))
        return std::nullopt;
    for (const auto who : kIndividuals)
        if (builtinGeometry(who, grid.width).samples == grid.samples) return who;
    return std::nullopt;
}

} // namespace

std::optional<face::Individual> builtinIndividualOf(const DeformationCascade& cascade) {
    for (auto stage = cascade.stages.rbegin(); stage != cascade.stages.rend(); ++stage)
        if (stage->kind == StageKind::Constant) return builtinOf(stage->field.sampled);
    return std::nullopt;
}

namespace {

Json pair(const Vec2& v) {
    return Json::array({v[0], v[1]});
}
Json triple(const Vec3& v) {
    return Json::array({v[0], v[1], v[2]});
}

Json sampledToJson(const SampledField& grid) {
    if (grid.empty() && grid.width == 0 && grid.height == 0) return nullptr;
    Json json = Json::object();
    if (const auto who = builtinOf(grid)) json["builtin"] = toString(*who);
    json["width"] = grid.width;
    json["height"] = grid.height;
    if (!json.contains("builtin")) {
        Json samples = Json::array();
        for (const Vec3& s : grid.samples) samples.push_back(triple(s));
        json["samples"] = std::move(samples);
    }
    return json;
}

SampledField sampledFromJson(const JsonNode& node) {
    SampledField grid;
    if (node.isNull()) return grid;
    node.expectObject();
    const bool builtin = node.has("builtin");
    if (builtin)
        node.allowOnly({"builtin", "width", "height"});
    else
        node.allowOnly({"width", "height", "samples"});
    grid.width = static_cast<int>(node["width"].integerInRange(1, kMaxGridSize));
    grid.height = static_cast<int>(node["height"].integerInRange(1, kMaxGridSize));
    if (builtin) {
        const JsonNode name = node["builtin"];
        const auto who = parseEnum<face::Individual>(name.string(), name.path());
        if (grid.width != grid.height || grid.width < 2)
            node["height"].fail("a built-in geometry is a square grid of at least 2 x 2, found " +
                                std::to_string(grid.width) + " x " + std::to_string(grid.height));
        return builtinGeometry(who, grid.width);
    }
    const JsonNode samples = node["samples"];
    const auto expected = static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
    if (samples.size() != expected)
        samples.fail("expected " + std::to_string(expected) + " samples (width x height), found " +
                     std::to_string(samples.size()));
    grid.samples.reserve(expected);
    for (const JsonNode& s : samples.elements()) grid.samples.push_back(s.vec3());
    return grid;
}

Json influenceToJson(const InfluenceField& r) {
    Json json = Json::object();
    json["centre"] = pair(r.centre);
    json["radii"] = pair(r.radii);
    json["plateau"] = pair(r.plateau);
    json["rotation"] = r.rotation;
    json["direction"] = triple(r.direction);
    json["magnitude"] = r.magnitude;
    json["falloff"] = toString(r.falloff);
    return json;
}

InfluenceField influenceFromJson(const JsonNode& node) {
    node.allowOnly({"centre", "radii", "plateau", "rotation", "direction", "magnitude", "falloff"});
    InfluenceField r;
    r.centre = node["centre"].vec2();
    const JsonNode radii = node["radii"];
    r.radii = radii.vec2();
    if (r.radii[0] <= 0.0 || r.radii[1] <= 0.0) radii.fail("radii must be positive");
    const JsonNode plateau = node["plateau"];
    r.plateau = plateau.vec2();
    const bool none = r.plateau[0] == 0.0 && r.plateau[1] == 0.0;
    const bool inside =
        r.plateau[0] > 0.0 && r.plateau[1] > 0.0 && r.plateau[0] < r.radii[0] && r.plateau[1] < r.radii[1];
    if (!none && !inside)
        plateau.fail("plateau radii must both be 0 or both lie strictly between 0 and the radii");
    r.rotation = node["rotation"].number();
    const JsonNode direction = node["direction"];
    r.direction = direction.vec3();
    if (r.direction.norm() == 0.0) direction.fail("direction must not be the zero vector");
    r.magnitude = node["magnitude"].number();
    const JsonNode falloff = node["falloff"];
    r.falloff = parseEnum<Falloff>(falloff.string(), falloff.path());
    return r;
}

} // namespace

Json vectorFieldToJson(const VectorField& field) {
    Json json = Json::object();
    json["sampled"] = sampledToJson(field.sampled);
    Json influences = Json::array();
    for (const auto& r : field.influences) influences.push_back(influenceToJson(r));
    json["influences"] = std::move(influences);
    return json;
}

VectorField vectorFieldFromJson(const JsonNode& node) {
    node.allowOnly({"sampled", "influences"});
    VectorField field;
    if (node.has("sampled")) field.sampled = sampledFromJson(node["sampled"]);
    if (node.has("influences"))
        for (const JsonNode& r : node["influences"].elements())
            field.influences.push_back(influenceFromJson(r));
    validateField(field, node.path()); // the module's own rules, in case they grow beyond the checks above
    return field;
}

} // namespace vl
