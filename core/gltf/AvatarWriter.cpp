#include "core/gltf/AvatarWriter.h"

#include "core/common/Error.h"
#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarPlacement.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GlbRepack.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/GltfReferences.h"
#include "core/gltf/KeyTable.h"
#include "core/gltf/MergedNames.h"
#include "core/gltf/MorphRemap.h"
#include "core/gltf/TargetStorage.h"
#include "core/reduce/Reduction.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kTargetAttributes[] = {"POSITION", "NORMAL", "TANGENT"};

int attribute(const std::map<std::string, int>& attributes, const char* name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

// Groups of the reduction and each viseme's weight inside its group's mean (eq. 19 of the paper: the
// frequency-weighted mean; a group of zero total frequency takes the plain mean, as mergeGroup does).
struct KeyGrouping {
    std::vector<int> groupOf;
    std::vector<double> weightInGroup;
    std::vector<std::size_t> size;

    KeyGrouping(const std::vector<int>& groups, const std::vector<double>& frequencies, std::size_t keys)
        : groupOf(groups), weightInGroup(groups.size()), size(keys, 0) {
        std::vector<double> total(keys, 0.0);
        for (std::size_t i = 0; i < groups.size(); ++i) {
            if (groups[i] == kRestGroup) continue; // rests: in no key
            ++size[static_cast<std::size_t>(groups[i])];
            total[static_cast<std::size_t>(groups[i])] += frequencies[i];
        }
        for (std::size_t i = 0; i < groups.size(); ++i) {
            if (groups[i] == kRestGroup) continue;
            const auto g = static_cast<std::size_t>(groups[i]);
            weightInGroup[i] = total[g] > 0 ? frequencies[i] / total[g] : 1.0 / static_cast<double>(size[g]);
        }
    }
};

// The reduced keys on one mesh: which of its targets belong to which key, and where they go.
struct MeshPlan {
    std::vector<std::vector<std::size_t>> members; // per key: the mesh's targets of its visemes
    std::vector<int> remap;                        // old target -> new target
    std::vector<std::string> names;                // new target names
    std::vector<int> keyTarget;                    // per key: its (first) target after writing, or -1
};

// The name every key is recorded under. Merged names: its target's name (core/gltf/MergedNames.h),
// unique among the targets kept as they are on every mesh carrying visemes, so that one key has one
// name on all of them. Original names: no target carries the key's name, which stays the model's
// (members joined by '+'), so that speech read back from the file names keys as the reduction did.
std::vector<std::string> recordedKeyNames(const AvatarScan& scan, const KeyGrouping& grouping,
                                          const ReducedModel& model, AvatarNames names) {
    if (names == AvatarNames::Original) {
        std::vector<std::string> out;
        for (const KeyMesh& key : model.keys) out.push_back(key.name);
        return out;
    }
    std::vector<std::string> kept;
    for (const AvatarMesh& mesh : scan.meshes)
        for (const AvatarTarget& t : mesh.targets)
            if (mesh.carriesVisemes &&
                (t.viseme < 0 || grouping.groupOf[static_cast<std::size_t>(t.viseme)] == kRestGroup))
                kept.push_back(t.name);
    std::vector<std::vector<std::string>> members;
    for (const KeyMesh& key : model.keys) members.push_back(key.members);
    return mergedTargetNames(members, kept);
}

MeshPlan planMesh(const AvatarMesh& mesh, const KeyGrouping& grouping, const ReducedModel& model,
                  const std::vector<std::string>& keyNames, AvatarNames names) {
    MeshPlan plan;
    plan.members.resize(model.keys.size());
    plan.keyTarget.assign(model.keys.size(), -1);
    plan.remap.assign(mesh.targets.size(), -1);
    for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
        const AvatarTarget& t = mesh.targets[k];
        const int key = t.viseme < 0 ? -1 : grouping.groupOf[static_cast<std::size_t>(t.viseme)];
        if (key >= 0) plan.members[static_cast<std::size_t>(key)].push_back(k);
        if (names == AvatarNames::Original || key < 0) {
            plan.remap[k] = static_cast<int>(plan.names.size());
            plan.names.push_back(t.name);
            if (key >= 0 && plan.keyTarget[static_cast<std::size_t>(key)] < 0)
                plan.keyTarget[static_cast<std::size_t>(key)] = plan.remap[k];
            continue;
        }
        int& target = plan.keyTarget[static_cast<std::size_t>(key)];
        if (target < 0) {
            target = static_cast<int>(plan.names.size());
            plan.names.push_back(keyNames[static_cast<std::size_t>(key)]);
        }
        plan.remap[k] = target;
    }
    return plan;
}

