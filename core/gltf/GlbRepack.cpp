#include "core/gltf/GlbRepack.h"

#include "core/common/Limits.h"
#include "core/gltf/GlbContainer.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/GltfReferences.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

std::size_t arraySize(const Json& doc, const char* key) {
    const auto it = doc.find(key);
    return it != doc.end() && it->is_array() ? it->size() : 0;
}

// The image type from its first bytes (the types glTF and its texture extensions allow).
std::string sniffMimeType(const std::string& bytes) {
    if (bytes.rfind("\x89PNG", 0) == 0) return "image/png";
    if (bytes.rfind("\xFF\xD8\xFF", 0) == 0) return "image/jpeg";
    if (bytes.size() >= 12 && bytes.compare(0, 4, "RIFF") == 0 && bytes.compare(8, 4, "WEBP") == 0)
        return "image/webp";
    if (bytes.rfind("\xABKTX 20\xBB", 0) == 0) return "image/ktx2";
    if (bytes.size() >= 12 && bytes.compare(4, 8, "ftypavif") == 0) return "image/avif";
    if (bytes.rfind("DDS ", 0) == 0) return "image/vnd-ms.dds";
    return "";
}

void appendAligned(std::string& bin, const unsigned char* data, std::size_t size) {
    while (bin.size() % 4 != 0) bin.push_back('\0');
    bin.append(reinterpret_cast<const char*>(data), size);
}

Json* meshoptExtension(Json& view) {
    const auto ext = view.find("extensions");
    if (ext == view.end() || !ext->is_object()) return nullptr;
    const auto it = ext->find("EXT_meshopt_compression");
    return it == ext->end() || !it->is_object() ? nullptr : &*it;
}

bool anyHas(Json& doc, const char* array, const char* extensionName) {
    bool found = false;
    const auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) return false;
    for (Json& element : *it)
        if (element.is_object() && element.contains("extensions") && element["extensions"].is_object() &&
            element["extensions"].contains(extensionName))
            found = true;
    return found;
}

bool dracoUsed(Json& doc) {
    const auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array()) return false;
    for (Json& mesh : *meshes)
        if (mesh.is_object() && anyHas(mesh, "primitives", "KHR_draco_mesh_compression")) return true;
    return false;
}

void dropExtensionName(Json& doc, const std::string& name) {
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        const auto it = doc.find(list);
        if (it == doc.end() || !it->is_array()) continue;
        Json kept = Json::array();
        for (const Json& e : *it)
            if (!(e.is_string() && e.get<std::string>() == name)) kept.push_back(e);
        if (kept.empty())
            doc.erase(list);
        else
            *it = kept;
    }
}

} // namespace

GlbRepack::GlbRepack(const GltfDocument& doc) : json(doc.json), doc_(doc) {
    originalViews_ = arraySize(json, "bufferViews");
}

int GlbRepack::addView(std::string bytes, int target, std::size_t stride) {
    if (!json.contains("bufferViews")) json["bufferViews"] = Json::array();
    Json view{{"buffer", 0}, {"byteLength", bytes.size()}};
    if (stride) view["byteStride"] = stride;
    if (target) view["target"] = target;
    json["bufferViews"].push_back(view);
    newViews_.push_back({std::move(bytes), false});
    return static_cast<int>(json["bufferViews"].size()) - 1;
}

int GlbRepack::addMeshoptView(std::string encoded, std::size_t count, std::size_t stride,
                              const std::string& mode, const std::string& filter, int target) {
    requireExtension("EXT_meshopt_compression");
    if (!json.contains("bufferViews")) json["bufferViews"] = Json::array();
    Json ext{{"buffer", 0},
             {"byteLength", encoded.size()},
             {"byteStride", stride},
             {"mode", mode},
             {"count", count}};
    if (filter != "NONE") ext["filter"] = filter;
    // buffer and byteOffset (in the fallback buffer) are set by finish().
    Json view{{"buffer", 0}, {"byteLength", count * stride}};
    if (mode == "ATTRIBUTES") view["byteStride"] = stride;
    if (target) view["target"] = target;
    view["extensions"] = {{"EXT_meshopt_compression", ext}};
    json["bufferViews"].push_back(view);
    newViews_.push_back({std::move(encoded), true});
    return static_cast<int>(json["bufferViews"].size()) - 1;
}

void GlbRepack::requireExtension(const std::string& name) {
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        if (!json.contains(list) || !json[list].is_array()) json[list] = Json::array();
        Json& names = json[list];
        if (std::find(names.begin(), names.end(), Json(name)) == names.end()) names.push_back(name);
    }
}

