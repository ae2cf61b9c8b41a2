#include "core/import/GltfImport.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/DracoDecode.h"
#include "core/gltf/GlbContainer.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/TargetNames.h"

#include <cmath>

namespace vl {
namespace {

int attribute(const std::map<std::string, int>& attributes, const char* name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

std::vector<Vec3> toVec3(const std::vector<float>& xyz) {
    std::vector<Vec3> out(xyz.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return out;
}

// Restores names, members, frequencies and the phoneme map from VisemeLab's mesh.extras.
void readExtras(const tinygltf::Value& extras, ReducedModel& model, std::string_view source) {
    const std::string where = std::string(source) + ": mesh.extras";
    const std::size_t keyCount = model.keys.size();
    if (extras.Has("targetNames") && extras.Get("targetNames").IsArray()) {
        const tinygltf::Value& names = extras.Get("targetNames");
        if (names.ArrayLen() != keyCount)
            throwInputError(where + ".targetNames", "count differs from the morph targets");
        for (std::size_t k = 0; k < keyCount; ++k) {
            if (!names.Get(static_cast<int>(k)).IsString())
                throwInputError(where + ".targetNames/" + std::to_string(k), "not a string");
            model.keys[k].name = names.Get(static_cast<int>(k)).Get<std::string>();
        }
    }
    if (extras.Has("targetFrequencies") && extras.Get("targetFrequencies").ArrayLen() == keyCount)
        for (std::size_t k = 0; k < keyCount; ++k) {
            const tinygltf::Value& f = extras.Get("targetFrequencies").Get(static_cast<int>(k));
            if (f.IsNumber()) model.keys[k].frequency = f.GetNumberAsDouble();
        }
    if (extras.Has("targetMembers") && extras.Get("targetMembers").ArrayLen() == keyCount)
        for (std::size_t k = 0; k < keyCount; ++k) {
            const tinygltf::Value& members = extras.Get("targetMembers").Get(static_cast<int>(k));
            model.keys[k].members.clear();
            for (std::size_t i = 0; i < members.ArrayLen(); ++i)
                if (members.Get(static_cast<int>(i)).IsString())
                    model.keys[k].members.push_back(members.Get(static_cast<int>(i)).Get<std::string>());
        }
    if (extras.Has("phonemeToTarget") && extras.Get("phonemeToTarget").IsObject()) {
        const tinygltf::Value& map = extras.Get("phonemeToTarget");
        for (const std::string& phoneme : map.Keys()) {
            const tinygltf::Value& v = map.Get(phoneme);
            const double k = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
            // -1: the phoneme rests (kRestingKey, the rest-free model): the neutral face.
            if (!(k >= kRestingKey && k < static_cast<double>(keyCount)) || k != std::floor(k))
                throwInputError(where + ".phonemeToTarget/" + phoneme, "not a morph target index");
            model.phonemeToKey.emplace_back(phoneme, static_cast<int>(k));
        }
    }
    if (extras.Has("phonemeFrequencies") && extras.Get("phonemeFrequencies").IsObject()) {
        const tinygltf::Value& map = extras.Get("phonemeFrequencies");
        for (const std::string& phoneme : map.Keys())
            if (map.Get(phoneme).IsNumber())
                model.phonemeFrequencies.emplace_back(phoneme, map.Get(phoneme).GetNumberAsDouble());
    }
}

} // namespace

namespace {

ReducedModel parse(const GltfDocument& gltf, std::string_view source) {
    if (gltf.model.meshes.empty()) gltf.fail("", "the glTF file has no mesh");
    std::size_t meshIndex = 0;
    for (std::size_t m = 0; m < gltf.model.meshes.size(); ++m)
        if (!gltf.model.meshes[m].primitives.empty() && !gltf.model.meshes[m].primitives[0].targets.empty()) {
            meshIndex = m;
            break;
        }
    const tinygltf::Mesh& mesh = gltf.model.meshes[meshIndex];
    const std::string meshWhere = "meshes/" + std::to_string(meshIndex);
    if (mesh.primitives.empty()) gltf.fail(meshWhere, "no primitives");
    const std::size_t targetCount = mesh.primitives[0].targets.size();

    BufferViews views(gltf);
    AccessorReader reader(gltf, views);
    ReducedModel model;
    model.keys.resize(targetCount);
    bool anyUVs = false, allUVs = true;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        const std::string where = meshWhere + "/primitives/" + std::to_string(p);
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
            gltf.fail(where,
                      "only triangle primitives are supported (mode " + std::to_string(prim.mode) + ")");
        if (prim.targets.size() != targetCount)
            gltf.fail(where, "has " + std::to_string(prim.targets.size()) +
                                 " morph targets, the first primitive " + std::to_string(targetCount));
        const int positionAccessor = attribute(prim.attributes, "POSITION");
        if (positionAccessor < 0) gltf.fail(where, "no POSITION attribute");
        const bool draco = hasDraco(gltf, static_cast<int>(meshIndex), static_cast<int>(p));
        std::vector<std::uint32_t> indices;
        if (draco)
            indices =
                decodeDracoPrimitive(gltf, views, reader, static_cast<int>(meshIndex), static_cast<int>(p));
        const std::vector<Vec3> positions =
            toVec3(reader.floats(positionAccessor, TINYGLTF_TYPE_VEC3, where + "/POSITION"));
        const std::size_t base = model.neutral.positions.size();
        if (base + positions.size() > 0xFFFFFFFFu) gltf.fail(where, "too many vertices");
        if (!draco) {
            if (prim.indices >= 0) {
                indices = reader.indices(prim.indices, where + "/indices", positions.size());
            } else {
                indices.resize(positions.size());
                for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
            }
        }
        if (indices.size() % 3 != 0) gltf.fail(where, "index count is not a multiple of 3");
        for (std::size_t i = 0; i < indices.size(); i += 3)
            model.neutral.triangles.push_back({static_cast<std::uint32_t>(base + indices[i]),
                                               static_cast<std::uint32_t>(base + indices[i + 1]),
                                               static_cast<std::uint32_t>(base + indices[i + 2])});

        const int uvAccessor = attribute(prim.attributes, "TEXCOORD_0");
        if (uvAccessor >= 0) {
            const std::vector<float> uv =
                reader.floats(uvAccessor, TINYGLTF_TYPE_VEC2, where + "/TEXCOORD_0", positions.size());
            model.neutral.uvs.resize(base);
            for (std::size_t i = 0; i < positions.size(); ++i)
                model.neutral.uvs.emplace_back(uv[2 * i], 1.0 - uv[2 * i + 1]);
            anyUVs = true;
        } else {
            allUVs = false;
        }
        model.neutral.positions.insert(model.neutral.positions.end(), positions.begin(), positions.end());

        for (std::size_t k = 0; k < targetCount; ++k) {
            const int delta = attribute(prim.targets[k], "POSITION");
            std::vector<Vec3> shape = positions;
            if (delta >= 0) {
                const std::vector<Vec3> d = toVec3(
                    reader.floats(delta, TINYGLTF_TYPE_VEC3,
                                  where + "/targets/" + std::to_string(k) + "/POSITION", positions.size()));
                for (std::size_t i = 0; i < d.size(); ++i) shape[i] += d[i];
            }
            auto& keyPositions = model.keys[k].positions;
            keyPositions.insert(keyPositions.end(), shape.begin(), shape.end());
        }
    }
    if (anyUVs && !allUVs) gltf.fail(meshWhere, "some primitives have TEXCOORD_0 and some not");
    if (model.neutral.positions.empty() || model.neutral.triangles.empty())
        gltf.fail(meshWhere, "the mesh is empty");

    const std::vector<TargetName> names = meshTargetNames(gltf, static_cast<int>(meshIndex));
    for (std::size_t k = 0; k < targetCount; ++k) model.keys[k].name = names[k].name;
    readExtras(mesh.extras, model, source);
    for (KeyMesh& key : model.keys)
        if (key.members.empty()) key.members.push_back(key.name);
    validateReducedModel(model, source);
    return model;
}

} // namespace

ReducedModel parseGltf(std::string_view bytes, std::string_view source, bool /*binary: detected*/,
                       const std::filesystem::path& baseDir) {
    // The hardened reader of core/gltf: limits, URI confinement, meshopt/Draco/sparse/quantised data.
    const GltfDocument gltf = parseGltfDocument(std::string(bytes), source, baseDir);
    try {
        return parse(gltf, source);
    } catch (const nlohmann::json::exception& e) { // a JSON value of a type tinygltf let through
        gltf.fail("", std::string("malformed glTF JSON: ") + e.what());
    }
}

ReducedModel readGltf(const std::filesystem::path& path) {
    const std::string bytes = readFileToString(path);
    return parseGltf(bytes, path.string(), isGlb(bytes),
                     path.parent_path().empty() ? "." : path.parent_path());
}

} // namespace vl
