#include "core/gltf/AvatarMaterials.h"

#include "core/common/Error.h"
#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/DracoDecode.h"
#include "core/gltf/GltfDocument.h"
#include "core/io/ImageDecode.h"

#include <map>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

// A JSON member of an object, or null when absent (wrong container types are the caller's check).
const Json* member(const Json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
}

const Json& arrayOf(const GltfDocument& doc, const char* name) {
    static const Json empty = Json::array();
    const Json* array = member(doc.json, name);
    if (!array) return empty;
    if (!array->is_array()) doc.fail(name, "not an array");
    return *array;
}

float numberAt(const GltfDocument& doc, const Json& value, const std::string& where) {
    if (!value.is_number()) doc.fail(where, "not a number");
    return value.get<float>();
}

template <std::size_t N>
void readNumbers(const GltfDocument& doc, const Json* value, const std::string& where,
                 std::array<float, N>& out) {
    if (!value) return;
    if (!value->is_array() || value->size() != N) doc.fail(where, "needs " + std::to_string(N) + " numbers");
    for (std::size_t k = 0; k < N; ++k) out[k] = numberAt(doc, (*value)[k], where + "/" + std::to_string(k));
}

int indexAt(const GltfDocument& doc, const Json& value, const std::string& where, std::size_t count) {
    if (!value.is_number_integer() || value.get<long long>() < 0 ||
        static_cast<std::size_t>(value.get<long long>()) >= count)
        doc.fail(where, "not an index below " + std::to_string(count));
    return value.get<int>();
}

class MaterialReader {
  public:
    MaterialReader(const GltfDocument& doc, BufferViews& views, SurfaceMaterials& out)
        : doc_(doc), views_(views), out_(out) {}

    // Our index of glTF material `index` (converted on first use), and the texCoord set its base
    // colour texture reads.
    int material(int index, int& texCoord) {
        if (const auto it = materials_.find(index); it != materials_.end()) {
            texCoord = it->second.second;
            return it->second.first;
        }
        const std::string where = "materials/" + std::to_string(index);
        const Json& m = arrayOf(doc_, "materials")[static_cast<std::size_t>(index)];
        SurfaceMaterial material;
        if (const Json* name = member(m, "name"); name && name->is_string()) material.name = *name;
        texCoord = 0;
        if (const Json* pbr = member(m, "pbrMetallicRoughness")) {
            readNumbers(doc_, member(*pbr, "baseColorFactor"),
                        where + "/pbrMetallicRoughness/baseColorFactor", material.baseColor);
            if (const Json* info = member(*pbr, "baseColorTexture"))
                texture(*info, where + "/pbrMetallicRoughness/baseColorTexture", material, texCoord);
        }
        if (const Json* mode = member(m, "alphaMode")) {
            if (*mode == "MASK")
                material.alphaMode = AlphaMode::Mask;
            else if (*mode == "BLEND")
                material.alphaMode = AlphaMode::Blend;
            else if (*mode != "OPAQUE")
                doc_.fail(where + "/alphaMode", "not OPAQUE, MASK or BLEND");
        }
        if (const Json* cutoff = member(m, "alphaCutoff"))
            material.alphaCutoff = numberAt(doc_, *cutoff, where + "/alphaCutoff");
        if (const Json* sides = member(m, "doubleSided"); sides && sides->is_boolean())
            material.doubleSided = *sides;
        const int ours = static_cast<int>(out_.materials.size());
        out_.materials.push_back(std::move(material));
        materials_[index] = {ours, texCoord};
        return ours;
    }

