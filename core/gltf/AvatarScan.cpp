#include "core/gltf/AvatarScan.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarPlacement.h"
#include "core/gltf/AvatarRest.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/DracoDecode.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/SceneGraph.h"
#include "core/gltf/TargetNames.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace vl {
namespace {

std::string meshWhere(int mesh) {
    return "meshes/" + std::to_string(mesh);
}
std::string primitiveWhere(int mesh, std::size_t p) {
    return meshWhere(mesh) + "/primitives/" + std::to_string(p);
}

int attribute(const std::map<std::string, int>& attributes, const std::string& name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

// Triangles of a primitive's index list by its mode (spec 3.7.2.1); points and lines give none.
std::vector<Triangle> trianglesOf(const std::vector<std::uint32_t>& indices, int mode, std::size_t base) {
    std::vector<Triangle> out;
    const auto at = [&](std::size_t i) { return static_cast<std::uint32_t>(base + indices[i]); };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) out.push_back({at(i), at(i + 1), at(i + 2)});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < indices.size(); ++i)
            out.push_back(i % 2 == 0 ? Triangle{at(i), at(i + 1), at(i + 2)}
                                     : Triangle{at(i + 1), at(i), at(i + 2)});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 1; i + 1 < indices.size(); ++i) out.push_back({at(0), at(i), at(i + 1)});
    }
    return out;
}

std::string storageOf(const tinygltf::Accessor& a) {
    return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ? "" : "quantised";
}

// Decides which targets of a mesh are visemes; returns their join keys (empty for the others).
std::vector<std::string> selectTargets(AvatarMesh& mesh, const AvatarSelection& selection) {
    std::vector<std::string> keys(mesh.targets.size());
    std::map<std::string, std::size_t> firstWithKey;
    for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
        AvatarTarget& t = mesh.targets[k];
        const bool selected = selection.pattern.empty() ? t.named && oculusVisemeOf(t.name).has_value()
                                                        : globMatch(selection.pattern, t.name);
        if (!selected) {
            t.ignored = !t.named && selection.pattern.empty() ? "no name (the file has no extras.targetNames)"
                        : selection.pattern.empty()           ? "not an Oculus viseme name"
                                                              : "does not match '" + selection.pattern + "'";
            continue;
        }
        const std::string key = visemeJoinKey(t.name);
        const auto [it, inserted] = firstWithKey.emplace(key, k);
        if (!inserted) {
            t.ignored = "same viseme as target " + std::to_string(it->second) + " ('" +
                        mesh.targets[it->second].name + "')";
            continue;
        }
        keys[k] = key;
    }
    return keys;
}

// VisemeLab's merged-name output: its key targets are the visemes, joined across meshes by key.
std::vector<std::string> selectOwnKeys(AvatarMesh& mesh, const OwnOutput& own,
                                       const AvatarSelection& selection) {
    std::vector<std::string> keys(mesh.targets.size());
    for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
        AvatarTarget& t = mesh.targets[k];
        const int key = own.keyOfTarget(mesh.index, static_cast<int>(k));
        if (key < 0) {
            t.ignored = own.isResting(t.name) ? "resting viseme of VisemeLab's reduction (moves nothing)"
                                              : "not a key of VisemeLab's reduction";
            continue;
        }
        const auto& members = own.keys[static_cast<std::size_t>(key)].members;
        if (!selection.pattern.empty() && !globMatch(selection.pattern, t.name) &&
            std::none_of(members.begin(), members.end(),
                         [&](const std::string& m) { return globMatch(selection.pattern, m); })) {
            t.ignored = "neither it nor its members match '" + selection.pattern + "'";
            continue;
        }
        keys[k] = "key " + std::to_string(key); // not a viseme name: never joins with another spelling
    }
    return keys;
}

// Accessors decoded once however many primitives use them: memory follows the file's unique data
// (300 primitives sharing one 100 k-vertex accessor decoded it 300 times).
class DecodedAccessors {
  public:
    explicit DecodedAccessors(AccessorReader& reader) : reader_(reader) {}