// What the key targets are written with: the reader of the members, and the tally of storages.
struct KeyWriting {
    const GltfDocument& doc;
    BufferViews& views;
    AccessorReader& reader;
    StorageTally tally;
};

// The sculpted visemes' POSITION displacements on one primitive, in the mesh's own space: per viseme,
// 3 x vertices floats, or empty where the viseme is as in the file on this primitive.
struct PrimitiveSculpts {
    std::vector<std::vector<float>> local;
    const std::vector<float>* of(int viseme) const {
        return static_cast<std::size_t>(viseme) < local.size() &&
                       !local[static_cast<std::size_t>(viseme)].empty()
                   ? &local[static_cast<std::size_t>(viseme)]
                   : nullptr;
    }
};

PrimitiveSculpts primitiveSculpts(const GltfDocument& doc, const AvatarScan& scan, const AvatarMesh& mesh,
                                  std::size_t p, const std::vector<std::vector<Vec3>>* sculpted) {
    PrimitiveSculpts out;
    if (!sculpted) return out;
    const std::size_t first = mesh.primitives[p].firstVertex, vertices = mesh.primitives[p].vertices;
    const auto& neutral = scan.set.neutral.positions;
    std::vector<glm::dmat3> inverses; // computed on the first sculpted viseme met
    for (std::size_t i = 0; i < sculpted->size() && i < scan.set.size(); ++i) {
        const std::vector<Vec3>& edited = (*sculpted)[i];
        const std::vector<Vec3>& original = scan.set.visemes[i].positions;
        if (edited.size() != neutral.size()) continue;
        bool changed = false;
        for (std::size_t v = first; v < first + vertices && !changed; ++v) changed = edited[v] != original[v];
        if (!changed) continue;
        if (inverses.empty()) inverses = inverseWorldLinear(doc, mesh, p);
        out.local.resize(scan.set.size());
        std::vector<float>& local = out.local[i];
        local.resize(3 * vertices);
        for (std::size_t v = 0; v < vertices; ++v) {
            const Vec3 d = edited[first + v] - neutral[first + v];
            const glm::dvec3 l = inverses[inverses.size() == 1 ? 0 : v] * glm::dvec3(d[0], d[1], d[2]);
            for (int c = 0; c < 3; ++c) local[3 * v + static_cast<std::size_t>(c)] = static_cast<float>(l[c]);
        }
    }
    return out;
}

// The morph target of key `key` on one primitive, each attribute stored as its most precise member.
Json keyTarget(GlbRepack& out, KeyWriting& w, const Json& originalTargets, const tinygltf::Primitive& prim,
               const AvatarMesh& mesh, const std::vector<std::size_t>& members, const KeyGrouping& grouping,
               std::size_t key, std::size_t vertices, bool targetNormals, const std::string& where,
               const PrimitiveSculpts& sculpts) {
    const bool sculpted = std::any_of(members.begin(), members.end(), [&](std::size_t k) {
        return sculpts.of(mesh.targets[k].viseme) != nullptr;
    });
    if (grouping.size[key] == 1 && !sculpted) { // one member: its own accessors, unchanged
        Json target = originalTargets[members.front()];
        if (!targetNormals) {
            target.erase("NORMAL");
            target.erase("TANGENT");
        }
        return target;
    }
    Json target = Json::object();
    for (const char* name : kTargetAttributes) {
        if (!targetNormals && std::strcmp(name, "POSITION") != 0) continue;
        std::vector<double> sum(3 * vertices, 0.0);
        bool any = false;
        TargetStorage storage;
        const bool position = std::strcmp(name, "POSITION") == 0;
        for (std::size_t k : members) {
            const int viseme = mesh.targets[k].viseme;
            const std::vector<float>* sculpt = position ? sculpts.of(viseme) : nullptr;
            const int accessor = attribute(prim.targets[k], name);
            if (accessor < 0 && !sculpt) continue;
            const std::string at = where + "/targets/" + std::to_string(k) + "/" + name;
            if (accessor >= 0 || sculpt) {
                TargetStorage own = accessor >= 0 ? storageOf(w.doc, w.views, accessor, at) : TargetStorage{};
                // A sculpted shape is new data: the member's grid or exponent (inferred from what the
                // file held, zeros on an eye) need not hold it. Floats, compressed if the member was.
                if (sculpt) own = TargetStorage{.meshopt = own.meshopt};
                storage = any ? morePrecise(storage, own) : own;
            }
            any = true;
            const double weight = grouping.weightInGroup[static_cast<std::size_t>(viseme)];
            const std::vector<float> d =
                sculpt ? *sculpt : w.reader.floats(accessor, TINYGLTF_TYPE_VEC3, at, vertices);
            for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += weight * d[c];
        }
        if (!any && std::strcmp(name, "POSITION") != 0) continue;
        target[name] = addVec3Target(out, sum, storage, std::strcmp(name, "POSITION") == 0, &w.tally);
    }
    return target;
}