  private:
    void texture(const Json& info, const std::string& where, SurfaceMaterial& material, int& texCoord) {
        const Json* index = member(info, "index");
        if (!index) doc_.fail(where, "has no index");
        const Json& textures = arrayOf(doc_, "textures");
        const int t = indexAt(doc_, *index, where + "/index", textures.size());
        if (const Json* set = member(info, "texCoord"))
            texCoord = indexAt(doc_, *set, where + "/texCoord", 8);
        const Json* infoExtensions = member(info, "extensions");
        if (const Json* transform =
                infoExtensions ? member(*infoExtensions, "KHR_texture_transform") : nullptr) {
            const std::string at = where + "/extensions/KHR_texture_transform";
            readNumbers(doc_, member(*transform, "offset"), at + "/offset", material.uvOffset);
            readNumbers(doc_, member(*transform, "scale"), at + "/scale", material.uvScale);
            if (const Json* rotation = member(*transform, "rotation"))
                material.uvRotation = numberAt(doc_, *rotation, at + "/rotation");
            if (const Json* set = member(*transform, "texCoord"))
                texCoord = indexAt(doc_, *set, at + "/texCoord", 8);
        }
        const std::string textureWhere = "textures/" + std::to_string(t);
        const Json& tex = textures[static_cast<std::size_t>(t)];
        if (const Json* sampler = member(tex, "sampler")) {
            const Json& samplers = arrayOf(doc_, "samplers");
            const std::string samplerWhere = textureWhere + "/sampler";
            const Json& s =
                samplers[static_cast<std::size_t>(indexAt(doc_, *sampler, samplerWhere, samplers.size()))];
            material.wrapU = wrap(member(s, "wrapS"), samplerWhere);
            material.wrapV = wrap(member(s, "wrapT"), samplerWhere);
        }
        const Json* source = member(tex, "source");
        if (!source) { // only an extension's image (KHR_texture_basisu, EXT_texture_webp, ...)
            std::string kinds;
            if (const Json* extensions = member(tex, "extensions"); extensions && extensions->is_object())
                for (const auto& [name, value] : extensions->items())
                    kinds += (kinds.empty() ? "" : ", ") + name;
            out_.warnings.push_back(doc_.source + ": " + textureWhere + ": not drawn, its image is only in " +
                                    (kinds.empty() ? std::string("no source") : kinds) +
                                    " (KTX2/WebP are not decoded); material '" + material.name +
                                    "' shows its base colour factor");
            return;
        }
        material.image = image(
            indexAt(doc_, *source, textureWhere + "/source", arrayOf(doc_, "images").size()), material.name);
    }

    // glTF's wrap mode codes (the WebGL enums); absent: repeat.
    TextureWrap wrap(const Json* mode, const std::string& where) const {
        if (!mode || *mode == 10497) return TextureWrap::Repeat;
        if (*mode == 33071) return TextureWrap::Clamp;
        if (*mode == 33648) return TextureWrap::Mirror;
        doc_.fail(where, "wrap mode " + mode->dump() + " is not 10497, 33071 or 33648");
    }

    std::string imageBytes(const Json& image, const std::string& where) {
        if (const Json* view = member(image, "bufferView")) {
            const ViewBytes bytes =
                views_.view(indexAt(doc_, *view, where + "/bufferView", arrayOf(doc_, "bufferViews").size()),
                            where + "/bufferView");
            return {reinterpret_cast<const char*>(bytes.data), bytes.size};
        }
        const Json* uri = member(image, "uri");
        if (!uri || !uri->is_string()) doc_.fail(where, "has neither a bufferView nor a uri");
        if (isDataUri(uri->get<std::string>())) {
            const std::string& text = uri->get_ref<const std::string&>();
            const std::size_t comma = text.find(";base64,");
            if (comma == std::string::npos) doc_.fail(where + "/uri", "a data URI that is not base64");
            std::vector<unsigned char> decoded;
            std::string mime;
            // tinygltf decodes "data:application/octet-stream;base64," and the image types alike.
            const std::string normalised = "data:application/octet-stream" + text.substr(comma);
            if (!tinygltf::DecodeDataURI(&decoded, mime, normalised, 0, false))
                doc_.fail(where + "/uri", "malformed base64 data URI");
            return {decoded.begin(), decoded.end()};
        }
        return doc_.readExternal(*uri, where + "/uri", kMaxTextureBytes);
    }

    int image(int index, const std::string& materialName) {
        if (const auto it = images_.find(index); it != images_.end()) return it->second;
        const std::string where = "images/" + std::to_string(index);
        const Json& image = arrayOf(doc_, "images")[static_cast<std::size_t>(index)];
        int ours = -1;
        std::string problem, bytes;
        try {
            bytes = imageBytes(image, where);
        } catch (const InputError& e) { // a missing file or a broken reference costs the texture only
            problem = e.what();
        }
        if (problem.empty()) {
            // An absurd declared size is refused outright (InputError), not skipped.
            DecodedImage decoded =
                decodeImage(bytes, doc_.source + ": " + where, kMaxTextureBytes - usedBytes_);
            if (decoded.image) {
                usedBytes_ += decoded.image->rgba.size();
                const Json* name = member(image, "name");
                decoded.image->name =
                    "image " + std::to_string(index) +
                    (name && name->is_string() ? " ('" + name->get<std::string>() + "')" : "");
                ours = static_cast<int>(out_.images.size());
                out_.images.push_back(std::move(*decoded.image));
            } else {
                problem = doc_.source + ": " + where + ": not drawn: " + decoded.problem;
            }
        }
        if (!problem.empty())
            out_.warnings.push_back(problem + "; material '" + materialName +
                                    "' shows its base colour factor");
        images_[index] = ours;
        return ours;
    }