int GlbRepack::addAccessor(Json accessor) {
    if (!json.contains("accessors")) json["accessors"] = Json::array();
    json["accessors"].push_back(std::move(accessor));
    return static_cast<int>(json["accessors"].size()) - 1;
}

std::size_t GlbRepack::binBound() const {
    std::size_t bound = 0;
    for (const GltfBuffer& b : doc_.buffers) bound += b.length;
    for (const NewView& added : newViews_) bound += added.bytes.size();
    return bound + 4 * (arraySize(json, "bufferViews") + 1); // alignment padding
}

std::map<long long, std::string> GlbRepack::compactSharedViews(const std::vector<int>& accessorIndex) {
    std::map<long long, std::string> compacted;
    const std::size_t viewCount = arraySize(json, "bufferViews");
    std::vector<std::size_t> references(viewCount, 0);
    forEachBufferViewReference(json, [&](Json& index) {
        const auto i = index.get<long long>();
        if (i >= 0 && static_cast<std::size_t>(i) < viewCount) ++references[static_cast<std::size_t>(i)];
    });
    std::map<std::size_t, std::vector<std::size_t>> users; // view -> accessors reading it densely
    for (std::size_t a = 0; a < accessorIndex.size(); ++a) {
        const Json& accessor = json["accessors"][a];
        if (accessor.is_object() && accessor.contains("bufferView") &&
            accessor["bufferView"].is_number_integer()) {
            const auto v = accessor["bufferView"].get<long long>();
            if (v >= 0 && static_cast<std::size_t>(v) < originalViews_)
                users[static_cast<std::size_t>(v)].push_back(a);
        }
    }
    for (const auto& [v, list] : users) {
        bool dropped = false, kept = false;
        for (std::size_t a : list) (accessorIndex[a] < 0 ? dropped : kept) = true;
        Json& view = json["bufferViews"][v];
        Json* ext = meshoptExtension(view);
        // Only views nothing else refers to, compressed as vertex data with a placeholder fallback.
        if (!dropped || !kept || references[v] != list.size() || !ext ||
            ext->value("mode", "") != "ATTRIBUTES")
            continue;
        const int buffer = view.value("buffer", -1), source = ext->value("buffer", -1);
        const std::size_t stride = ext->value("byteStride", std::size_t{0}),
                          count = ext->value("count", std::size_t{0});
        const std::size_t offset = ext->value("byteOffset", std::size_t{0}),
                          length = ext->value("byteLength", std::size_t{0});
        if (buffer < 0 || static_cast<std::size_t>(buffer) >= doc_.buffers.size() ||
            !doc_.buffers[static_cast<std::size_t>(buffer)].placeholder || source < 0 ||
            static_cast<std::size_t>(source) >= doc_.buffers.size() || stride == 0 || stride % 4 != 0)
            continue;
        const GltfBuffer& b = doc_.buffers[static_cast<std::size_t>(source)];
        if (b.placeholder || offset > b.length || length > b.length - offset ||
            count * stride != view.value("byteLength", std::size_t{0}))
            continue;
        // Decoded without the filter: elements are filtered one by one, so a subset stays valid as it is.
        std::vector<unsigned char> filtered(count * stride);
        if (meshopt_decodeVertexBuffer(filtered.data(), count, stride, b.data() + offset, length) != 0)
            doc_.fail("bufferViews/" + std::to_string(v), "meshoptimizer could not decode the data");
        std::vector<char> keep(count, 0);
        bool fits = true;
        for (std::size_t a : list) {
            if (accessorIndex[a] < 0) continue;
            const Json& accessor = json["accessors"][a];
            const std::size_t first = accessor.value("byteOffset", std::size_t{0}) / stride,
                              n = accessor.value("count", std::size_t{0});
            if (first > count || n > count - first) fits = false;
            for (std::size_t e = first; fits && e < first + n; ++e) keep[e] = 1;
        }
        std::vector<std::size_t> newElement(count, 0);
        std::string bytes;
        for (std::size_t e = 0; e < count; ++e) {
            if (!keep[e]) continue;
            newElement[e] = bytes.size() / stride;
            bytes.append(reinterpret_cast<const char*>(filtered.data() + e * stride), stride);
        }
        const std::size_t newCount = bytes.size() / stride;
        if (!fits || newCount == count || newCount == 0) continue;
        for (std::size_t a : list) {
            if (accessorIndex[a] < 0) continue;
            Json& accessor = json["accessors"][a];
            const std::size_t byteOffset = accessor.value("byteOffset", std::size_t{0});
            accessor["byteOffset"] = newElement[byteOffset / stride] * stride + byteOffset % stride;
        }
        meshopt_encodeVertexVersion(0); // EXT_meshopt_compression: version 0 only
        std::string encoded(meshopt_encodeVertexBufferBound(newCount, stride), '\0');
        encoded.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(encoded.data()),
                                                  encoded.size(), bytes.data(), newCount, stride));
        (*ext)["count"] = newCount;
        (*ext)["byteLength"] = encoded.size();
        view["byteLength"] = newCount * stride;
        compacted[static_cast<long long>(v)] = std::move(encoded);
    }
    return compacted;
}

