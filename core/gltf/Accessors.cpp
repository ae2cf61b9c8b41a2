#include "core/gltf/Accessors.h"

#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vl {
namespace {

template <typename T> T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

float component(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? p[0] / 255.0f : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = load<std::int8_t>(p);
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const auto v = load<std::uint16_t>(p);
        return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const auto v = load<std::int16_t>(p);
        return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    default: // UNSIGNED_INT (never normalised in glTF)
        return static_cast<float>(load<std::uint32_t>(p));
    }
}

std::uint32_t unsignedComponent(const unsigned char* p, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return load<std::uint16_t>(p);
    default:
        return load<std::uint32_t>(p);
    }
}

bool isUnsignedIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

} // namespace

int componentsOf(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

int componentBytes(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

const tinygltf::Accessor& AccessorReader::accessor(int index, const std::string& where) const {
    if (index < 0 || static_cast<std::size_t>(index) >= doc_.model.accessors.size())
        doc_.fail(where, "accessor " + std::to_string(index) + " does not exist");
    return doc_.model.accessors[static_cast<std::size_t>(index)];
}

// Needs byteOffset + (count - 1) * stride + elementSize <= view size, checked without overflow,
// before the caller allocates anything for `count` elements.
void AccessorReader::readDense(int viewIndex, std::size_t byteOffset, std::size_t count, int components,
                               int componentType, bool normalized, float* out, const std::string& where) {
    if (count == 0) return;
    const std::size_t size = static_cast<std::size_t>(componentBytes(componentType));
    const std::size_t elementSize = size * static_cast<std::size_t>(components);
    const ViewBytes view = views_.view(viewIndex, where);
    const std::size_t stride = view.stride == 0 ? elementSize : view.stride;
    if (stride < elementSize)
        doc_.fail(where, "byteStride " + std::to_string(stride) + " is smaller than an element");
    for (std::size_t i = 0; i < count; ++i) {
        const unsigned char* element = view.data + byteOffset + i * stride;
        float* o = out + i * static_cast<std::size_t>(components);
        if (componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            std::memcpy(o, element, elementSize);
        } else {
            for (int c = 0; c < components; ++c)
                o[c] = component(element + static_cast<std::size_t>(c) * size, componentType, normalized);
        }
    }
}

std::vector<std::uint32_t> AccessorReader::readUnsigned(int viewIndex, std::size_t byteOffset,
                                                        std::size_t count, int componentType,
                                                        const std::string& where) {
    const std::size_t size = static_cast<std::size_t>(componentBytes(componentType));
    const ViewBytes view = views_.view(viewIndex, where);
    const std::size_t stride = view.stride == 0 ? size : view.stride;
    if (count > 0 && (stride < size || byteOffset > view.size || view.size - byteOffset < size ||
                      count - 1 > (view.size - byteOffset - size) / stride))
        doc_.fail(where, std::to_string(count) + " elements run past buffer view " +
                             std::to_string(viewIndex) + " (" + std::to_string(view.size) + " bytes)");
    std::vector<std::uint32_t> out(count);
    for (std::size_t i = 0; i < count; ++i)
        out[i] = unsignedComponent(view.data + byteOffset + i * stride, componentType);
    return out;
}

std::vector<float> AccessorReader::floats(int index, int type, const std::string& where,
                                          std::size_t expectedCount) {
    const tinygltf::Accessor& a = accessor(index, where);
    const std::string at = where + " (accessor " + std::to_string(index) + ")";
    if (type >= 0 && a.type != type) doc_.fail(at, "unexpected accessor type");
    const int components = componentsOf(a.type);
    const int size = componentBytes(a.componentType);
    if (components <= 0 || size <= 0) doc_.fail(at, "unsupported type or component type");
    if (expectedCount != kAnyCount && a.count != expectedCount)
        doc_.fail(at, "count " + std::to_string(a.count) + " differs from the " +
                          std::to_string(expectedCount) + " vertices of the primitive");
    const std::size_t n = static_cast<std::size_t>(components);
    if (const auto it = providedFloats_.find(index); it != providedFloats_.end()) {
        if (it->second.size() != a.count * n) doc_.fail(at, "count differs from the decoded Draco data");
        return it->second;
    }
    if (a.bufferView < 0 && expectedCount == kAnyCount)
        doc_.fail(at, "has no buffer view, so no data to read here");
    if (a.bufferView >= 0) {
        // Bytes first: count * stride must fit in the view before count floats are allocated.
        const ViewBytes view = views_.view(a.bufferView, at);
        const std::size_t elementSize = static_cast<std::size_t>(size) * n;
        const std::size_t stride = view.stride == 0 ? elementSize : view.stride;
        if (a.count > 0 &&
            (a.byteOffset > view.size || view.size - a.byteOffset < elementSize ||
             a.count - 1 > (view.size - a.byteOffset - elementSize) / std::max(stride, std::size_t{1})))
            doc_.fail(at, std::to_string(a.count) + " elements run past buffer view " +
                              std::to_string(a.bufferView) + " (" + std::to_string(view.size) + " bytes)");
    }
    std::vector<float> out(a.count * n, 0.0f);
    if (a.bufferView >= 0)
        readDense(a.bufferView, a.byteOffset, a.count, components, a.componentType, a.normalized, out.data(),
                  at);
    if (a.sparse.isSparse) {
        const std::string sparseAt = at + " sparse";
        if (a.sparse.count < 1 || static_cast<std::size_t>(a.sparse.count) > a.count)
            doc_.fail(sparseAt,
                      "count " + std::to_string(a.sparse.count) + " outside 1.." + std::to_string(a.count));
        const auto count = static_cast<std::size_t>(a.sparse.count);
        const int indexType = a.sparse.indices.componentType;
        if (!isUnsignedIndexType(indexType))
            doc_.fail(sparseAt + " indices", "componentType " + std::to_string(indexType) +
                                                 " (only unsigned byte, short or int are allowed)");
        const std::vector<std::uint32_t> indices =
            readUnsigned(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset),
                         count, indexType, sparseAt + " indices");
        for (std::size_t i = 0; i < count; ++i) {
            if (indices[i] >= a.count)
                doc_.fail(sparseAt + " indices", "index " + std::to_string(indices[i]) + " at " +
                                                     std::to_string(i) + " is not below the accessor count " +
                                                     std::to_string(a.count));
            if (i > 0 && indices[i] <= indices[i - 1])
                doc_.fail(sparseAt + " indices", "not strictly increasing at " + std::to_string(i));
        }
        const ViewBytes values = views_.view(a.sparse.values.bufferView, sparseAt + " values");
        const std::size_t elementSize = static_cast<std::size_t>(size) * n;
        const auto offset = static_cast<std::size_t>(a.sparse.values.byteOffset);
        if (offset > values.size || (values.size - offset) / elementSize < count)
            doc_.fail(sparseAt + " values", std::to_string(count) + " values run past buffer view " +
                                                std::to_string(a.sparse.values.bufferView));
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t c = 0; c < n; ++c)
                out[indices[i] * n + c] =
                    component(values.data + offset + i * elementSize + c * static_cast<std::size_t>(size),
                              a.componentType, a.normalized);
    }
    for (float v : out)
        if (!std::isfinite(v)) doc_.fail(at, "non-finite value");
    return out;
}

std::vector<std::uint32_t> AccessorReader::indices(int index, const std::string& where,
                                                   std::size_t vertexCount) {
    const tinygltf::Accessor& a = accessor(index, where);
    const std::string at = where + " (accessor " + std::to_string(index) + ")";
    std::vector<std::uint32_t> out;
    if (const auto it = providedIndices_.find(index); it != providedIndices_.end()) {
        out = it->second;
    } else {
        if (a.type != TINYGLTF_TYPE_SCALAR || !isUnsignedIndexType(a.componentType))
            doc_.fail(at, "indices must be scalar unsigned byte, short or int");
        if (a.bufferView < 0 || a.sparse.isSparse)
            doc_.fail(at, "indices need a buffer view and no sparse storage");
        out = readUnsigned(a.bufferView, a.byteOffset, a.count, a.componentType, at);
    }
    for (std::size_t i = 0; i < out.size(); ++i)
        if (out[i] >= vertexCount)
            doc_.fail(at, "index " + std::to_string(out[i]) + " at " + std::to_string(i) +
                              " is not below the " + std::to_string(vertexCount) + " vertices");
    return out;
}

} // namespace vl
