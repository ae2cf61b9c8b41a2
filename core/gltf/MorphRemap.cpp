#include "core/gltf/MorphRemap.h"

#include "core/common/Error.h"
#include "core/gltf/Accessors.h"
#include "core/gltf/GlbRepack.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

std::size_t newCount(const std::vector<int>& remap) {
    return remap.empty() ? 0 : static_cast<std::size_t>(*std::max_element(remap.begin(), remap.end()) + 1);
}

// A weights array of the old targets as one of the new ones (sums of merged members).
void remapWeights(Json& weights, const std::vector<int>& remap) {
    if (!weights.is_array() || weights.size() != remap.size()) return;
    std::vector<double> out(newCount(remap), 0.0);
    for (std::size_t k = 0; k < remap.size(); ++k)
        if (weights[k].is_number()) out[static_cast<std::size_t>(remap[k])] += weights[k].get<double>();
    weights = out;
}

int meshOfNode(const Json& doc, const Json& node) {
    if (!node.is_number_integer()) return -1;
    const auto i = node.get<long long>();
    const auto& nodes = doc["nodes"];
    if (i < 0 || static_cast<std::size_t>(i) >= nodes.size()) return -1;
    return nodes[static_cast<std::size_t>(i)].value("mesh", -1);
}

// The normalised integer layout of a weights output (KHR_mesh_quantization: gltfpack stores weights
// as normalised bytes), or none for floats.
struct NormalisedLayout {
    int componentType = 0;
    double scale = 0; // the largest integer: value = integer / scale
    double lowest = 0, highest = 0;
    std::size_t size = 0;
};

std::optional<NormalisedLayout> normalisedLayoutOf(const Json& accessor) {
    if (!accessor.is_object() || !accessor.value("normalized", false)) return std::nullopt;
    switch (accessor.value("componentType", 0)) {
    case 5120:
        return NormalisedLayout{5120, 127, -1, 1, 1};
    case 5121:
        return NormalisedLayout{5121, 255, 0, 1, 1};
    case 5122:
        return NormalisedLayout{5122, 32767, -1, 1, 2};
    case 5123:
        return NormalisedLayout{5123, 65535, 0, 1, 2};
    default:
        return std::nullopt;
    }
}

// The remapped weights stored as the input stored them: normalised integers on the same grid when the
// input was quantised and every sum still fits the type's range (the members' integers add exactly),
// floats otherwise. Floats where gltfpack had bytes made outputs 4x their animation (issue 29).
Json weightsAccessor(GlbRepack& out, const std::vector<float>& weights, const Json& oldAccessor) {
    const auto layout = normalisedLayoutOf(oldAccessor);
    const bool fits = layout && std::all_of(weights.begin(), weights.end(), [&](float w) {
                          return w >= layout->lowest - 1e-6 && w <= layout->highest + 1e-6;
                      });
    if (!fits) {
        std::string bytes(weights.size() * 4, '\0');
        std::memcpy(bytes.data(), weights.data(), bytes.size());
        return {{"bufferView", out.addView(std::move(bytes))},
                {"componentType", 5126},
                {"count", weights.size()},
                {"type", "SCALAR"}};
    }
    std::string bytes(weights.size() * layout->size, '\0');
    for (std::size_t i = 0; i < weights.size(); ++i) {
        const double clamped = std::clamp(static_cast<double>(weights[i]), layout->lowest, layout->highest);
        const auto integer = static_cast<long>(std::lround(clamped * layout->scale));
        if (layout->size == 1) {
            const auto byte = static_cast<std::int8_t>(integer);
            std::memcpy(bytes.data() + i, &byte, 1);
        } else {
            const auto half = static_cast<std::int16_t>(integer);
            std::memcpy(bytes.data() + 2 * i, &half, 2);
        }
    }
    return {{"bufferView", out.addView(std::move(bytes))},
            {"componentType", layout->componentType},
            {"normalized", true},
            {"count", weights.size()},
            {"type", "SCALAR"}};
}