// The morph target of a resting viseme: zero displacement.
Json restingTarget(GlbRepack& out, std::size_t vertices, StorageTally& tally) {
    return Json{{"POSITION", addVec3Target(out, std::vector<double>(3 * vertices, 0.0), {}, true, &tally)}};
}

Json* extrasObject(Json& object) {
    if (!object.contains("extras")) object["extras"] = Json::object();
    return object["extras"].is_object() ? &object["extras"] : nullptr;
}

// Per key, this mesh's targets of it after writing (names original: every member's, the first driven;
// merged: the key's one target).
std::vector<std::vector<int>> keyTargetsOf(const MeshPlan& plan, AvatarNames names) {
    std::vector<std::vector<int>> out(plan.members.size());
    for (std::size_t g = 0; g < plan.members.size(); ++g) {
        if (plan.members[g].empty()) continue;
        if (names == AvatarNames::Merged) out[g].push_back(plan.keyTarget[g]);
        for (std::size_t k : plan.members[g])
            if (names == AvatarNames::Original) out[g].push_back(plan.remap[k]);
    }
    return out;
}

// The viseme names of this mesh (its own spelling and the set's) whose target core/gltf/KeyTable.h's
// rule (targetNames, then the key listing the name) does not already give: a spelling of the mesh's
// own that no target keeps (merged names), or the set's spelling of a target named otherwise.
Json targetAliases(const AvatarMesh& mesh, const MeshPlan& plan, const std::vector<std::string>& visemes,
                   const std::vector<std::string>& writtenNames,
                   const std::vector<std::vector<std::string>>& members,
                   const std::vector<std::vector<int>>& keyTargets) {
    Json aliases = Json::object();
    for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
        const AvatarTarget& t = mesh.targets[k];
        if (t.viseme < 0) continue;
        for (const std::string& name : {t.name, visemes[static_cast<std::size_t>(t.viseme)]})
            if (!aliases.contains(name) &&
                impliedTarget(name, writtenNames, members, keyTargets) != plan.remap[k])
                aliases[name] = plan.remap[k];
    }
    return aliases;
}

// Version 2 (core/gltf/KeyTable.h): what only this mesh knows. Fields a version-1 table of an input
// that was itself reduced left here are removed, so that no stale table survives.
void writeMeshExtras(Json& meshJson, const AvatarMesh& mesh, const MeshPlan& plan, const ReducedModel& model,
                     const std::vector<std::string>& visemes, AvatarNames names,
                     std::vector<std::string>& notes) {
    Json* extras = extrasObject(meshJson);
    if (!extras) {
        notes.push_back("mesh '" + meshJson.value("name", std::string()) +
                        "': its extras are not an object, so its key targets were not added to them");
        return;
    }
    const bool named = names == AvatarNames::Merged || extras->contains("targetNames");
    if (named) (*extras)["targetNames"] = plan.names;
    const std::vector<std::vector<int>> keyTargets = keyTargetsOf(plan, names);
    std::vector<std::vector<std::string>> members;
    for (const KeyMesh& key : model.keys) members.push_back(key.members);
    const Json aliases = targetAliases(mesh, plan, visemes, named ? plan.names : std::vector<std::string>(),
                                       members, keyTargets);
    extras->erase("phonemeToTarget");
    (*extras)["visemeKeys"] = keyTargets;
    if (aliases.empty())
        extras->erase("targetAliases");
    else
        (*extras)["targetAliases"] = aliases;
}

// A frequency as written (core/gltf/KeyTable.h); a whole number (phoneme counts) without ".0".
Json frequencyJson(double frequency) {
    const double written = writtenFrequency(frequency);
    if (std::abs(written) < 1e15 && written == std::floor(written)) return static_cast<long long>(written);
    return written;
}