    const GltfDocument& doc_;
    BufferViews& views_;
    SurfaceMaterials& out_;
    std::map<int, std::pair<int, int>> materials_; // glTF index -> (ours, texCoord)
    std::map<int, int> images_;                    // glTF index -> ours, or -1
    std::size_t usedBytes_ = 0;
};

void addRange(SurfaceLayout& layout, std::size_t triangles, int material) {
    if (triangles == 0) return;
    if (!layout.ranges.empty() && layout.ranges.back().material == material) {
        layout.ranges.back().triangleCount += triangles;
        return;
    }
    const std::size_t first =
        layout.ranges.empty() ? 0 : layout.ranges.back().firstTriangle + layout.ranges.back().triangleCount;
    layout.ranges.push_back({first, triangles, material});
}

} // namespace

AvatarSurfaces readAvatarSurfaces(const GltfDocument& doc, const AvatarScan& scan) {
    AvatarSurfaces out;
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    MaterialReader materials(doc, views, out.materials);
    const bool context = !scan.context.triangles.empty();
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes && !context) continue;
        SurfaceLayout& layout = mesh.carriesVisemes ? out.visemes : out.context;
        const tinygltf::Mesh& gm = doc.model.meshes[static_cast<std::size_t>(mesh.index)];
        for (std::size_t p = 0; p < gm.primitives.size() && p < mesh.primitives.size(); ++p) {
            const AvatarPrimitive& info = mesh.primitives[p];
            if (info.vertices == 0) continue; // not read (no POSITION)
            const tinygltf::Primitive& prim = gm.primitives[p];
            const std::string where =
                "meshes/" + std::to_string(mesh.index) + "/primitives/" + std::to_string(p);
            int texCoord = 0, material = -1;
            if (prim.material >= 0) material = materials.material(prim.material, texCoord);
            const std::string attribute = "TEXCOORD_" + std::to_string(texCoord);
            const auto uv = prim.attributes.find(attribute);
            std::vector<float> values;
            if (uv != prim.attributes.end()) {
                if (hasDraco(doc, mesh.index, static_cast<int>(p))) // its accessors hold the decoded values
                    (void)decodeDracoPrimitive(doc, views, reader, mesh.index, static_cast<int>(p));
                values =
                    reader.floats(uv->second, TINYGLTF_TYPE_VEC2, where + "/" + attribute, info.vertices);
            } else if (material >= 0 &&
                       out.materials.materials[static_cast<std::size_t>(material)].image >= 0) {
                out.materials.warnings.push_back(doc.source + ": " + where + ": no " + attribute +
                                                 " for its material's texture; drawn untextured");
            }
            for (std::size_t v = 0; v < info.vertices; ++v)
                layout.texCoords.push_back(values.empty() ? Vec2(0, 0)
                                                          : Vec2(values[2 * v], values[2 * v + 1]));
            addRange(layout, info.triangles, material);
        }
    }
    // The layouts must fit the scan's geometry vertex for vertex (they are drawn with it).
    const auto fit = [&](SurfaceLayout& layout, const MeshData& mesh, const char* what) {
        std::size_t triangles = 0;
        for (const MaterialRange& r : layout.ranges) triangles += r.triangleCount;
        if (layout.texCoords.size() != mesh.positions.size() || triangles != mesh.triangles.size())
            doc.fail("", std::string("the materials' layout does not match the ") + what + " geometry (" +
                             std::to_string(layout.texCoords.size()) + " vs " +
                             std::to_string(mesh.positions.size()) + " vertices)");
        layout.cornerTexCoords = mesh.triangles; // one texture coordinate per vertex
    };
    fit(out.visemes, scan.set.neutral, "viseme set's");
    if (context) fit(out.context, scan.context, "context");
    return out;
}

} // namespace vl