void remapAnimations(GlbRepack& out, AccessorReader& reader, const std::map<int, std::vector<int>>& remaps) {
    Json& doc = out.json;
    if (!doc.contains("animations") || !doc["animations"].is_array()) return;
    for (std::size_t a = 0; a < doc["animations"].size(); ++a) {
        Json& animation = doc["animations"][a];
        if (!animation.contains("channels") || !animation.contains("samplers")) continue;
        std::map<std::pair<int, int>, int> samplerFor; // (original sampler, mesh) -> sampler
        std::vector<char> rewritten(animation["samplers"].size(), 0);
        for (std::size_t c = 0; c < animation["channels"].size(); ++c) {
            Json& channel = animation["channels"][c];
            const Json& target = channel.value("target", Json::object());
            if (target.value("path", "") != "weights" || !target.contains("node")) continue;
            const int mesh = meshOfNode(doc, target["node"]);
            const auto remap = remaps.find(mesh);
            if (remap == remaps.end()) continue;
            const int sampler = channel.value("sampler", -1);
            if (sampler < 0 || static_cast<std::size_t>(sampler) >= animation["samplers"].size()) continue;
            if (const auto done = samplerFor.find({sampler, mesh}); done != samplerFor.end()) {
                channel["sampler"] = done->second;
                continue;
            }
            const std::string where =
                "animations/" + std::to_string(a) + "/samplers/" + std::to_string(sampler);
            Json copy = animation["samplers"][static_cast<std::size_t>(sampler)];
            const int output = copy.value("output", -1);
            const std::vector<float> old = reader.floats(output, TINYGLTF_TYPE_SCALAR, where + "/output");
            const std::size_t oldTargets = remap->second.size(), targets = newCount(remap->second);
            if (oldTargets == 0 || old.size() % oldTargets != 0)
                throwInputError(where, "output holds " + std::to_string(old.size()) +
                                           " weights, not a multiple of the mesh's " +
                                           std::to_string(oldTargets) + " morph targets");
            std::vector<float> weights(old.size() / oldTargets * targets, 0.0f);
            for (std::size_t row = 0; row < old.size() / oldTargets; ++row)
                for (std::size_t k = 0; k < oldTargets; ++k)
                    weights[row * targets + static_cast<std::size_t>(remap->second[k])] +=
                        old[row * oldTargets + k];
            const Json& oldAccessor = doc["accessors"][static_cast<std::size_t>(output)];
            out.mayDrop(output);
            copy["output"] = out.addAccessor(weightsAccessor(out, weights, oldAccessor));
            int index = sampler;
            if (rewritten[static_cast<std::size_t>(
                    sampler)]) { // used by another mesh too: a sampler of its own
                index = static_cast<int>(animation["samplers"].size());
                animation["samplers"].push_back(copy);
            } else {
                animation["samplers"][static_cast<std::size_t>(sampler)] = copy;
                rewritten[static_cast<std::size_t>(sampler)] = 1;
            }
            samplerFor[{sampler, mesh}] = index;
            channel["sampler"] = index;
        }
    }
}

// Remaps binds[] entries {<owner>, index, weight}; `meshOf` gives the bind's mesh.
template <typename MeshOf>
void remapBinds(Json& binds, const std::map<int, std::vector<int>>& remaps, MeshOf meshOf) {
    if (!binds.is_array()) return;
    Json kept = Json::array();
    for (Json& bind : binds) {
        if (!bind.is_object() || !bind.contains("index") || !bind["index"].is_number_integer()) {
            kept.push_back(bind);
            continue;
        }
        const int mesh = meshOf(bind);
        const auto remap = remaps.find(mesh);
        const auto index = bind["index"].get<long long>();
        if (remap != remaps.end() && index >= 0 && static_cast<std::size_t>(index) < remap->second.size())
            bind["index"] = remap->second[static_cast<std::size_t>(index)];
        const auto same = std::find_if(kept.begin(), kept.end(), [&](const Json& k) {
            return k.is_object() && meshOf(k) == mesh && k.value("index", -1) == bind["index"].get<int>() &&
                   k.value("node", -1) == bind.value("node", -1);
        });
        if (same == kept.end()) {
            kept.push_back(bind);
        } else if (bind.value("weight", 0.0) > same->value("weight", 0.0)) {
            (*same)["weight"] = bind["weight"];
        }
    }
    binds = kept;
}

void remapVrm(Json& doc, const std::map<int, std::vector<int>>& remaps) {
    if (!doc.contains("extensions") || !doc["extensions"].is_object()) return;
    Json& ext = doc["extensions"];
    // VRM 0.x: blendShapeMaster.blendShapeGroups[].binds[] {mesh, index, weight 0..100}
    if (ext.contains("VRM") && ext["VRM"].is_object() && ext["VRM"].contains("blendShapeMaster")) {
        Json& master = ext["VRM"]["blendShapeMaster"];
        if (master.is_object() && master.contains("blendShapeGroups") &&
            master["blendShapeGroups"].is_array())
            for (Json& group : master["blendShapeGroups"])
                if (group.is_object() && group.contains("binds"))
                    remapBinds(group["binds"], remaps, [](const Json& b) { return b.value("mesh", -1); });
    }
    // VRM 1.0: expressions.{preset,custom}.<name>.morphTargetBinds[] {node, index, weight 0..1}
    if (ext.contains("VRMC_vrm") && ext["VRMC_vrm"].is_object() && ext["VRMC_vrm"].contains("expressions")) {
        Json& expressions = ext["VRMC_vrm"]["expressions"];
        for (const char* kind : {"preset", "custom"}) {
            if (!expressions.is_object() || !expressions.contains(kind) || !expressions[kind].is_object())
                continue;
            for (auto& [name, expression] : expressions[kind].items())
                if (expression.is_object() && expression.contains("morphTargetBinds"))
                    remapBinds(expression["morphTargetBinds"], remaps, [&](const Json& b) {
                        return b.contains("node") ? meshOfNode(doc, b["node"]) : -1;
                    });
        }
    }
}

} // namespace

void remapMorphTargets(GlbRepack& out, AccessorReader& reader,
                       const std::map<int, std::vector<int>>& remaps) {
    Json& json = out.json;
    for (const auto& [mesh, remap] : remaps) {
        Json& meshJson = json["meshes"][static_cast<std::size_t>(mesh)];
        if (meshJson.contains("weights")) remapWeights(meshJson["weights"], remap);
    }
    if (json.contains("nodes") && json["nodes"].is_array())
        for (Json& node : json["nodes"]) {
            const auto remap = remaps.find(node.value("mesh", -1));
            if (remap != remaps.end() && node.contains("weights"))
                remapWeights(node["weights"], remap->second);
        }
    remapAnimations(out, reader, remaps);
    remapVrm(json, remaps);
}

} // namespace vl