// Version 2 of extras.visemelab (core/gltf/KeyTable.h): a key's name only when it is not its members
// joined with '+' (merged names of several members), frequencies to 4 significant digits.
Json rootExtras(const ReducedModel& model, const std::vector<std::string>& keyNames, AvatarNames names) {
    Json keys = Json::array();
    for (std::size_t g = 0; g < model.keys.size(); ++g) {
        Json key = Json::object();
        if (keyNames[g] != mergedKeyName(model.keys[g].members)) key["name"] = keyNames[g];
        key["members"] = model.keys[g].members;
        key["frequency"] = frequencyJson(model.keys[g].frequency);
        keys.push_back(std::move(key));
    }
    Json phonemeToKey = Json::object(), phonemeFrequencies = Json::object();
    for (const auto& [phoneme, key] : model.phonemeToKey) phonemeToKey[phoneme] = key;
    for (const auto& [phoneme, f] : model.phonemeFrequencies) phonemeFrequencies[phoneme] = frequencyJson(f);
    Json out{{"version", kKeyTableVersion},
             {"names", toString(names)},
             {"keys", keys},
             {"resting", model.resting},
             {"phonemeToKey", phonemeToKey}};
    if (!model.phonemeFrequencies.empty()) out["phonemeFrequencies"] = phonemeFrequencies;
    return out;
}

void noteStorage(const GltfDocument& doc, const StorageTally& tally, std::vector<std::string>& notes) {
    const auto used = [&](const char* name) {
        return std::find(doc.model.extensionsUsed.begin(), doc.model.extensionsUsed.end(), name) !=
               doc.model.extensionsUsed.end();
    };
    if (used("EXT_meshopt_compression"))
        notes.push_back("EXT_meshopt_compression: views left as they were stay compressed");
    if (used("KHR_draco_mesh_compression"))
        notes.push_back(
            "KHR_draco_mesh_compression: the Draco geometry streams are kept as they are; the reduced "
            "targets are stored as the input's targets are (the extension never compresses targets)");
    if (!tally.empty()) {
        std::string line = "new target accessors, stored as their members were (smallest layout of each):";
        const char* separator = " ";
        for (const auto& [storage, n] : tally) {
            line += separator + std::to_string(n) + " x " + storage;
            separator = "; ";
        }
        notes.push_back(line);
    }
    for (const std::string& name : doc.model.extensionsUsed)
        if (!isKnownExtension(name))
            notes.push_back("extension " + name +
                            " kept as it is (VisemeLab does not know it; if it refers to "
                            "accessors or buffer views by index, those references were not renumbered)");
}