    const std::vector<float>& floats(int index, int type, const std::string& where,
                                     std::size_t expectedCount = kAnyCount) {
        const auto key = std::make_tuple(index, type, expectedCount);
        auto it = cache_.find(key);
        if (it == cache_.end())
            it = cache_.emplace(key, reader_.floats(index, type, where, expectedCount)).first;
        return it->second;
    }

    const std::vector<std::uint32_t>& indices(int index, const std::string& where, std::size_t vertexCount) {
        const auto key = std::make_pair(index, vertexCount);
        auto it = indices_.find(key);
        if (it == indices_.end())
            it = indices_.emplace(key, reader_.indices(index, where, vertexCount)).first;
        return it->second;
    }

  private:
    AccessorReader& reader_;
    std::map<std::tuple<int, int, std::size_t>, std::vector<float>> cache_;
    std::map<std::pair<int, std::size_t>, std::vector<std::uint32_t>> indices_;
};

// A world-space value overflowing a double (a node scale of 1e160 squared) would make every cost
// infinite or zero: a data error naming the node and the accessor.
void requireFiniteWorld(const GltfDocument& doc, const glm::dvec4& w, int node, const std::string& where,
                        std::size_t vertex) {
    if (std::abs(w.x) <= kMaxWorldCoordinate && std::abs(w.y) <= kMaxWorldCoordinate &&
        std::abs(w.z) <= kMaxWorldCoordinate)
        return;
    doc.fail(where, "vertex " + std::to_string(vertex) + " placed by node " + std::to_string(node) +
                        " lies beyond +-1e30 in world space (squared distances would overflow)");
}

} // namespace

std::string visemeJoinKey(std::string_view targetName) {
    if (const auto oculus = oculusVisemeOf(targetName)) return *oculus;
    std::string key(targetName);
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return key;
}

namespace {

// What the world-space geometry will take, summed over every primitive that will be read (a shared
// accessor counts once per use: each use becomes vertices of its own), checked before any of it is
// allocated: positions of the neutral and of each viseme (24 bytes each) and triangles (12 bytes per
// index at most, for strips). Counts are those of the decoded (so checked) accessors; Draco
// primitives count as declared (their decoder checks them).
void checkWorldSpaceBudget(const GltfDocument& doc, DecodedAccessors& decoded, const AvatarScan& scan,
                           std::size_t visemes, bool context) {
    std::size_t bytes = 0;
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes && !context) continue;
        const std::size_t perVertex = 24 * (mesh.carriesVisemes ? visemes + 1 : 1);
        const auto& primitives = doc.model.meshes[static_cast<std::size_t>(mesh.index)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const std::string where = primitiveWhere(mesh.index, p);
            const int position = attribute(primitives[p].attributes, "POSITION");
            if (position < 0) continue;
            std::size_t vertices = mesh.primitives[p].vertices, indexCount = vertices;
            if (!hasDraco(doc, mesh.index, static_cast<int>(p))) {
                vertices = decoded.floats(position, TINYGLTF_TYPE_VEC3, where + "/POSITION").size() / 3;
                indexCount =
                    primitives[p].indices < 0
                        ? vertices
                        : decoded.indices(primitives[p].indices, where + "/indices", vertices).size();
            }
            bytes += vertices * perVertex + 12 * indexCount; // each term < 2^32 x 1560: no overflow
            if (bytes > kMaxAvatarVisemeBytes)
                doc.fail(where, "the world-space geometry would exceed " +
                                    std::to_string(kMaxAvatarVisemeBytes >> 20) + " MiB (" +
                                    std::to_string(visemes) +
                                    " visemes; an accessor shared by several primitives counts once per "
                                    "primitive)");
        }
    }
}

