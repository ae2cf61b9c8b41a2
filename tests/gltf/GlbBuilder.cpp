#include "tests/gltf/GlbBuilder.h"

#include "core/gltf/GlbContainer.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace vl::test {
namespace {

int componentsOf(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    if (type == "MAT4") return 16;
    throw std::invalid_argument("type " + type);
}

} // namespace

void vectorBounds(const std::vector<float>& values, int components, std::vector<double>& lo,
                  std::vector<double>& hi) {
    lo.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
    hi.assign(static_cast<std::size_t>(components), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto c = i % static_cast<std::size_t>(components);
        lo[c] = std::min(lo[c], static_cast<double>(values[i]));
        hi[c] = std::max(hi[c], static_cast<double>(values[i]));
    }
}

GlbBuilder::GlbBuilder() {
    json["asset"] = {{"version", "2.0"}, {"generator", "VisemeLab test fixtures"}};
    json["buffers"] = nlohmann::ordered_json::array({{{"byteLength", 0}}}); // buffer 0: the BIN chunk
}

void GlbBuilder::useExtension(const std::string& name, bool required) {
    auto addTo = [&](const char* list) {
        if (!json.contains(list)) json[list] = nlohmann::ordered_json::array();
        for (const auto& e : json[list])
            if (e == name) return;
        json[list].push_back(name);
    };
    addTo("extensionsUsed");
    if (required) addTo("extensionsRequired");
}

void GlbBuilder::align() {
    while (bin.size() % 4 != 0) bin.push_back('\0');
}

int GlbBuilder::add(const std::string& array, nlohmann::ordered_json object) {
    if (!json.contains(array)) json[array] = nlohmann::ordered_json::array();
    json[array].push_back(std::move(object));
    return static_cast<int>(json[array].size()) - 1;
}

int GlbBuilder::addView(const void* data, std::size_t bytes, int target, std::size_t stride) {
    align();
    nlohmann::ordered_json view{{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (stride) view["byteStride"] = stride;
    if (target) view["target"] = target;
    bin.append(static_cast<const char*>(data), bytes);
    return add("bufferViews", view);
}

int GlbBuilder::addMeshoptView(const void* data, std::size_t count, std::size_t stride,
                               const std::string& mode, const std::string& filter, int target) {
    useExtension("EXT_meshopt_compression", true);
    if (meshoptFallback_ < 0) {
        meshoptFallback_ =
            add("buffers",
                {{"byteLength", 4}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    }
    std::vector<unsigned char> encoded;
    if (mode == "ATTRIBUTES") {
        encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
        encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), data, count, stride));
    } else {
        std::vector<std::uint32_t> indices(count);
        for (std::size_t i = 0; i < count; ++i)
            indices[i] = stride == 2 ? static_cast<const std::uint16_t*>(data)[i]
                                     : static_cast<const std::uint32_t*>(data)[i];
        std::size_t vertices = 0;
        for (auto i : indices) vertices = std::max<std::size_t>(vertices, i + 1);
        encoded.resize(meshopt_encodeIndexBufferBound(count, vertices) + 16);
        encoded.resize(
            mode == "TRIANGLES"
                ? meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count)
                : meshopt_encodeIndexSequence(encoded.data(), encoded.size(), indices.data(), count));
    }
    if (encoded.empty()) throw std::runtime_error("meshopt encoding failed");
    align();
    const std::size_t compressedOffset = bin.size();
    bin.append(reinterpret_cast<const char*>(encoded.data()), encoded.size());
    // The fallback buffer gets the uncompressed layout; its byteLength grows to cover every view.
    auto& fallback = json["buffers"][static_cast<std::size_t>(meshoptFallback_)];
    const std::size_t fallbackOffset = (fallback["byteLength"].get<std::size_t>() + 3) & ~std::size_t{3};
    fallback["byteLength"] = fallbackOffset + count * stride;
    nlohmann::ordered_json ext{{"buffer", 0},
                               {"byteOffset", compressedOffset},
                               {"byteLength", encoded.size()},
                               {"byteStride", stride},
                               {"mode", mode},
                               {"count", count}};
    if (filter != "NONE") ext["filter"] = filter;
    nlohmann::ordered_json view{
        {"buffer", meshoptFallback_}, {"byteOffset", fallbackOffset}, {"byteLength", count * stride}};
    if (mode == "ATTRIBUTES" && target == kArrayBuffer) view["byteStride"] = stride;
    if (target) view["target"] = target;
    view["extensions"] = {{"EXT_meshopt_compression", ext}};
    return add("bufferViews", view);
}

