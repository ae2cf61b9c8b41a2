#include "core/gltf/AvatarKeyTargets.h"

#include "core/common/JsonParse.h"
#include "core/gltf/GlbContainer.h"

#include <algorithm>
#include <map>

namespace vl {

namespace {

// A target's name from the mesh's targetNames extras, else its index (a file may name none).
std::string targetName(const Json& extras, const Json& target) {
    if (!target.is_number_integer()) return "?";
    const auto index = target.get<long long>();
    const Json* names = extras.contains("targetNames") ? &extras["targetNames"] : nullptr;
    if (names && names->is_array() && index >= 0 && static_cast<std::size_t>(index) < names->size() &&
        (*names)[static_cast<std::size_t>(index)].is_string())
        return (*names)[static_cast<std::size_t>(index)].get<std::string>();
    return "#" + std::to_string(index);
}

std::string quotedList(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
    return text;
}

} // namespace

std::vector<AvatarKeyTargets> avatarKeyTargets(std::string_view glb, std::string_view source) {
    const Json root = parseJsonStrict(splitGlb(glb, source).json, source);
    std::map<int, AvatarKeyTargets> byKey;
    if (!root.contains("meshes") || !root["meshes"].is_array()) return {};
    const Json& meshes = root["meshes"];
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const Json& mesh = meshes[m];
        if (!mesh.is_object() || !mesh.contains("extras") || !mesh["extras"].is_object()) continue;
        const Json& extras = mesh["extras"];
        if (!extras.contains("visemeKeys") || !extras["visemeKeys"].is_array()) continue;
        const std::string meshName = mesh.contains("name") && mesh["name"].is_string()
                                         ? mesh["name"].get<std::string>()
                                         : "mesh #" + std::to_string(m);
        for (const Json& entry : extras["visemeKeys"]) {
            if (!entry.is_object() || !entry.contains("key") || !entry["key"].is_number_integer()) continue;
            AvatarKeyTargets& key = byKey[entry["key"].get<int>()];
            key.key = entry["key"].get<int>();
            if (entry.contains("name") && entry["name"].is_string())
                key.name = entry["name"].get<std::string>();
            std::vector<std::string> targets;
            if (entry.contains("targets") && entry["targets"].is_array())
                for (const Json& target : entry["targets"]) targets.push_back(targetName(extras, target));
            key.meshes.emplace_back(meshName, std::move(targets));
        }
    }
    std::vector<AvatarKeyTargets> keys;
    for (auto& [index, key] : byKey) keys.push_back(std::move(key));
    return keys;
}

std::vector<std::string> formatAvatarKeyTargets(const std::vector<AvatarKeyTargets>& keys) {
    std::vector<std::string> lines;
    for (const AvatarKeyTargets& key : keys) {
        // Meshes whose targets have the same names are listed together (the head and teeth of an RPM).
        std::vector<std::pair<std::vector<std::string>, std::string>> same;
        for (const auto& entry : key.meshes) { // not a structured binding: clang 14 cannot capture one
            const auto& [mesh, targets] = entry;
            const auto it = std::find_if(same.begin(), same.end(),
                                         [&](const auto& s) { return s.first == entry.second; });
            if (it == same.end())
                same.emplace_back(targets, mesh);
            else
                it->second += ", " + mesh;
        }
        std::string line = "key " + std::to_string(key.key) + " (" + key.name + "):";
        for (std::size_t i = 0; i < same.size(); ++i)
            line += (i ? "; " : " ") + std::string(same[i].first.size() == 1 ? "target " : "targets ") +
                    quotedList(same[i].first) + " on " + same[i].second;
        lines.push_back(std::move(line));
    }
    return lines;
}

} // namespace vl
