#include "core/gltf/GltfReferences.h"

#include <algorithm>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

// Calls `f` for each element of doc[key] when it is an array of objects.
template <typename F> void eachObject(Json& parent, const char* key, F f) {
    const auto it = parent.find(key);
    if (it == parent.end() || !it->is_array()) return;
    for (Json& element : *it)
        if (element.is_object()) f(element);
}

void visitMember(Json& object, const char* key, const JsonRef& visit) {
    const auto it = object.find(key);
    if (it != object.end() && it->is_number_integer()) visit(*it);
}

void visitValues(Json& object, const char* key, const JsonRef& visit) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_object()) return;
    for (auto& [name, value] : it->items())
        if (value.is_number_integer()) visit(value);
}

Json* extension(Json& object, const char* name) {
    const auto ext = object.find("extensions");
    if (ext == object.end() || !ext->is_object()) return nullptr;
    const auto it = ext->find(name);
    return it == ext->end() || !it->is_object() ? nullptr : &*it;
}

} // namespace

void forEachAccessorReference(Json& doc, const JsonRef& visit) {
    eachObject(doc, "meshes", [&](Json& mesh) {
        eachObject(mesh, "primitives", [&](Json& prim) {
            visitValues(prim, "attributes", visit);
            visitMember(prim, "indices", visit);
            const auto targets = prim.find("targets");
            if (targets != prim.end() && targets->is_array())
                for (Json& target : *targets)
                    if (target.is_object())
                        for (auto& [name, value] : target.items())
                            if (value.is_number_integer()) visit(value);
        });
    });
    eachObject(doc, "skins", [&](Json& skin) { visitMember(skin, "inverseBindMatrices", visit); });
    eachObject(doc, "animations", [&](Json& animation) {
        eachObject(animation, "samplers", [&](Json& sampler) {
            visitMember(sampler, "input", visit);
            visitMember(sampler, "output", visit);
        });
    });
    eachObject(doc, "nodes", [&](Json& node) {
        if (Json* instancing = extension(node, "EXT_mesh_gpu_instancing"))
            visitValues(*instancing, "attributes", visit);
    });
}

void forEachBufferViewReference(Json& doc, const JsonRef& visit) {
    eachObject(doc, "accessors", [&](Json& accessor) {
        visitMember(accessor, "bufferView", visit);
        const auto sparse = accessor.find("sparse");
        if (sparse == accessor.end() || !sparse->is_object()) return;
        for (const char* part : {"indices", "values"}) {
            const auto it = sparse->find(part);
            if (it != sparse->end() && it->is_object()) visitMember(*it, "bufferView", visit);
        }
    });
    eachObject(doc, "images", [&](Json& image) { visitMember(image, "bufferView", visit); });
    eachObject(doc, "meshes", [&](Json& mesh) {
        eachObject(mesh, "primitives", [&](Json& prim) {
            if (Json* draco = extension(prim, "KHR_draco_mesh_compression"))
                visitMember(*draco, "bufferView", visit);
        });
    });
}

void renumber(Json& doc, const std::string& array, const std::vector<int>& newIndex,
              void (*forEach)(Json&, const JsonRef&)) {
    forEach(doc, [&](Json& index) {
        const auto old = index.get<long long>();
        if (old >= 0 && static_cast<std::size_t>(old) < newIndex.size() &&
            newIndex[static_cast<std::size_t>(old)] >= 0)
            index = newIndex[static_cast<std::size_t>(old)];
    });
    const auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) return;
    Json kept = Json::array();
    for (std::size_t i = 0; i < it->size() && i < newIndex.size(); ++i)
        if (newIndex[i] >= 0) kept.push_back(std::move((*it)[i]));
    *it = std::move(kept);
}

bool isKnownExtension(const std::string& name) {
    static const char* known[] = {
        // Handled by the reference visitors.
        "KHR_draco_mesh_compression", "EXT_meshopt_compression", "EXT_mesh_gpu_instancing",
        // Refer to no accessor, buffer view or buffer.
        "KHR_mesh_quantization", "KHR_texture_transform", "KHR_texture_basisu", "EXT_texture_webp",
        "EXT_texture_avif", "KHR_lights_punctual", "KHR_materials_variants", "KHR_materials_unlit",
        "KHR_materials_emissive_strength", "KHR_materials_clearcoat", "KHR_materials_ior",
        "KHR_materials_specular", "KHR_materials_sheen", "KHR_materials_transmission", "KHR_materials_volume",
        "KHR_materials_iridescence", "KHR_materials_anisotropy", "KHR_materials_dispersion",
        "KHR_materials_pbrSpecularGlossiness", "KHR_xmp_json_ld", "KHR_node_visibility", "MSFT_lod",
        "MSFT_texture_dds", "VRM", "VRMC_vrm", "VRMC_springBone", "VRMC_materials_mtoon",
        "VRMC_node_constraint", "VRMC_materials_hdr_emissiveMultiplier", "VRMC_vrm_animation"};
    return std::find(std::begin(known), std::end(known), name) != std::end(known);
}

} // namespace vl
