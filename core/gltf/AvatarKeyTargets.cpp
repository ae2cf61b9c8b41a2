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

// Each key's name from the root table (version 2 meshes name no keys): its "name", else its members
// joined with '+' (core/gltf/KeyTable.h).
std::vector<std::string> rootKeyNames(const Json& root) {
    std::vector<std::string> names;
    const Json* extras = root.contains("extras") && root["extras"].is_object() ? &root["extras"] : nullptr;
    const Json* table = extras && extras->contains("visemelab") ? &(*extras)["visemelab"] : nullptr;
    if (!table || !table->is_object() || !table->contains("keys") || !(*table)["keys"].is_array())
        return names;
    for (const Json& key : (*table)["keys"]) {
        std::string name;
        if (key.is_object() && key.contains("name") && key["name"].is_string())
            name = key["name"].get<std::string>();
        if (name.empty() && key.is_object() && key.contains("members") && key["members"].is_array())
            for (const Json& m : key["members"])
                if (m.is_string()) name += (name.empty() ? "" : "+") + m.get<std::string>();
        names.push_back(name);
    }
    return names;
}

// Entry i of a mesh's visemeKeys as {key, name, targets}: version 2 lists key i's targets as an
// array (named by the root table), version 1 an object {key, name, targets}; key -1 when neither.
struct KeyEntry {
    int key = -1;
    std::string name;
    const Json* targets = nullptr;
};

KeyEntry keyEntry(const Json& entry, std::size_t i, const std::vector<std::string>& rootNames) {
    if (entry.is_array())
        return {static_cast<int>(i), i < rootNames.size() ? rootNames[i] : std::string(), &entry};
    if (!entry.is_object() || !entry.contains("key") || !entry["key"].is_number_integer()) return {};
    KeyEntry out{entry["key"].get<int>(), "", nullptr};
    if (entry.contains("name") && entry["name"].is_string()) out.name = entry["name"].get<std::string>();
    if (entry.contains("targets") && entry["targets"].is_array()) out.targets = &entry["targets"];
    return out;
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
    const std::vector<std::string> names = rootKeyNames(root);
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const Json& mesh = meshes[m];
        if (!mesh.is_object() || !mesh.contains("extras") || !mesh["extras"].is_object()) continue;
        const Json& extras = mesh["extras"];
        if (!extras.contains("visemeKeys") || !extras["visemeKeys"].is_array()) continue;
        const std::string meshName = mesh.contains("name") && mesh["name"].is_string()
                                         ? mesh["name"].get<std::string>()
                                         : "mesh #" + std::to_string(m);
        for (std::size_t i = 0; i < extras["visemeKeys"].size(); ++i) {
            const KeyEntry entry = keyEntry(extras["visemeKeys"][i], i, names);
            if (entry.key < 0 || (entry.targets && entry.targets->empty())) continue; // not on this mesh
            AvatarKeyTargets& key = byKey[entry.key];
            key.key = entry.key;
            if (!entry.name.empty()) key.name = entry.name;
            std::vector<std::string> targets;
            if (entry.targets)
                for (const Json& target : *entry.targets) targets.push_back(targetName(extras, target));
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