int GlbBuilder::addAccessor(int view, int componentType, const std::string& type, std::size_t count,
                            bool normalized, const std::vector<double>& minValues,
                            const std::vector<double>& maxValues) {
    nlohmann::ordered_json a;
    if (view >= 0) a["bufferView"] = view;
    a["componentType"] = componentType;
    if (normalized) a["normalized"] = true;
    a["count"] = count;
    a["type"] = type;
    if (!minValues.empty()) {
        a["min"] = minValues;
        a["max"] = maxValues;
    }
    return add("accessors", a);
}

int GlbBuilder::addFloats(const std::vector<float>& values, const std::string& type, bool bounds,
                          int target) {
    const int components = componentsOf(type);
    const int view = addView(values.data(), values.size() * sizeof(float), target);
    std::vector<double> lo, hi;
    if (bounds) vectorBounds(values, components, lo, hi);
    return addAccessor(view, kFloat, type, values.size() / static_cast<std::size_t>(components), false, lo,
                       hi);
}

int GlbBuilder::addIndices(const std::vector<std::uint32_t>& indices) {
    const bool small = *std::max_element(indices.begin(), indices.end()) < 65535;
    int view;
    if (small) {
        std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
        view = addView(shorts.data(), shorts.size() * 2, kElementArrayBuffer);
    } else {
        view = addView(indices.data(), indices.size() * 4, kElementArrayBuffer);
    }
    return addAccessor(view, small ? kUnsignedShort : kUnsignedInt, "SCALAR", indices.size(), false);
}

int GlbBuilder::addSparseVec3(const std::vector<float>& values, int indexType) {
    std::vector<std::uint32_t> nonZero;
    std::vector<float> nonZeroValues;
    for (std::size_t i = 0; i < values.size() / 3; ++i)
        if (values[3 * i] != 0 || values[3 * i + 1] != 0 || values[3 * i + 2] != 0) {
            nonZero.push_back(static_cast<std::uint32_t>(i));
            nonZeroValues.insert(nonZeroValues.end(), values.begin() + static_cast<long>(3 * i),
                                 values.begin() + static_cast<long>(3 * i + 3));
        }
    std::vector<double> lo, hi;
    vectorBounds(values, 3, lo, hi);
    const int accessor = addAccessor(-1, kFloat, "VEC3", values.size() / 3, false, lo, hi);
    if (nonZero.empty()) return accessor; // all zeros: no sparse storage at all
    int indexView;
    if (indexType == kUnsignedByte) {
        std::vector<std::uint8_t> idx(nonZero.begin(), nonZero.end());
        indexView = addView(idx.data(), idx.size());
    } else if (indexType == kUnsignedShort) {
        std::vector<std::uint16_t> idx(nonZero.begin(), nonZero.end());
        indexView = addView(idx.data(), idx.size() * 2);
    } else {
        indexView = addView(nonZero.data(), nonZero.size() * 4);
    }
    const int valueView = addView(nonZeroValues.data(), nonZeroValues.size() * 4);
    json["accessors"][static_cast<std::size_t>(accessor)]["sparse"] = {
        {"count", nonZero.size()},
        {"indices", {{"bufferView", indexView}, {"componentType", indexType}}},
        {"values", {{"bufferView", valueView}}}};
    return accessor;
}

std::string GlbBuilder::glb() const {
    nlohmann::ordered_json out = json;
    out["buffers"][0]["byteLength"] = bin.size();
    return joinGlb(out.dump(), bin);
}

} // namespace vl::test
