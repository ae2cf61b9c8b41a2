#include "core/gltf/BufferViews.h"

#include "core/gltf/GltfDocument.h"

#include <meshoptimizer.h>

#include <optional>

namespace vl {
namespace {

const nlohmann::ordered_json* meshoptExtension(const nlohmann::ordered_json& view) {
    const auto ext = view.find("extensions");
    if (ext == view.end() || !ext->is_object()) return nullptr;
    const auto m = ext->find("EXT_meshopt_compression");
    return m == ext->end() ? nullptr : &*m;
}

std::uint64_t unsignedField(const GltfDocument& doc, const nlohmann::ordered_json& object, const char* key,
                            const std::string& where, std::optional<std::uint64_t> fallback = {}) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (!fallback) doc.fail(where, std::string("missing ") + key);
        return *fallback;
    }
    if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0))
        doc.fail(where + "/" + key, "must be an integer >= 0");
    return it->get<std::uint64_t>();
}

} // namespace

bool BufferViews::isCompressed(int index) const {
    const auto views = doc_.json.find("bufferViews");
    return views != doc_.json.end() && views->is_array() && index >= 0 &&
           static_cast<std::size_t>(index) < views->size() &&
           meshoptExtension((*views)[static_cast<std::size_t>(index)]) != nullptr;
}

ViewBytes BufferViews::view(int index, const std::string& where) {
    const auto& views = doc_.model.bufferViews;
    if (index < 0 || static_cast<std::size_t>(index) >= views.size())
        doc_.fail(where, "buffer view " + std::to_string(index) + " does not exist");
    const tinygltf::BufferView& view = views[static_cast<std::size_t>(index)];
    const std::string viewWhere = "bufferViews/" + std::to_string(index);
    ViewBytes out;
    out.stride = view.byteStride;
    if (isCompressed(index)) {
        const std::vector<unsigned char>& bytes = decodeMeshopt(index, viewWhere);
        out.data = bytes.data();
        out.size = bytes.size();
        out.compressed = true;
        return out;
    }
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= doc_.buffers.size())
        doc_.fail(viewWhere, "buffer " + std::to_string(view.buffer) + " does not exist");
    const GltfBuffer& buffer = doc_.buffers[static_cast<std::size_t>(view.buffer)];
    if (buffer.placeholder)
        doc_.fail(viewWhere, "refers to a fallback buffer without data, and is not EXT_meshopt_compression "
                             "compressed");
    if (view.byteOffset > buffer.length || view.byteLength > buffer.length - view.byteOffset)
        doc_.fail(viewWhere, "lies outside buffer " + std::to_string(view.buffer) + " (" +
                                 std::to_string(buffer.length) + " bytes)");
    out.data = buffer.data() + view.byteOffset;
    out.size = view.byteLength;
    return out;
}

const std::vector<unsigned char>& BufferViews::decodeMeshopt(int index, const std::string& where) {
    if (const auto it = decoded_.find(index); it != decoded_.end()) return it->second;
    const auto& viewJson = doc_.json.at("bufferViews").at(static_cast<std::size_t>(index));
    const nlohmann::ordered_json& ext = *meshoptExtension(viewJson);
    const std::string extWhere = where + "/extensions/EXT_meshopt_compression";
    if (!ext.is_object()) doc_.fail(extWhere, "not an object");
    const std::uint64_t bufferIndex = unsignedField(doc_, ext, "buffer", extWhere);
    const std::uint64_t offset = unsignedField(doc_, ext, "byteOffset", extWhere, 0);
    const std::uint64_t length = unsignedField(doc_, ext, "byteLength", extWhere);
    const std::uint64_t stride = unsignedField(doc_, ext, "byteStride", extWhere);
    const std::uint64_t count = unsignedField(doc_, ext, "count", extWhere);
    const std::string mode = ext.value("mode", "");
    const std::string filter = ext.value("filter", "NONE");
    if (bufferIndex >= doc_.buffers.size())
        doc_.fail(extWhere + "/buffer", "buffer " + std::to_string(bufferIndex) + " does not exist");
    const GltfBuffer& buffer = doc_.buffers[bufferIndex];
    if (buffer.placeholder)
        doc_.fail(extWhere + "/buffer", "the compressed data is in a buffer without data");
    if (offset > buffer.length || length > buffer.length - offset)
        doc_.fail(extWhere, "compressed range lies outside buffer " + std::to_string(bufferIndex));
    const tinygltf::BufferView& parent = doc_.model.bufferViews[static_cast<std::size_t>(index)];
    if (stride == 0 || stride > 256) doc_.fail(extWhere + "/byteStride", "must be 1..256");
    if (count > (std::uint64_t{1} << 32) || stride * count != parent.byteLength)
        doc_.fail(extWhere, "count x byteStride differs from the view's byteLength " +
                                std::to_string(parent.byteLength));
    if (parent.byteStride != 0 && parent.byteStride != stride)
        doc_.fail(extWhere + "/byteStride", "differs from the view's byteStride");
    const std::uint64_t decodedSize = stride * count;
    if (decodedSize > kMaxMeshoptExpansion * length + 4096)
        doc_.fail(extWhere, std::to_string(length) + " compressed bytes cannot hold " +
                                std::to_string(decodedSize) + " bytes (hostile count?)");

    const unsigned char* source = buffer.data() + offset;
    std::vector<unsigned char> out(decodedSize);
    int result = -1;
    if (mode == "ATTRIBUTES") {
        if (stride % 4 != 0) doc_.fail(extWhere + "/byteStride", "ATTRIBUTES need a multiple of 4");
        result = meshopt_decodeVertexBuffer(out.data(), count, stride, source, length);
        if (result == 0) {
            if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
                meshopt_decodeFilterOct(out.data(), count, stride);
            else if (filter == "QUATERNION" && stride == 8)
                meshopt_decodeFilterQuat(out.data(), count, stride);
            else if (filter == "EXPONENTIAL")
                meshopt_decodeFilterExp(out.data(), count, stride);
            else if (filter != "NONE")
                doc_.fail(extWhere + "/filter",
                          "filter '" + filter + "' with byteStride " + std::to_string(stride));
        }
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) doc_.fail(extWhere + "/byteStride", mode + " need 2 or 4");
        if (filter != "NONE") doc_.fail(extWhere + "/filter", mode + " take no filter");
        if (mode == "TRIANGLES" && count % 3 != 0) doc_.fail(extWhere + "/count", "not a multiple of 3");
        result = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), count, stride, source, length)
                                     : meshopt_decodeIndexSequence(out.data(), count, stride, source, length);
    } else {
        doc_.fail(extWhere + "/mode", "unknown mode '" + mode + "'");
    }
    if (result != 0)
        doc_.fail(extWhere, "meshoptimizer could not decode the data (error " + std::to_string(result) + ")");
    return decoded_.emplace(index, std::move(out)).first->second;
}

} // namespace vl
