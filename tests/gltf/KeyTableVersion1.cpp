#include "tests/gltf/KeyTableVersion1.h"

#include "core/gltf/GlbContainer.h"
#include "core/reduce/ReducedModel.h"

#include <nlohmann/json.hpp>

namespace vl::test {
namespace {

using Json = nlohmann::ordered_json;

// Every viseme name of the table (members, resting) -> its target on the mesh, as version 1 listed.
Json fullAliases(const Json& root, const Json& extras) {
    Json aliases = extras.value("targetAliases", Json::object());
    const Json names = extras.value("targetNames", Json::array());
    const Json& lists = extras["visemeKeys"];
    const auto targetOf = [&](const std::string& name, const Json* list) -> int {
        for (std::size_t t = 0; t < names.size(); ++t)
            if (names[t] == name) return static_cast<int>(t);
        return list && !list->empty() ? (*list)[0].get<int>() : -1;
    };
    for (std::size_t k = 0; k < root["keys"].size(); ++k)
        for (const Json& m : root["keys"][k]["members"])
            if (!aliases.contains(m.get<std::string>()))
                if (const int t = targetOf(m.get<std::string>(), &lists[k]); t >= 0)
                    aliases[m.get<std::string>()] = t;
    for (const Json& r : root["resting"])
        if (!aliases.contains(r.get<std::string>()))
            if (const int t = targetOf(r.get<std::string>(), nullptr); t >= 0)
                aliases[r.get<std::string>()] = t;
    return aliases;
}

void meshToVersion1(const Json& root, Json& extras) {
    const Json lists = extras["visemeKeys"];
    Json phonemeToTarget = Json::object(), keys = Json::array();
    for (const auto& [phoneme, key] : root["phonemeToKey"].items())
        if (key.get<int>() >= 0 && !lists[key.get<std::size_t>()].empty())
            phonemeToTarget[phoneme] = lists[key.get<std::size_t>()][0];
    for (std::size_t k = 0; k < lists.size(); ++k)
        if (!lists[k].empty())
            keys.push_back({{"key", k},
                            {"name", root["keys"][k]["name"]},
                            {"members", root["keys"][k]["members"]},
                            {"frequency", root["keys"][k]["frequency"]},
                            {"targets", lists[k]}});
    const Json aliases = fullAliases(root, extras);
    extras.erase("visemeKeys");
    extras.erase("targetAliases");
    extras["phonemeToTarget"] = phonemeToTarget;
    extras["visemeKeys"] = keys;
    extras["targetAliases"] = aliases;
}

} // namespace

std::string withKeyTableVersion1(const std::string& glb) {
    const GlbChunks chunks = splitGlb(glb, "version 2 output");
    Json json = Json::parse(chunks.json);
    {
        Json& root = json["extras"]["visemelab"];
        root["version"] = 1;
        for (Json& key : root["keys"])
            if (!key.contains("name"))
                key["name"] = mergedKeyName(key["members"].get<std::vector<std::string>>());
        Json touched = Json::array();
        for (std::size_t m = 0; m < json["meshes"].size(); ++m) {
            Json& mesh = json["meshes"][m];
            if (!mesh.contains("extras") || !mesh["extras"].contains("visemeKeys")) continue;
            meshToVersion1(root, mesh["extras"]);
            touched.push_back(m);
        }
        root["meshes"] = touched;
    }
    return joinGlb(json.dump(), chunks.bin);
}

} // namespace vl::test
