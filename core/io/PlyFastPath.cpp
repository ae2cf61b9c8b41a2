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

// The file's data when it has the bulk layout: counts checked against the bytes.
struct FastPly {
    VertexLayout layout;
    std::size_t vertices = 0, faces = 0;
    const char* data = nullptr; // the vertex records, then the face records
};

std::optional<FastPly> fastPly(std::string_view bytes, const PlyHeader& header) {
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
    return FastPly{*layout, vertices, faces, bytes.data() + header.dataOffset};
}

// Whether the file's faces are `expected`, each one a triangle the general reader would read as is.
bool facesEqual(const FastPly& ply, const std::vector<Triangle>& expected) {
    if (expected.size() != ply.faces) return false;
    const char* faceData = ply.data + ply.vertices * ply.layout.stride;
    if constexpr (std::endian::native == std::endian::little &&
                  sizeof(Triangle) == 3 * sizeof(std::int32_t)) {
        // The records' bytes against the expected triangles' (a count of 3, then the same three indices
        // in the same byte order): 13 bytes compared a face instead of decoded and range-checked. Equal
        // bytes are the same triangles, so the file's are valid exactly when the expected ones are.
        for (std::size_t f = 0; f < ply.faces; ++f) {
            const char* record = faceData + f * kFaceRecord;
            if (record[0] != 3 || std::memcmp(record + 1, expected[f].data(), sizeof(Triangle)) != 0)
                return false;
        }
        for (const Triangle& t : expected) // as readTriangle checks them
            if (t[0] >= ply.vertices || t[1] >= ply.vertices || t[2] >= ply.vertices || t[0] == t[1] ||
                t[1] == t[2] || t[0] == t[2] || t[0] > 0x7fffffffu || t[1] > 0x7fffffffu ||
                t[2] > 0x7fffffffu)
                return false;
        return true;
    }
    for (std::size_t f = 0; f < ply.faces; ++f) {
        Triangle t;
        if (!readTriangle(faceData + f * kFaceRecord, ply.vertices, t) || t != expected[f]) return false;
    }
    return true;
}

} // namespace

std::optional<MeshData> readPlyFast(std::string_view bytes, const PlyHeader& header,
                                    const std::vector<Triangle>* expected) {
    const auto ply = fastPly(bytes, header);
    if (!ply || (expected && !facesEqual(*ply, *expected))) return std::nullopt;
    MeshData mesh;
    if (!readVertices(ply->data, ply->vertices, ply->layout, mesh.positions)) return std::nullopt;
    if (expected) return mesh;
    const char* faceData = ply->data + ply->vertices * ply->layout.stride;
    mesh.triangles.reserve(ply->faces);
    for (std::size_t f = 0; f < ply->faces; ++f) {
        Triangle t;
        if (!readTriangle(faceData + f * kFaceRecord, ply->vertices, t)) return std::nullopt;
        mesh.triangles.push_back(t);
    }
    return mesh;
}

bool readPlyFloatsMatching(std::string_view bytes, const PlyHeader& header,
                           const std::vector<Triangle>& triangles, std::span<float> out) {
    const auto ply = fastPly(bytes, header);
    if (!ply || ply->vertices * 3 != out.size()) return false;
    const VertexLayout& layout = ply->layout;
    if (layout.isDouble[0] || layout.isDouble[1] || layout.isDouble[2]) return false; // would be rounded
    if (!facesEqual(*ply, triangles)) return false;
    if (layout.stride == 3 * sizeof(float) && layout.offset[0] == 0 && layout.offset[1] == 4 &&
        layout.offset[2] == 8) {
        std::memcpy(out.data(), ply->data, out.size() * sizeof(float)); // x y z records: one copy
    } else {
        for (std::size_t i = 0; i < ply->vertices; ++i)
            for (int axis = 0; axis < 3; ++axis)
                std::memcpy(&out[3 * i + static_cast<std::size_t>(axis)],
                            ply->data + i * layout.stride + layout.offset[axis], sizeof(float));
    }
    for (const float c : out)
        if (!std::isfinite(c)) return false; // the general reader names the vertex
    return true;
}

} // namespace vl::meshio