std::string write(const GltfDocument& doc, const AvatarScan& scan, const ReducedModel& model,
                  const std::vector<int>& groupOf, const std::vector<double>& frequencies,
                  const AvatarWriteOptions& options, AvatarWriteSummary* summary) {
    if (groupOf.size() != scan.visemes.size() || frequencies.size() != scan.visemes.size())
        throwInputError("avatar writer", "the grouping does not match the avatar's visemes");
    const KeyGrouping grouping(groupOf, frequencies, model.keys.size());
    GlbRepack out(doc);
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    KeyWriting keyWriting{doc, views, reader, {}};
    AvatarWriteSummary local;
    AvatarWriteSummary& s = summary ? *summary : local;
    const std::size_t storageNotesAt = s.notes.size(); // filled in once the keys are written

    // Plans first, so that a --max-targets refusal names every mesh over the cap before anything is done.
    const std::vector<std::string> keyNames = recordedKeyNames(scan, grouping, model, options.names);
    std::vector<MeshPlan> plans(scan.meshes.size());
    std::string overCap;
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes) continue;
        MeshPlan& plan = plans[static_cast<std::size_t>(mesh.index)];
        plan = planMesh(mesh, grouping, model, keyNames, options.names);
        AvatarMeshChange change{mesh.index, mesh.name, mesh.targets.size(), plan.names.size(), 0, 0};
        for (const AvatarTarget& t : mesh.targets) change.visemeTargets += t.viseme >= 0;
        for (const auto& m : plan.members) change.keys += !m.empty();
        s.meshes.push_back(change);
        if (options.maxTargets <= 0 || plan.names.size() <= static_cast<std::size_t>(options.maxTargets))
            continue;
        const bool original = options.names == AvatarNames::Original;
        std::size_t resting = 0;
        for (const AvatarTarget& t : mesh.targets)
            resting += t.viseme >= 0 && grouping.groupOf[static_cast<std::size_t>(t.viseme)] == kRestGroup;
        overCap +=
            std::string(overCap.empty() ? "" : "; ") + "mesh '" + mesh.name + "' would have " +
            std::to_string(plan.names.size()) + " morph targets (" +
            std::to_string(mesh.targets.size() - change.visemeTargets) + " kept + " +
            (original ? std::to_string(change.visemeTargets) + " viseme names kept by --names original)"
                      : std::to_string(change.keys) + " reduced keys" +
                            (resting ? " + " + std::to_string(resting) + " resting visemes (zero targets))"
                                     : std::string(")")));
    }
    if (!overCap.empty())
        throwInputError("--max-targets " + std::to_string(options.maxTargets),
                        overCap + (options.names == AvatarNames::Original
                                       ? "; --names merged keeps one target per key"
                                       : "; a smaller --target gives fewer keys"));

    std::map<int, std::vector<int>> remaps; // mesh -> old target -> new target (merged names)
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes) continue;
        const MeshPlan& plan = plans[static_cast<std::size_t>(mesh.index)];
        Json& meshJson = out.json["meshes"][static_cast<std::size_t>(mesh.index)];
        const tinygltf::Mesh& gm = doc.model.meshes[static_cast<std::size_t>(mesh.index)];
        for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
            const std::string where =
                "meshes/" + std::to_string(mesh.index) + "/primitives/" + std::to_string(p);
            Json& primJson = meshJson["primitives"][p];
            const Json originalTargets = primJson["targets"];
            const PrimitiveSculpts sculpts = primitiveSculpts(doc, scan, mesh, p, options.sculpted);
            std::vector<Json> keys(model.keys.size());
            for (std::size_t g = 0; g < model.keys.size(); ++g)
                if (!plan.members[g].empty())
                    keys[g] = keyTarget(out, keyWriting, originalTargets, gm.primitives[p], mesh,
                                        plan.members[g], grouping, g, mesh.primitives[p].vertices,
                                        options.targetNormals, where, sculpts);
            Json targets = Json::array();
            for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
                const int viseme = mesh.targets[k].viseme;
                if (viseme < 0) {
                    targets.push_back(originalTargets[k]);
                    continue;
                }
                for (const auto& [name, accessor] : originalTargets[k].items())
                    if (accessor.is_number_integer()) out.mayDrop(accessor.get<int>());
                if (grouping.groupOf[static_cast<std::size_t>(viseme)] == kRestGroup) {
                    // A resting viseme keeps its target (every name still resolves in a player) but
                    // moves nothing: the rest pose is the neutral.
                    targets.push_back(restingTarget(out, mesh.primitives[p].vertices, keyWriting.tally));
                    continue;
                }
                const auto g = static_cast<std::size_t>(grouping.groupOf[static_cast<std::size_t>(viseme)]);
                if (options.names == AvatarNames::Original ||
                    plan.remap[k] == static_cast<int>(targets.size()))
                    targets.push_back(keys[g]);
            }
            primJson["targets"] = targets;
            if (primJson.contains("extras") && primJson["extras"].is_object() &&
                primJson["extras"].contains("targetNames"))
                primJson["extras"]["targetNames"] = plan.names;
        }
        writeMeshExtras(meshJson, mesh, plan, model, scan.visemes, options.names, s.notes);
        if (options.names == AvatarNames::Merged) remaps[mesh.index] = plan.remap;
    }
    if (!remaps.empty()) remapMorphTargets(out, reader, remaps);
    std::vector<std::string> storageNotes;
    noteStorage(doc, keyWriting.tally, storageNotes);
    s.notes.insert(s.notes.begin() + static_cast<long>(storageNotesAt), storageNotes.begin(),
                   storageNotes.end());

    if (!out.json.contains("extras")) out.json["extras"] = Json::object();
    if (out.json["extras"].is_object())
        out.json["extras"]["visemelab"] = rootExtras(model, keyNames, options.names);
    else
        s.notes.push_back(
            "the document's extras are not an object: the key table (extras.visemelab) was not written, "
            "only each mesh's key targets");

    RepackStats stats;
    std::string glb = out.finish(&stats);
    s.accessorsBefore = stats.accessorsBefore;
    s.accessorsAfter = stats.accessorsAfter;
    s.binaryBytesBefore = stats.binaryBytesBefore;
    s.binaryBytesAfter = stats.binaryBytesAfter;
    return glb;
}

} // namespace

std::string writeReducedAvatar(const GltfDocument& doc, const AvatarScan& scan, const ReducedModel& model,
                               const std::vector<int>& groupOf, const std::vector<double>& frequencies,
                               const AvatarWriteOptions& options, AvatarWriteSummary* summary) {
    try {
        return write(doc, scan, model, groupOf, frequencies, options, summary);
    } catch (const nlohmann::json::exception& e) { // a JSON value of a type tinygltf let through
        doc.fail("", std::string("malformed glTF JSON: ") + e.what());
    }
}

} // namespace vl
