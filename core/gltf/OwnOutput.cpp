#include "core/gltf/OwnOutput.h"

#include "core/gltf/GltfDocument.h"
#include "core/gltf/KeyTable.h"
#include "core/gltf/TargetNames.h"
#include "core/reduce/ReducedModel.h"

#include <algorithm>
#include <set>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

// Hostile extras can hold millions of bad entries: the first few are named, the rest counted.
constexpr std::size_t kMaxNotes = 12;
// As many keys as an avatar can have visemes (AvatarScan.h kMaxAvatarVisemes): each mesh holds a
// list per key, so the count must not come from the file unchecked.
constexpr std::size_t kMaxOwnKeys = 64;

void note(OwnOutput& own, const std::string& where, const std::string& what) {
    if (own.notes.size() < kMaxNotes)
        own.notes.push_back(where + ": " + what);
    else if (own.notes.size() == kMaxNotes)
        own.notes.push_back("further elements of VisemeLab's extras ignored");
}

const Json* field(const Json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
}

int indexBelow(const Json& value, std::size_t size) {
    if (!value.is_number_integer()) return -1;
    const auto i = value.get<long long>();
    return i >= 0 && static_cast<std::size_t>(i) < size ? static_cast<int>(i) : -1;
}

// The root key table; false (with a note) when it cannot be used at all.
bool readKeys(const Json& root, OwnOutput& own) {
    const Json* version = field(root, "version");
    const long long read = version ? (version->is_number_integer() ? version->get<long long>() : -1) : 1;
    if (read < 1 || read > kKeyTableVersion) {
        note(own, "/extras/visemelab/version",
             "expected 1 or " + std::to_string(kKeyTableVersion) + " (the versions this VisemeLab reads)");
        return false;
    }
    own.version = static_cast<int>(read);
    const Json* names = field(root, "names");
    if (!names || !names->is_string() ||
        (names->get<std::string>() != "original" && names->get<std::string>() != "merged")) {
        note(own, "/extras/visemelab/names", "expected \"original\" or \"merged\"");
        return false;
    }
    own.mergedNames = names->get<std::string>() == "merged";
    const Json* keys = field(root, "keys");
    if (!keys || !keys->is_array() || keys->empty() || keys->size() > kMaxOwnKeys) {
        note(own, "/extras/visemelab/keys",
             "expected a non-empty array of at most " + std::to_string(kMaxOwnKeys) + " keys");
        return false;
    }
    std::set<std::string> seen;
    for (std::size_t k = 0; k < keys->size(); ++k) {
        const std::string where = "/extras/visemelab/keys/" + std::to_string(k);
        const Json* members = field((*keys)[k], "members");
        OwnKey key;
        if (members && members->is_array())
            for (const Json& m : *members)
                if (m.is_string() && !m.get<std::string>().empty())
                    key.members.push_back(m.get<std::string>());
        if (!members || key.members.empty() || key.members.size() != members->size()) {
            note(own, where + "/members", "expected a non-empty array of names");
            return false;
        }
        for (const std::string& m : key.members)
            if (!seen.insert(m).second) {
                note(own, where + "/members", "'" + m + "' is a member of another key too");
                return false;
            }
        const Json* name = field((*keys)[k], "name");
        key.name = name && name->is_string() && !name->get<std::string>().empty()
                       ? name->get<std::string>()
                       : mergedKeyName(key.members);
        if (const Json* f = field((*keys)[k], "frequency"); f && f->is_number())
            key.frequency = f->get<double>();
        own.keys.push_back(std::move(key));
    }
    if (const Json* resting = field(root, "resting")) {
        if (!resting->is_array())
            note(own, "/extras/visemelab/resting", "expected an array of names; ignored");
        for (std::size_t i = 0; resting->is_array() && i < resting->size(); ++i) {
            const Json& r = (*resting)[i];
            if (!r.is_string() || seen.count(r.get<std::string>()))
                note(own, "/extras/visemelab/resting/" + std::to_string(i),
                     "not a viseme name outside the keys; ignored");
            else if (seen.insert(r.get<std::string>()).second)
                own.resting.push_back(r.get<std::string>());
        }
    }
    return true;
}