void GlbRepack::embedExternalImages() {
    const auto images = json.find("images");
    if (images == json.end() || !images->is_array()) return;
    for (std::size_t i = 0; i < images->size(); ++i) {
        Json& image = (*images)[i];
        if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) continue;
        const std::string uri = image["uri"].get<std::string>();
        if (isDataUri(uri)) continue; // already inside the JSON
        const std::string element = "images/" + std::to_string(i) + "/uri";
        std::string bytes = doc_.readExternal(uri, element, limits::kMaxInputFileBytes);
        std::string mime = image.value("mimeType", "");
        if (mime.empty()) mime = sniffMimeType(bytes);
        if (mime.empty()) doc_.fail(element, "'" + uri + "' is not an image type a GLB can embed");
        const int view = addView(std::move(bytes));
        image.erase("uri");
        image["bufferView"] = view;
        image["mimeType"] = mime;
    }
}

std::string GlbRepack::finish(RepackStats* stats) {
    embedExternalImages();
    // Accessors the caller stopped using, and the views only they used.
    const std::size_t accessorCount = arraySize(json, "accessors");
    std::vector<char> usedAccessor(accessorCount, 0);
    forEachAccessorReference(json, [&](Json& index) {
        const auto i = index.get<long long>();
        if (i >= 0 && static_cast<std::size_t>(i) < accessorCount)
            usedAccessor[static_cast<std::size_t>(i)] = 1;
    });
    std::vector<int> accessorIndex(accessorCount);
    std::set<long long> viewCandidates;
    int next = 0;
    for (std::size_t a = 0; a < accessorCount; ++a) {
        const bool drop = !usedAccessor[a] && dropCandidates_.count(static_cast<int>(a));
        accessorIndex[a] = drop ? -1 : next++;
        if (!drop) continue;
        Json single = Json::object();
        single["accessors"] = Json::array({json["accessors"][a]});
        forEachBufferViewReference(single, [&](Json& view) { viewCandidates.insert(view.get<long long>()); });
    }
    const std::map<long long, std::string> compacted = compactSharedViews(accessorIndex);
    renumber(json, "accessors", accessorIndex, &forEachAccessorReference);

    const std::size_t viewCount = arraySize(json, "bufferViews");
    std::vector<char> usedView(viewCount, 0);
    forEachBufferViewReference(json, [&](Json& index) {
        const auto i = index.get<long long>();
        if (i >= 0 && static_cast<std::size_t>(i) < viewCount) usedView[static_cast<std::size_t>(i)] = 1;
    });
    std::vector<int> viewIndex(viewCount);
    std::vector<long long> sourceOf; // per kept view: original index, or -(1 + new view number)
    next = 0;
    for (std::size_t v = 0; v < viewCount; ++v) {
        const bool drop = !usedView[v] && viewCandidates.count(static_cast<long long>(v));
        viewIndex[v] = drop ? -1 : next++;
        if (!drop)
            sourceOf.push_back(v < originalViews_ ? static_cast<long long>(v)
                                                  : -1 - static_cast<long long>(v - originalViews_));
    }
    renumber(json, "bufferViews", viewIndex, &forEachBufferViewReference);

    // Buffers: one BIN chunk with every byte that remains, then the placeholder fallback buffers.
    std::vector<int> placeholderIndex(doc_.buffers.size(), -1);
    Json buffers = Json::array({Json{{"byteLength", 0}}});
    std::string bin;
    bin.reserve(binBound()); // one allocation: appending a 15 MB chunk by doubling touched 2.5x its size
    const auto placeholder = [&](int buffer) {
        if (placeholderIndex[static_cast<std::size_t>(buffer)] < 0) {
            placeholderIndex[static_cast<std::size_t>(buffer)] = static_cast<int>(buffers.size());
            buffers.push_back(json["buffers"][static_cast<std::size_t>(buffer)]);
        }
        return placeholderIndex[static_cast<std::size_t>(buffer)];
    };
    const auto copyRange = [&](int buffer, std::size_t offset, std::size_t length,
                               const std::string& element) {
        if (buffer < 0 || static_cast<std::size_t>(buffer) >= doc_.buffers.size())
            doc_.fail(element, "buffer " + std::to_string(buffer) + " does not exist");
        const GltfBuffer& b = doc_.buffers[static_cast<std::size_t>(buffer)];
        if (offset > b.length || length > b.length - offset) doc_.fail(element, "lies outside its buffer");
        appendAligned(bin, b.data() + offset, length);
        return bin.size() - length;
    };
    std::vector<std::size_t> newCompressed; // kept views of new compressed bytes
    for (std::size_t v = 0; v < sourceOf.size(); ++v) {
        Json& view = json["bufferViews"][v];
        if (sourceOf[v] < 0) {
            const NewView& added = newViews_[static_cast<std::size_t>(-1 - sourceOf[v])];
            appendAligned(bin, reinterpret_cast<const unsigned char*>(added.bytes.data()),
                          added.bytes.size());
            Json& target = added.meshopt ? *meshoptExtension(view) : view;
            target["buffer"] = 0;
            target["byteOffset"] = bin.size() - added.bytes.size();
            if (added.meshopt) newCompressed.push_back(v);
            continue;
        }
        const std::string element = "bufferViews/" + std::to_string(sourceOf[v]);
        if (const auto it = compacted.find(sourceOf[v]); it != compacted.end()) {
            Json& meshopt = *meshoptExtension(view);
            appendAligned(bin, reinterpret_cast<const unsigned char*>(it->second.data()), it->second.size());
            meshopt["buffer"] = 0;
            meshopt["byteOffset"] = bin.size() - it->second.size();
        } else if (Json* meshopt = meshoptExtension(view)) {
            const std::size_t at =
                copyRange((*meshopt)["buffer"].get<int>(), meshopt->value("byteOffset", std::size_t{0}),
                          (*meshopt)["byteLength"].get<std::size_t>(), element);
            (*meshopt)["buffer"] = 0;
            (*meshopt)["byteOffset"] = at;
        }
        const int buffer = view["buffer"].get<int>();
        if (buffer >= 0 && static_cast<std::size_t>(buffer) < doc_.buffers.size() &&
            doc_.buffers[static_cast<std::size_t>(buffer)].placeholder) {
            view["buffer"] = placeholder(buffer);
            continue;
        }
        const std::size_t at = copyRange(buffer, view.value("byteOffset", std::size_t{0}),
                                         view["byteLength"].get<std::size_t>(), element);
        view["buffer"] = 0;
        view["byteOffset"] = at;
    }
    if (!newCompressed.empty()) {
        // The uncompressed layout of new compressed views: in a fallback buffer without data, as the
        // extension requires; buffers after the BIN chunk are all such placeholders.
        if (buffers.size() < 2)
            buffers.push_back(
                {{"byteLength", 0}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
        Json& fallback = buffers[1];
        std::size_t end = fallback.value("byteLength", std::size_t{0});
        for (std::size_t v : newCompressed) {
            Json& view = json["bufferViews"][v];
            end = (end + 3) / 4 * 4;
            view["buffer"] = 1;
            view["byteOffset"] = end;
            end += view["byteLength"].get<std::size_t>();
        }
        fallback["byteLength"] = end;
    }
    while (bin.size() % 4 != 0 || bin.empty()) bin.push_back('\0');
    buffers[0]["byteLength"] = bin.size();
    json["buffers"] = buffers;

    if (!anyHas(json, "bufferViews", "EXT_meshopt_compression") &&
        !anyHas(json, "buffers", "EXT_meshopt_compression"))
        dropExtensionName(json, "EXT_meshopt_compression");
    if (!dracoUsed(json)) dropExtensionName(json, "KHR_draco_mesh_compression");

    if (stats) {
        stats->accessorsBefore = arraySize(doc_.json, "accessors");
        stats->accessorsAfter = arraySize(json, "accessors");
        stats->binaryBytesBefore = 0;
        for (const GltfBuffer& b : doc_.buffers) stats->binaryBytesBefore += b.length;
        stats->binaryBytesAfter = bin.size();
    }
    return joinGlb(json.dump(), bin);
}

} // namespace vl
