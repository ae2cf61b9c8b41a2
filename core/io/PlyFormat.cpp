// Stanford PLY reader (ASCII, binary little- and big-endian) and binary little-endian writer.
// The data section is walked once per element; the ASCII and binary readers share that walk and
// differ only in how one value is read, skipped and located in error messages.
#include "core/common/Error.h"
#include "core/io/MeshIO.h"
#include "core/io/MeshIOSupport.h"
#include "core/io/PlyFastPath.h"
#include "core/io/PlyHeader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <limits>

namespace vl {

using meshio::PlyElement;
using meshio::PlyEncoding;
using meshio::PlyHeader;
using meshio::PlyType;

namespace {

// Where the walk is, for error messages: "face 12" (elements counted from 0).
struct Location {
    const std::string* element = nullptr;
    std::size_t index = 0;
    std::string describe() const { return *element + " " + std::to_string(index); }
};

class AsciiPlyReader {
  public:
    AsciiPlyReader(std::string_view bytes, const PlyHeader& header, std::string_view source)
        : bytes_(bytes), pos_(header.dataOffset), line_(header.dataLine), lastTokenLine_(header.dataLine),
          source_(source) {}

    Location at;

    std::string where() const { return fileLine(source_, line_) + ": " + at.describe(); }

    double readReal(PlyType type) {
        const std::string_view token = next();
        if (meshio::isPlyIntegerType(type))
            return static_cast<double>(meshio::toInteger(token, [this] { return where(); }));
        return meshio::toFiniteDouble(token, [this] { return where(); });
    }
    std::int64_t readInteger(PlyType) {
        return meshio::toInteger(next(), [this] { return where(); });
    }
    void skip(PlyType) { next(); }

    void requireEnd() {
        skipSpace();
        if (pos_ < bytes_.size())
            throwInputError(fileLine(source_, line_), "unexpected data after the last PLY element");
    }

  private:
    void skipSpace() {
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
            if (bytes_[pos_] == '\n') ++line_;
            ++pos_;
        }
    }
    std::string_view next() {
        skipSpace();
        if (pos_ >= bytes_.size()) {
            line_ = lastTokenLine_; // the line where the data stopped, not the empty one after it
            throwInputError(where(), "data ends early (file truncated?)");
        }
        const std::size_t start = pos_;
        lastTokenLine_ = line_;
        while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
        return bytes_.substr(start, pos_ - start);
    }

    std::string_view bytes_;
    std::size_t pos_;
    std::size_t line_;
    std::size_t lastTokenLine_;
    std::string_view source_;
};

class BinaryPlyReader {
  public:
    BinaryPlyReader(std::string_view bytes, const PlyHeader& header, std::string_view source)
        : pos_(bytes.data() + header.dataOffset), end_(bytes.data() + bytes.size()), source_(source),
          swap_((header.encoding == PlyEncoding::BinaryBigEndian) !=
                (std::endian::native == std::endian::big)) {}

    Location at;

    std::string where() const { return std::string(source_) + ": " + at.describe(); }

    double readReal(PlyType type) {
        switch (type) {
        case PlyType::Float32:
            return static_cast<double>(read<float>());
        case PlyType::Float64:
            return read<double>();
        default:
            return static_cast<double>(readInteger(type));
        }
    }
    std::int64_t readInteger(PlyType type) {
        switch (type) {
        case PlyType::Int8:
            return read<std::int8_t>();
        case PlyType::UInt8:
            return read<std::uint8_t>();
        case PlyType::Int16:
            return read<std::int16_t>();
        case PlyType::UInt16:
            return read<std::uint16_t>();
        case PlyType::Int32:
            return read<std::int32_t>();
        case PlyType::UInt32:
            return read<std::uint32_t>();
        default:
            throwInputError(where(), "expected an integer property"); // excluded by the walk
        }
    }
    void skip(PlyType type) { advance(meshio::plyTypeSize(type)); }
    void requireEnd() const {} // bytes after the last element are ignored, as other readers do