// Entry i of a mesh's visemeKeys: its key and its list of targets, or key -1. Version 2 lists the
// targets of key i as an array; version 1 wrote {key, name, members, frequency, targets} objects.
std::pair<int, const Json*> keyEntry(const Json& entry, std::size_t i, std::size_t keys) {
    if (entry.is_array()) return {i < keys ? static_cast<int>(i) : -1, &entry};
    const Json* key = field(entry, "key");
    const Json* targets = field(entry, "targets");
    return {key && targets && targets->is_array() ? indexBelow(*key, keys) : -1, targets};
}

// The mesh's targets of each key, read from extras.visemeKeys (either version).
void readKeyTargets(const Json& table, const std::string& where, const std::vector<TargetName>& names,
                    OwnMesh& mesh, OwnOutput& own) {
    std::vector<bool> claimed(names.size(), false);
    for (std::size_t i = 0; i < table.size(); ++i) {
        const std::string at = where + "/visemeKeys/" + std::to_string(i);
        const auto [key, targets] = keyEntry(table[i], i, own.keys.size());
        if (key < 0) {
            note(own, at,
                 "expected the targets of key " + std::to_string(i) + " (an array; version 1: {key below " +
                     std::to_string(own.keys.size()) + ", targets}); ignored");
            continue;
        }
        auto& list = mesh.keyTargets[static_cast<std::size_t>(key)];
        if (!list.empty()) {
            note(own, at, "key " + std::to_string(key) + " listed twice on the mesh; ignored");
            continue;
        }
        const std::string targetsAt = table[i].is_array() ? at : at + "/targets";
        for (const Json& t : *targets) {
            const int target = indexBelow(t, names.size());
            if (target < 0 || claimed[static_cast<std::size_t>(target)]) {
                note(own, targetsAt, "not a target of the mesh, or one another key has; ignored");
                continue;
            }
            claimed[static_cast<std::size_t>(target)] = true;
            list.push_back(target);
        }
        if (own.mergedNames && !list.empty() &&
            names[static_cast<std::size_t>(list.front())].name !=
                own.keys[static_cast<std::size_t>(key)].name)
            note(own, at,
                 "its target is named '" + names[static_cast<std::size_t>(list.front())].name +
                     "', the key '" + own.keys[static_cast<std::size_t>(key)].name + "'");
    }
}

// The mesh's extras.targetNames as three.js reads them (an entry that is no string names nothing).
std::vector<std::string> extrasTargetNames(const Json& extras, std::size_t targets) {
    std::vector<std::string> out;
    const Json* names = field(extras, "targetNames");
    for (std::size_t t = 0; names && names->is_array() && t < names->size() && t < targets; ++t)
        out.push_back((*names)[t].is_string() ? (*names)[t].get<std::string>() : std::string());
    return out;
}

// Every viseme name the table knows that resolves on the mesh: by targetNames, else by the mesh's
// extras.targetAliases (version 1 lists every name, version 2 only those the next rule misses), else
// by the key listing it (core/gltf/KeyTable.h). Aliases of other names (a mesh's own spelling) are kept.
void readAliases(const Json& extras, const std::string& where, std::size_t targets, OwnMesh& mesh,
                 OwnOutput& own) {
    if (const Json* aliases = field(extras, "targetAliases")) {
        if (!aliases->is_object()) note(own, where + "/targetAliases", "not an object; ignored");
        for (auto it = aliases->begin(); aliases->is_object() && it != aliases->end(); ++it) {
            const int target = indexBelow(it.value(), targets);
            if (target < 0)
                note(own, where + "/targetAliases/" + it.key(), "not a target of the mesh; ignored");
            else
                mesh.aliases[it.key()] = target;
        }
    }
    const std::vector<std::string> targetNames = extrasTargetNames(extras, targets);
    std::vector<std::vector<std::string>> members;
    for (const OwnKey& key : own.keys) members.push_back(key.members);
    std::vector<std::string> visemes = own.resting;
    for (const auto& m : members) visemes.insert(visemes.end(), m.begin(), m.end());
    for (const std::string& name : visemes) {
        if (const int named = impliedTarget(name, targetNames, {}, {}); named >= 0)
            mesh.aliases[name] = named;
        else if (const int keyed = impliedTarget(name, {}, members, mesh.keyTargets);
                 keyed >= 0 && !mesh.aliases.count(name))
            mesh.aliases[name] = keyed;
    }
}

