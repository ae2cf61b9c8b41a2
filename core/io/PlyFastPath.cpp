#include "core/io/PlyFastPath.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace vl::meshio {

namespace {

struct VertexLayout {
    std::size_t stride = 0;
    std::size_t offset[3] = {0, 0, 0};
    bool isDouble[3] = {false, false, false};
};

bool hasUvCandidate(const PlyElement& vertex) {
    for (const char* name : {"u", "v", "s", "t", "texture_u", "texture_v", "texture_s", "texture_t"})
        if (vertex.find(name) >= 0) return true;
    return false;
}

std::optional<VertexLayout> vertexLayout(const PlyElement& vertex) {
    if (vertex.name != "vertex" || hasUvCandidate(vertex)) return std::nullopt;
    VertexLayout layout;
    int found = 0;
    for (const auto& property : vertex.properties) {
        if (property.isList) return std::nullopt;
        for (int axis = 0; axis < 3; ++axis) {
            if (property.name != std::string_view("xyz" + axis, 1)) continue;
            if (property.type != PlyType::Float32 && property.type != PlyType::Float64) return std::nullopt;
            layout.offset[axis] = layout.stride;
            layout.isDouble[axis] = property.type == PlyType::Float64;
            ++found;
        }
        layout.stride += plyTypeSize(property.type);
    }
    if (found != 3) return std::nullopt; // a duplicate or missing axis: the general reader decides
    return layout;
}

bool isTriangleList(const PlyElement& face) {
    if (face.name != "face" || face.properties.size() != 1) return false;
    const PlyProperty& list = face.properties[0];
    return list.isList && (list.name == "vertex_indices" || list.name == "vertex_index") &&
           (list.countType == PlyType::UInt8 || list.countType == PlyType::Int8) &&
           (list.type == PlyType::Int32 || list.type == PlyType::UInt32);
}

double coordinate(const char* at, bool isDouble) {
    if (isDouble) {
        double d;
        std::memcpy(&d, at, sizeof d);
        return d;
    }
    float f;
    std::memcpy(&f, at, sizeof f);
    return static_cast<double>(f);
}

bool readVertices(const char* data, std::size_t count, const VertexLayout& layout, std::vector<Vec3>& out) {
    out.reserve(count); // reserve + push_back: nothing written twice
    for (std::size_t i = 0; i < count; ++i) {
        const char* record = data + i * layout.stride;
        Vec3 p;
        for (int axis = 0; axis < 3; ++axis) {
            p[axis] = coordinate(record + layout.offset[axis], layout.isDouble[axis]);
            if (!std::isfinite(p[axis])) return false;
        }
        out.push_back(p);
    }
    return true;
}

constexpr std::size_t kFaceRecord = 1 + 3 * sizeof(std::int32_t);

// Reads the triangle at `record`; false for anything the general reader would report or triangulate
// differently (not 3 corners, an index out of range, a repeated vertex).
bool readTriangle(const char* record, std::size_t vertexCount, Triangle& t) {
    if (record[0] != 3) return false;
    std::int32_t v[3];
    std::memcpy(v, record + 1, sizeof v);
    for (int k = 0; k < 3; ++k) {
        if (v[k] < 0 || static_cast<std::uint64_t>(v[k]) >= vertexCount) return false;
        t[k] = static_cast<std::uint32_t>(v[k]);
    }
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
}

} // namespace

std::optional<MeshData> readPlyFast(std::string_view bytes, const PlyHeader& header,
                                    const std::vector<Triangle>* expected) {
    const bool littleFile = header.encoding == PlyEncoding::BinaryLittleEndian;
    if (header.encoding == PlyEncoding::Ascii || littleFile != (std::endian::native == std::endian::little))
        return std::nullopt;
    std::vector<const PlyElement*> elements;
    for (const auto& element : header.elements)
        if (!element.properties.empty()) elements.push_back(&element); // the others hold no data
    if (elements.size() != 2 || !isTriangleList(*elements[1])) return std::nullopt;
    const auto layout = vertexLayout(*elements[0]);
    if (!layout) return std::nullopt;
    const std::size_t vertices = elements[0]->count, faces = elements[1]->count;
    const std::size_t available = bytes.size() - header.dataOffset;
    // Counts are checked against the bytes before anything is allocated.
    if (vertices == 0 || faces == 0 || vertices > available / layout->stride ||
        faces > (available - vertices * layout->stride) / kFaceRecord)
        return std::nullopt;
    if (expected && expected->size() != faces) return std::nullopt;
    MeshData mesh;
    const char* data = bytes.data() + header.dataOffset;
    if (!readVertices(data, vertices, *layout, mesh.positions)) return std::nullopt;
    const char* faceData = data + vertices * layout->stride;
    if (!expected) mesh.triangles.reserve(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        Triangle t;
        if (!readTriangle(faceData + f * kFaceRecord, vertices, t)) return std::nullopt;
        if (!expected)
            mesh.triangles.push_back(t);
        else if (t != (*expected)[f])
            return std::nullopt;
    }
    return mesh;
}

} // namespace vl::meshio