  private:
    const char* advance(std::size_t size) {
        if (static_cast<std::size_t>(end_ - pos_) < size)
            throwInputError(where(), "binary data ends early (file truncated?)");
        const char* start = pos_;
        pos_ += size;
        return start;
    }
    template <class T> T read() {
        char raw[sizeof(T)];
        std::memcpy(raw, advance(sizeof(T)), sizeof(T));
        if (swap_) std::reverse(raw, raw + sizeof(T));
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return value;
    }

    const char* pos_;
    const char* end_;
    std::string_view source_;
    bool swap_;
};

enum class Role { Skip, X, Y, Z, U, V, Indices };

// What each property of `element` feeds; throws for a vertex element without x/y/z or a face
// element without an integer vertex index list.
std::vector<Role> rolesOf(const PlyElement& element, std::string_view source) {
    std::vector<Role> roles(element.properties.size(), Role::Skip);
    const std::string where = fileLine(source, element.line);
    const auto assign = [&](std::string_view name, Role role, bool list) {
        const int i = element.find(name);
        if (i < 0) return false;
        const auto& property = element.properties[static_cast<std::size_t>(i)];
        if (property.isList != list)
            throwInputError(where, "property '" + std::string(name) +
                                       (list ? "' must be a list" : "' must not be a list"));
        if (list && !meshio::isPlyIntegerType(property.type))
            throwInputError(where, "property '" + std::string(name) + "' must list integers");
        roles[static_cast<std::size_t>(i)] = role;
        return true;
    };
    if (element.name == "vertex") {
        for (const auto& [name, role] : {std::pair{"x", Role::X}, {"y", Role::Y}, {"z", Role::Z}})
            if (!assign(name, role, false))
                throwInputError(where, std::string("vertex element has no '") + name + "' property");
        for (const auto& [u, v] :
             {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}})
            if (element.find(u) >= 0 && element.find(v) >= 0 && assign(u, Role::U, false) &&
                assign(v, Role::V, false))
                break;
    } else if (element.name == "face") {
        if (!assign("vertex_indices", Role::Indices, true) && !assign("vertex_index", Role::Indices, true))
            throwInputError(where, "face element has no 'vertex_indices' list");
    }
    return roles;
}

// Whether the element counts the header declares fit in the bytes that follow it: an element takes
// at least one byte per value plus a separator in ASCII, and the sizes of its scalars and list
// lengths in binary. Only counts that fit are used to reserve memory; the others are reported by
// the walk where the data runs out, so a few bytes never allocate gigabytes.
bool countsFitData(const PlyHeader& header, std::size_t dataBytes) {
    const bool ascii = header.encoding == PlyEncoding::Ascii;
    const std::uint64_t available = dataBytes + (ascii ? 1 : 0); // the last ASCII value needs no separator
    std::uint64_t needed = 0;
    for (const auto& element : header.elements) {
        std::uint64_t perElement = 0;
        for (const auto& property : element.properties)
            perElement +=
                ascii ? 2 : meshio::plyTypeSize(property.isList ? property.countType : property.type);
        if (perElement == 0 || element.count == 0) continue;
        if (element.count > (available - needed) / perElement) return false;
        needed += element.count * perElement;
    }
    return true;
}

