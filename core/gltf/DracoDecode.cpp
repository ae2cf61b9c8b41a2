#include "core/gltf/DracoDecode.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"

#include <draco/compression/decode.h>

#include <algorithm>

namespace vl {
namespace {

const nlohmann::ordered_json* dracoExtension(const GltfDocument& doc, int mesh, int primitive) {
    const auto meshes = doc.json.find("meshes");
    if (meshes == doc.json.end() || !meshes->is_array() || static_cast<std::size_t>(mesh) >= meshes->size())
        return nullptr;
    const auto& m = (*meshes)[static_cast<std::size_t>(mesh)];
    const auto prims = m.find("primitives");
    if (prims == m.end() || !prims->is_array() || static_cast<std::size_t>(primitive) >= prims->size())
        return nullptr;
    const auto& p = (*prims)[static_cast<std::size_t>(primitive)];
    const auto ext = p.find("extensions");
    if (ext == p.end() || !ext->is_object()) return nullptr;
    const auto draco = ext->find("KHR_draco_mesh_compression");
    return draco == ext->end() ? nullptr : &*draco;
}

float normalise(float v, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return v / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(v / 127.0f, -1.0f);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return v / 65535.0f;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(v / 32767.0f, -1.0f);
    default:
        return v;
    }
}

} // namespace

bool hasDraco(const GltfDocument& doc, int mesh, int primitive) {
    return dracoExtension(doc, mesh, primitive) != nullptr;
}

std::vector<std::uint32_t> decodeDracoPrimitive(const GltfDocument& doc, BufferViews& views,
                                                AccessorReader& reader, int mesh, int primitive) {
    const std::string where = "meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(primitive) +
                              "/extensions/KHR_draco_mesh_compression";
    const nlohmann::ordered_json* ext = dracoExtension(doc, mesh, primitive);
    if (!ext || !ext->is_object() || !ext->contains("bufferView") ||
        !(*ext)["bufferView"].is_number_integer() || !ext->contains("attributes") ||
        !(*ext)["attributes"].is_object())
        doc.fail(where, "needs an integer bufferView and an attributes object");
    const tinygltf::Primitive& prim =
        doc.model.meshes[static_cast<std::size_t>(mesh)].primitives[static_cast<std::size_t>(primitive)];
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
        doc.fail(where, "only TRIANGLES primitives are supported with Draco (mode " +
                            std::to_string(prim.mode) + ")");
    const ViewBytes bytes = views.view((*ext)["bufferView"].get<int>(), where + "/bufferView");

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data), bytes.size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        doc.fail(where, std::string("Draco could not decode the stream: ") + decoded.status().error_msg());
    const std::unique_ptr<draco::Mesh> dracoMesh = std::move(decoded).value();
    const std::size_t points = dracoMesh->num_points();

    for (const auto& [name, id] : ext->at("attributes").items()) {
        const auto attribute = prim.attributes.find(name);
        if (attribute == prim.attributes.end())
            continue; // the extension may list more than the primitive uses
        if (!id.is_number_unsigned()) doc.fail(where + "/attributes/" + name, "not a Draco attribute id");
        const draco::PointAttribute* att = dracoMesh->GetAttributeByUniqueId(id.get<std::uint32_t>());
        if (!att)
            doc.fail(where + "/attributes/" + name, "attribute id " +
                                                        std::to_string(id.get<std::uint32_t>()) +
                                                        " is not in the Draco stream");
        const tinygltf::Accessor& accessor = reader.accessor(attribute->second, where);
        const int components = componentsOf(accessor.type);
        if (components <= 0 || components > 16)
            doc.fail(where + "/attributes/" + name, "unsupported accessor type");
        if (accessor.count != points)
            doc.fail(where + "/attributes/" + name,
                     "the accessor declares " + std::to_string(accessor.count) + " elements, Draco decoded " +
                         std::to_string(points) + " points");
        std::vector<float> values(points * static_cast<std::size_t>(components));
        for (std::size_t i = 0; i < points; ++i) {
            float* out = values.data() + i * static_cast<std::size_t>(components);
            const draco::AttributeValueIndex index =
                att->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(i)));
            if (!att->ConvertValue<float>(index, static_cast<std::int8_t>(components), out))
                doc.fail(where + "/attributes/" + name, "Draco could not convert point " + std::to_string(i));
            if (accessor.normalized && !att->normalized())
                for (int c = 0; c < components; ++c) out[c] = normalise(out[c], accessor.componentType);
        }
        reader.provide(attribute->second, std::move(values));
    }

    std::vector<std::uint32_t> indices;
    indices.reserve(static_cast<std::size_t>(dracoMesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < dracoMesh->num_faces(); ++f) {
        const auto& face = dracoMesh->face(f);
        for (int c = 0; c < 3; ++c) indices.push_back(face[c].value());
    }
    for (std::uint32_t i : indices)
        if (i >= points)
            doc.fail(where,
                     "a Draco face refers to point " + std::to_string(i) + " of " + std::to_string(points));
    return indices;
}

} // namespace vl