AvatarScan scan(const GltfDocument& doc, const AvatarSelection& selection) {
    AvatarScan scan;
    scan.source = doc.source;
    scan.own = recogniseOwnOutput(doc);
    const bool ownKeys = scan.own.recognised && scan.own.mergedNames;
    scan.selection = ownKeys                     ? (selection.pattern.empty()
                                                        ? std::string("keys of VisemeLab's reduction")
                                                        : "keys of VisemeLab's reduction matching '" + selection.pattern + "'")
                     : selection.pattern.empty() ? "Oculus viseme names"
                                                 : "pattern '" + selection.pattern + "'";
    scan.extensionsUsed = doc.model.extensionsUsed;
    scan.extensionsRequired = doc.model.extensionsRequired;
    const SceneInstances scene = sceneInstances(doc);
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    DecodedAccessors decoded(reader);

    // Targets and their selection, mesh by mesh; visemes joined by key.
    std::vector<std::vector<std::string>> keysOfMesh;
    std::vector<std::string> keyOrder;
    for (std::size_t m = 0; m < doc.model.meshes.size(); ++m) {
        const tinygltf::Mesh& gm = doc.model.meshes[m];
        AvatarMesh mesh;
        mesh.index = static_cast<int>(m);
        mesh.name = gm.name;
        mesh.node = scene.meshNode[m];
        mesh.uses = scene.meshUses[m];
        mesh.skin = mesh.node >= 0 ? doc.model.nodes[static_cast<std::size_t>(mesh.node)].skin : -1;
        if (gm.primitives.empty()) doc.fail(meshWhere(mesh.index), "has no primitives");
        for (std::size_t p = 1; p < gm.primitives.size(); ++p)
            if (gm.primitives[p].targets.size() != gm.primitives[0].targets.size())
                doc.fail(primitiveWhere(mesh.index, p), "has " +
                                                            std::to_string(gm.primitives[p].targets.size()) +
                                                            " morph targets, primitive 0 has " +
                                                            std::to_string(gm.primitives[0].targets.size()));
        for (const TargetName& name : meshTargetNames(doc, mesh.index))
            mesh.targets.push_back({name.name, name.named, -1, ""});
        keysOfMesh.push_back(ownKeys ? selectOwnKeys(mesh, scan.own, selection)
                                     : selectTargets(mesh, selection));
        for (const std::string& key : keysOfMesh.back())
            if (!key.empty() && std::find(keyOrder.begin(), keyOrder.end(), key) == keyOrder.end())
                keyOrder.push_back(key);
        if (mesh.targets.empty())
            mesh.note = "no morph targets";
        else if (std::all_of(keysOfMesh.back().begin(), keysOfMesh.back().end(),
                             [](const auto& k) { return k.empty(); }))
            mesh.note = "no viseme among its morph targets";
        scan.meshes.push_back(std::move(mesh));
    }
    if (selection.pattern.empty()) { // Oculus visemes in their canonical order
        const auto& canonical = oculusVisemeNames();
        std::stable_sort(keyOrder.begin(), keyOrder.end(), [&](const std::string& a, const std::string& b) {
            return std::find(canonical.begin(), canonical.end(), a) <
                   std::find(canonical.begin(), canonical.end(), b);
        });
    }
    scan.visemeKeys = keyOrder;
    scan.visemes.assign(keyOrder.size(), "");
    scan.oculusNames = !keyOrder.empty();
    for (std::size_t m = 0; m < scan.meshes.size(); ++m)
        for (std::size_t k = 0; k < keysOfMesh[m].size(); ++k) {
            if (keysOfMesh[m][k].empty()) continue;
            const auto index = static_cast<std::size_t>(
                std::find(keyOrder.begin(), keyOrder.end(), keysOfMesh[m][k]) - keyOrder.begin());
            AvatarTarget& target = scan.meshes[m].targets[k];
            target.viseme = static_cast<int>(index);
            if (scan.visemes[index].empty()) scan.visemes[index] = target.name;
            scan.meshes[m].carriesVisemes = true;
        }
    for (const std::string& name : scan.visemes)
        if (!oculusVisemeOf(name)) scan.oculusNames = false;
    // Original names written before extras.visemelab listed the resting visemes: those in no key.
    if (scan.own.recognised && !scan.own.mergedNames && scan.own.resting.empty())
        for (const std::string& name : scan.visemes)
            if (std::none_of(scan.own.keys.begin(), scan.own.keys.end(), [&](const OwnKey& k) {
                    return std::find(k.members.begin(), k.members.end(), name) != k.members.end();
                }))
                scan.own.resting.push_back(name);

    // Storage and declared sizes of every primitive, for the report.
    for (AvatarMesh& mesh : scan.meshes)
        for (std::size_t p = 0; p < doc.model.meshes[static_cast<std::size_t>(mesh.index)].primitives.size();
             ++p) {
            const tinygltf::Primitive& prim =
                doc.model.meshes[static_cast<std::size_t>(mesh.index)].primitives[p];
            const int position = attribute(prim.attributes, "POSITION");
            AvatarPrimitive info;
            info.mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (hasDraco(doc, mesh.index, static_cast<int>(p))) info.storage.push_back("Draco");
            if (position >= 0) {
                const tinygltf::Accessor& a =
                    reader.accessor(position, primitiveWhere(mesh.index, p) + "/POSITION");
                info.vertices = a.count;
                if (views.isCompressed(a.bufferView)) info.storage.push_back("meshopt");
                if (!storageOf(a).empty()) info.storage.push_back("quantised");
            }
            for (const auto& target : prim.targets) {
                const int delta = attribute(target, "POSITION");
                if (delta >= 0 && reader.accessor(delta, primitiveWhere(mesh.index, p)).sparse.isSparse) {
                    info.storage.push_back("sparse targets");
                    break;
                }
            }
            scan.fileVertices += info.vertices;
            mesh.primitives.push_back(std::move(info));
        }

    const std::size_t n = scan.visemes.size();
    if (n > kMaxAvatarVisemes)
        doc.fail("", std::to_string(n) + " distinct targets selected as visemes (" + scan.selection +
                         "); at most " + std::to_string(kMaxAvatarVisemes) + " are supported");
    checkWorldSpaceBudget(doc, decoded, scan, n, selection.context);
    // Geometry of the meshes carrying visemes, primitive by primitive, and (when asked) of the others,
    // for showing them. Everything allocated grows with data already read and checked, never with a
    // declared count.
    std::vector<std::vector<Vec3>> deltas(n);
    scan.set.neutralSource = doc.source;
    for (AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes && !selection.context) continue;
        MeshData& out = mesh.carriesVisemes ? scan.set.neutral : scan.context;
        const AvatarPlacement placement = avatarPlacement(doc, reader, scene, mesh);
        if (mesh.carriesVisemes && mesh.uses > 1)
            mesh.note = "measured at node " + std::to_string(mesh.node) + " (one of " +
                        std::to_string(mesh.uses) + ")";
        if (mesh.carriesVisemes && mesh.uses == 0)
            mesh.note = "not placed by any node: measured untransformed";
        const tinygltf::Mesh& gm = doc.model.meshes[static_cast<std::size_t>(mesh.index)];
        for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = gm.primitives[p];
            AvatarPrimitive& info = mesh.primitives[p];
            const std::string where = primitiveWhere(mesh.index, p);
            const int position = attribute(prim.attributes, "POSITION");
            if (position < 0) {
                if (!mesh.carriesVisemes) continue; // nothing to show
                doc.fail(where, "has morph targets but no POSITION");
            }
            std::vector<std::uint32_t> indices;
            const bool draco = hasDraco(doc, mesh.index, static_cast<int>(p));
            if (draco) indices = decodeDracoPrimitive(doc, views, reader, mesh.index, static_cast<int>(p));
            std::vector<float> dracoPositions;
            if (draco) dracoPositions = reader.floats(position, TINYGLTF_TYPE_VEC3, where + "/POSITION");
            const std::vector<float>& local =
                draco ? dracoPositions : decoded.floats(position, TINYGLTF_TYPE_VEC3, where + "/POSITION");
            info.vertices = local.size() / 3;
            const std::size_t first = out.positions.size();
            if (mesh.carriesVisemes) info.firstVertex = first;
            if (first + info.vertices > 0xFFFFFFFFu)
                doc.fail(where, "more than 2^32 vertices in the meshes carrying visemes");
            if (!draco) {
                if (prim.indices >= 0) {
                    indices = decoded.indices(prim.indices, where + "/indices", info.vertices);
                } else {
                    indices.resize(info.vertices);
                    for (std::size_t i = 0; i < indices.size(); ++i)
                        indices[i] = static_cast<std::uint32_t>(i);
                }
            }
            if (info.mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
                doc.fail(where, "TRIANGLES with " + std::to_string(indices.size()) +
                                    " indices (not a multiple of 3)");
            const std::vector<Triangle> triangles = trianglesOf(indices, info.mode, first);
            info.triangles = triangles.size();
            out.triangles.insert(out.triangles.end(), triangles.begin(), triangles.end());

            const std::vector<glm::dmat4> perVertex =
                skinnedMatrices(doc, reader, prim, placement, info.vertices, where);
            const auto matrixOf = [&](std::size_t v) -> const glm::dmat4& {
                return perVertex.empty() ? placement.node : perVertex[v];
            };
            for (std::size_t v = 0; v < info.vertices; ++v) {
                const glm::dvec4 w =
                    matrixOf(v) * glm::dvec4(local[3 * v], local[3 * v + 1], local[3 * v + 2], 1.0);
                requireFiniteWorld(doc, w, mesh.node, where + "/POSITION", v);
                out.positions.emplace_back(w.x, w.y, w.z);
            }
            if (!mesh.carriesVisemes) continue;
            for (auto& d : deltas) d.resize(out.positions.size(), Vec3(0, 0, 0));
            for (std::size_t k = 0; k < mesh.targets.size(); ++k) {
                const int viseme = mesh.targets[k].viseme;
                const int delta = viseme < 0 ? -1 : attribute(prim.targets[k], "POSITION");
                if (delta < 0) continue; // not a viseme, or no displacement on this primitive
                const std::string targetWhere = where + "/targets/" + std::to_string(k) + "/POSITION";
                const std::vector<float>& d =
                    decoded.floats(delta, TINYGLTF_TYPE_VEC3, targetWhere, info.vertices);
                auto& target = deltas[static_cast<std::size_t>(viseme)];
                for (std::size_t v = 0; v < info.vertices; ++v) {
                    const glm::dvec4 w = matrixOf(v) * glm::dvec4(d[3 * v], d[3 * v + 1], d[3 * v + 2], 0.0);
                    requireFiniteWorld(doc, w, mesh.node, targetWhere, v);
                    target[first + v] += Vec3(w.x, w.y, w.z);
                }
            }
        }
    }
    const std::size_t total = scan.set.neutral.positions.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t v = 0; v < total; ++v) deltas[i][v] += scan.set.neutral.positions[v];
        scan.set.visemes.push_back({scan.visemes[i], std::move(deltas[i])});
    }
    return scan;
}

} // namespace

AvatarScan scanAvatar(const GltfDocument& doc, const AvatarSelection& selection) {
    try {
        AvatarScan result = scan(doc, selection);
        if (!selection.addedRest.empty()) addAvatarRest(result, selection.addedRest);
        return result;
    } catch (const nlohmann::json::exception& e) { // a JSON value of a type tinygltf let through
        doc.fail("", std::string("malformed glTF JSON: ") + e.what());
    }
}

bool avatarStoredCompressed(const AvatarScan& scan) {
    for (const AvatarMesh& mesh : scan.meshes)
        for (const AvatarPrimitive& primitive : mesh.primitives)
            for (const std::string& storage : primitive.storage)
                if (storage != "sparse targets") return true;
    return false;
}

} // namespace vl