// Mesh m's key table and aliases, entries that do not fit ignored with a note.
void readMesh(const GltfDocument& doc, std::size_t m, OwnOutput& own) {
    const Json& meshJson = doc.json["meshes"][m];
    const Json* extras = field(meshJson, "extras");
    const Json* table = extras ? field(*extras, "visemeKeys") : nullptr;
    if (!table) return;
    const std::string where = "/meshes/" + std::to_string(m) + "/extras";
    if (!table->is_array()) {
        note(own, where + "/visemeKeys", "not an array; ignored");
        return;
    }
    const std::vector<TargetName> names = meshTargetNames(doc, static_cast<int>(m));
    OwnMesh mesh{static_cast<int>(m), std::vector<std::vector<int>>(own.keys.size()), {}};
    readKeyTargets(*table, where, names, mesh, own);
    if (std::none_of(mesh.keyTargets.begin(), mesh.keyTargets.end(),
                     [](const auto& l) { return !l.empty(); }))
        return;
    readAliases(*extras, where, names.size(), mesh, own);
    own.meshes.push_back(std::move(mesh));
}

} // namespace

std::size_t OwnOutput::visemeCount() const {
    std::size_t n = resting.size();
    for (const OwnKey& key : keys) n += key.members.size();
    return n;
}

int OwnOutput::keyOfTarget(int mesh, int target) const {
    // meshes are in index order: a binary search keeps the scan linear in the file's targets.
    const auto it = std::lower_bound(meshes.begin(), meshes.end(), mesh,
                                     [](const OwnMesh& m, int index) { return m.mesh < index; });
    if (it == meshes.end() || it->mesh != mesh) return -1;
    for (std::size_t k = 0; k < it->keyTargets.size(); ++k)
        if (!it->keyTargets[k].empty() && it->keyTargets[k].front() == target) return static_cast<int>(k);
    return -1;
}

bool OwnOutput::isResting(const std::string& name) const {
    return std::find(resting.begin(), resting.end(), name) != resting.end();
}

OwnOutput recogniseOwnOutput(const GltfDocument& doc) {
    OwnOutput own;
    const Json* extras = field(doc.json, "extras");
    const Json* root = extras ? field(*extras, "visemelab") : nullptr;
    if (!root) return own;
    if (!root->is_object() || !readKeys(*root, own)) {
        if (!root->is_object()) note(own, "/extras/visemelab", "not an object");
        own.keys.clear();
        own.resting.clear();
        own.version = 0;
        own.notes.push_back("not read as VisemeLab's output");
        return own;
    }
    readOwnMeshes(doc, own);
    if (!own.recognised)
        own.notes.push_back("no mesh lists its keys (extras.visemeKeys): not read as VisemeLab's output");
    return own;
}

void readOwnMeshes(const GltfDocument& doc, OwnOutput& own) {
    own.meshes.clear();
    const Json* meshes = field(doc.json, "meshes");
    for (std::size_t m = 0; meshes && meshes->is_array() && m < meshes->size() && m < doc.model.meshes.size();
         ++m)
        readMesh(doc, m, own);
    own.recognised = !own.meshes.empty();
}

std::string describeOwnOutput(const OwnOutput& own) {
    return "reduced by VisemeLab: " + std::to_string(own.keys.size()) + " keys from " +
           std::to_string(own.visemeCount()) + " visemes (names " +
           (own.mergedNames ? "merged" : "original") + ")";
}

} // namespace vl