template <class Reader>
MeshData readData(Reader& reader, const PlyHeader& header, std::size_t dataBytes, std::string_view source) {
    MeshData mesh;
    const std::size_t vertexCount = header.find("vertex")->count;
    if (countsFitData(header, dataBytes)) mesh.positions.reserve(vertexCount);
    std::vector<std::uint32_t> corners;
    std::size_t faceIndex = 0;
    for (const auto& element : header.elements) {
        const std::vector<Role> roles = rolesOf(element, source);
        if (roles.empty()) continue; // no properties, no data, however large the count
        reader.at = {&element.name, 0};
        const bool hasUV = std::find(roles.begin(), roles.end(), Role::U) != roles.end();
        for (std::size_t i = 0; i < element.count; ++i) {
            reader.at.index = i;
            Vec3 p(0.0, 0.0, 0.0);
            Vec2 uv(0.0, 0.0);
            corners.clear();
            for (std::size_t k = 0; k < roles.size(); ++k) {
                const auto& property = element.properties[k];
                if (property.isList) {
                    const std::int64_t n = reader.readInteger(property.countType);
                    if (n < 0) throwInputError(reader.where(), "negative list length " + std::to_string(n));
                    for (std::int64_t j = 0; j < n; ++j) {
                        if (roles[k] != Role::Indices) {
                            reader.skip(property.type);
                            continue;
                        }
                        const std::int64_t v = reader.readInteger(property.type);
                        if (v < 0)
                            throwInputError(reader.where(), "negative vertex index " + std::to_string(v));
                        if (static_cast<std::uint64_t>(v) >= vertexCount)
                            throwInputError(reader.where(), "vertex index " + std::to_string(v) +
                                                                " out of range (" +
                                                                std::to_string(vertexCount) + " vertices)");
                        corners.push_back(static_cast<std::uint32_t>(v));
                    }
                    continue;
                }
                const Role role = roles[k];
                if (role == Role::Skip) {
                    reader.skip(property.type);
                    continue;
                }
                const double value = reader.readReal(property.type);
                if (!std::isfinite(value))
                    throwInputError(reader.where(),
                                    "non-finite value (NaN or Inf) for '" + property.name + "'");
                if (role == Role::U || role == Role::V)
                    uv[role == Role::U ? 0 : 1] = value;
                else
                    p[static_cast<int>(role) - static_cast<int>(Role::X)] = value;
            }
            if (element.name == "vertex") {
                mesh.positions.push_back(p);
                if (hasUV) mesh.uvs.push_back(uv);
            } else if (element.name == "face") {
                const std::string problem = meshio::appendPolygonFan(corners, faceIndex++, 0, mesh.triangles);
                if (!problem.empty()) throwInputError(reader.where(), problem);
            }
        }
    }
    reader.requireEnd();
    return mesh;
}

template <class T> void appendBinary(std::string& out, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
    out.append(raw, sizeof(T));
}

} // namespace

MeshData parsePly(std::string_view bytes, std::string_view source) {
    meshio::requireNotBlank(bytes, source);
    const PlyHeader header = meshio::parsePlyHeader(bytes, source);
    const PlyElement* vertices = header.find("vertex");
    const PlyElement* faces = header.find("face");
    if (!vertices || vertices->count == 0) throwInputError(source, "no vertices");
    if (!faces || faces->count == 0) throwInputError(source, "no faces");
    if (auto fast = meshio::readPlyFast(bytes, header)) return std::move(*fast);
    MeshData mesh;
    if (header.encoding == PlyEncoding::Ascii) {
        AsciiPlyReader reader(bytes, header, source);
        mesh = readData(reader, header, bytes.size() - header.dataOffset, source);
    } else {
        BinaryPlyReader reader(bytes, header, source);
        mesh = readData(reader, header, bytes.size() - header.dataOffset, source);
    }
    meshio::requireVerticesAndFaces(mesh, source);
    return mesh;
}

std::optional<std::vector<Vec3>> meshio::parsePlyPositionsMatching(std::string_view bytes,
                                                                   std::string_view source,
                                                                   const std::vector<Triangle>& triangles) {
    meshio::requireNotBlank(bytes, source);
    auto fast = meshio::readPlyFast(bytes, meshio::parsePlyHeader(bytes, source), &triangles);
    if (!fast) return std::nullopt;
    return std::move(fast->positions);
}

std::string formatPly(const MeshData& mesh) {
    meshio::requireWritable(mesh);
    if (mesh.positions.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throwInputError("mesh to write", "too many vertices for PLY int indices");
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment VisemeLab mesh\nelement vertex " +
                      std::to_string(mesh.positions.size()) +
                      "\nproperty double x\nproperty double y\nproperty double z\n";
    if (mesh.hasUVs()) out += "property double u\nproperty double v\n";
    out += "element face " + std::to_string(mesh.triangles.size()) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
    out.reserve(out.size() + mesh.positions.size() * 40 + mesh.triangles.size() * 13);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) appendBinary(out, mesh.positions[i][k]);
        if (mesh.hasUVs()) {
            appendBinary(out, mesh.uvs[i][0]);
            appendBinary(out, mesh.uvs[i][1]);
        }
    }
    for (const auto& t : mesh.triangles) {
        appendBinary(out, std::uint8_t{3});
        for (const auto v : t) appendBinary(out, static_cast<std::int32_t>(v));
    }
    return out;
}

} // namespace vl
