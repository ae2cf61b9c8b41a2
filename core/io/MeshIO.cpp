// Format dispatch by file extension, file reading and atomic writing.
#include "core/io/MeshIO.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/MeshIOSupport.h"
#include "core/io/PlyFastPath.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>
#include <optional>

namespace vl {

namespace {

std::optional<MeshFormat> formatOfExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".wrl" || ext == ".vrml") return MeshFormat::Vrml;
    return std::nullopt;
}

} // namespace

MeshFormat meshFormatFromPath(const std::filesystem::path& path) {
    if (const auto format = formatOfExtension(path)) return *format;
    throwInputError(path.string(), "unknown mesh format '" + path.extension().string() +
                                       "' (expected .obj, .ply, .wrl or .vrml)");
}

bool isMeshFile(const std::filesystem::path& path) {
    return formatOfExtension(path).has_value();
}

namespace {

MeshData readMeshFile(const std::filesystem::path& path, CornerTexCoords* corners) {
    const MeshFormat format = meshFormatFromPath(path);
    const FileBytes file = readFileBytes(path); // not zero-filled first
    const std::string_view bytes = file.view();
    const std::string source = path.string();
    try {
        switch (format) {
        case MeshFormat::Obj:
            return corners ? parseObj(bytes, source, *corners) : parseObj(bytes, source);
        case MeshFormat::Ply: {
            MeshData mesh = parsePly(bytes, source);
            if (corners && mesh.hasUVs()) *corners = {mesh.uvs, mesh.triangles};
            return mesh;
        }
        case MeshFormat::Vrml:
            return corners ? parseVrml(bytes, source, *corners) : parseVrml(bytes, source);
        }
    } catch (const std::bad_alloc&) {
        // Memory grows linearly with the file's size; a machine short of it still gets the file's name.
        throwInputError(source,
                        "not enough memory to read this mesh (" + std::to_string(bytes.size()) + " bytes)");
    }
    throwInputError(source, "unknown mesh format");
}

} // namespace

MeshData readMesh(const std::filesystem::path& path) {
    return readMeshFile(path, nullptr);
}

MeshData readMesh(const std::filesystem::path& path, CornerTexCoords& corners) {
    corners = {};
    return readMeshFile(path, &corners);
}

ReferenceMesh readReferenceMesh(const std::filesystem::path& path) {
    if (meshFormatFromPath(path) != MeshFormat::Obj) return {readMesh(path), {}};
    const std::string bytes = readFileToString(path);
    try {
        ReferenceMesh reference{parseObj(bytes, path.string()), {}};
        reference.objStructure = objStructure(bytes);
        return reference;
    } catch (const std::bad_alloc&) {
        throwInputError(path.string(),
                        "not enough memory to read this mesh (" + std::to_string(bytes.size()) + " bytes)");
    }
}

namespace {

// A binary PLY viseme of its neutral's layout: its positions, its faces compared and dropped.
std::optional<MeshLike> readPlyPositionsLike(const std::filesystem::path& path,
                                             const ReferenceMesh& reference) {
    if (!reference.mesh.uvs.empty()) return std::nullopt; // the fast path reads no (u,v)
    const FileBytes file = readFileBytes(path);
    const std::string_view bytes = file.view();
    try {
        if (auto positions =
                meshio::parsePlyPositionsMatching(bytes, path.string(), reference.mesh.triangles))
            return MeshLike{{std::move(*positions), {}, {}}, true};
        return MeshLike{parsePly(bytes, path.string())};
    } catch (const std::bad_alloc&) {
        throwInputError(path.string(),
                        "not enough memory to read this mesh (" + std::to_string(bytes.size()) + " bytes)");
    }
}

} // namespace

MeshLike readPositionsLike(const std::filesystem::path& path, const ReferenceMesh& reference) {
    if (meshFormatFromPath(path) == MeshFormat::Ply)
        if (auto read = readPlyPositionsLike(path, reference)) return std::move(*read);
    if (reference.objStructure.empty() || meshFormatFromPath(path) != MeshFormat::Obj)
        return {readMesh(path)};
    const std::string bytes = readFileToString(path);
    const std::string source = path.string();
    try {
        if (auto positions = parseObjPositionsMatching(bytes, source, reference.objStructure))
            return {{std::move(*positions), {}, {}}, true};
        return {parseObj(bytes, source)};
    } catch (const std::bad_alloc&) {
        throwInputError(source,
                        "not enough memory to read this mesh (" + std::to_string(bytes.size()) + " bytes)");
    }
}

MeshData readMeshLike(const std::filesystem::path& path, const ReferenceMesh& reference) {
    MeshLike read = readPositionsLike(path, reference);
    if (read.sameTopology) {
        read.mesh.triangles = reference.mesh.triangles;
        read.mesh.uvs = reference.mesh.uvs;
    }
    return std::move(read.mesh);
}

std::string formatMesh(const std::filesystem::path& path, const MeshData& mesh, PositionPrecision precision) {
    const MeshFormat format = meshFormatFromPath(path);
    meshio::requireWritable(mesh, precision);
    switch (format) {
    case MeshFormat::Obj:
        return meshio::joinAroundPositions(meshio::objTextAroundPositions(mesh),
                                           PositionText(mesh.positions, precision),
                                           meshio::appendObjPositions);
    case MeshFormat::Ply:
        if (precision == PositionPrecision::Exact) return formatPly(mesh);
        return formatPly({PositionText(mesh.positions, precision).values(), mesh.uvs, mesh.triangles});
    case MeshFormat::Vrml:
        return meshio::joinAroundPositions(meshio::vrmlTextAroundPositions(mesh),
                                           PositionText(mesh.positions, precision),
                                           meshio::appendVrmlPositions);
    }
    throwInputError(path.string(), "unknown mesh format");
}

PositionText::PositionText(std::span<const Vec3> positions, PositionPrecision precision,
                           const PositionText* reference) {
    assign(positions, precision, reference);
}

namespace {

// Copies of a few bytes (a coordinate, a vertex line) as one fixed-size move instead of a call to
// memmove per piece: both buffers keep kCopySlack bytes past any piece's end, so reading and writing
// those extra bytes stays inside them (what is written past the piece is overwritten next, or cut).
constexpr std::size_t kCopySlack = 32;

char* copyPiece(char* to, const char* from, std::size_t length) {
    if (length <= kCopySlack)
        std::memcpy(to, from, kCopySlack);
    else
        std::memcpy(to, from, length);
    return to + length;
}

} // namespace

void PositionText::assign(std::span<const Vec3> positions, PositionPrecision precision,
                          const PositionText* reference) {
    meshio::requireWritablePositions(positions, precision);
    if (reference && (reference == this || reference->precision_ != precision ||
                      reference->vertexCount() != positions.size()))
        reference = nullptr;
    precision_ = precision;
    // Written through a pointer into text_, which only grows (a buffer reused for every key is not
    // cleared again): at most 24 characters (the longest shortest double) and a separator each, and
    // the slack of copyPiece.
    constexpr std::size_t kMaxCoordinate = 25;
    const std::size_t count = 3 * positions.size();
    if (text_.size() < count * kMaxCoordinate + kCopySlack) text_.resize(count * kMaxCoordinate + kCopySlack);
    ends_.resize(count);
    bits_.resize(count);
    char* const begin = text_.data();
    char* at = begin;
    for (std::size_t i = 0, c = 0; i < positions.size(); ++i)
        for (int k = 0; k < 3; ++k, ++c) {
            const double x = positions[i][k];
            const auto f = static_cast<float>(x);
            const std::uint64_t bits = precision == PositionPrecision::Float32
                                           ? std::bit_cast<std::uint32_t>(f)
                                           : std::bit_cast<std::uint64_t>(x);
            if (k > 0) *at++ = ' ';
            if (reference && reference->bits_[c] == bits) {
                const std::size_t from = reference->start(c);
                at = copyPiece(at, reference->text_.data() + from, reference->ends_[c] - from);
            } else {
                at = precision == PositionPrecision::Float32 ? std::to_chars(at, at + 24, f).ptr
                                                             : std::to_chars(at, at + 24, x).ptr;
            }
            ends_[c] = static_cast<std::size_t>(at - begin);
            bits_[c] = bits;
        }
}

void PositionText::appendLines(std::string& out, std::string_view prefix, std::string_view separator,
                               std::string_view last) const {
    const std::size_t vertices = vertexCount();
    if (vertices == 0) return;
    const std::size_t from = out.size();
    const std::size_t size =
        ends_.back() + vertices * (prefix.size() + separator.size()) - separator.size() + last.size();
    out.resize(from + size + kCopySlack);
    char* at = out.data() + from;
    // Between two vertices: the separator, then the next line's prefix, as one padded piece.
    char joint[kCopySlack] = {};
    const bool smallJoint = separator.size() + prefix.size() <= kCopySlack;
    if (smallJoint) {
        std::memcpy(joint, separator.data(), separator.size());
        std::memcpy(joint + separator.size(), prefix.data(), prefix.size());
    }
    at = std::copy(prefix.begin(), prefix.end(), at);
    for (std::size_t i = 0; i < vertices; ++i) {
        const std::size_t begin = start(3 * i);
        at = copyPiece(at, text_.data() + begin, ends_[3 * i + 2] - begin);
        if (i + 1 == vertices) break;
        if (smallJoint) {
            at = copyPiece(at, joint, separator.size() + prefix.size());
        } else {
            at = std::copy(separator.begin(), separator.end(), at);
            at = std::copy(prefix.begin(), prefix.end(), at);
        }
    }
    at = std::copy(last.begin(), last.end(), at);
    out.resize(from + size);
}

std::string_view PositionText::vertex(std::size_t i) const {
    const std::size_t from = start(3 * i);
    return std::string_view(text_).substr(from, ends_[3 * i + 2] - from);
}

std::string_view PositionText::coordinate(std::size_t i, int axis) const {
    const std::size_t c = 3 * i + static_cast<std::size_t>(axis);
    return std::string_view(text_).substr(start(c), ends_[c] - start(c));
}

std::vector<Vec3> PositionText::values() const {
    std::vector<Vec3> positions(vertexCount());
    for (std::size_t c = 0; c < bits_.size(); ++c)
        positions[c / 3][static_cast<int>(c % 3)] =
            precision_ == PositionPrecision::Float32
                ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits_[c])))
                : std::bit_cast<double>(bits_[c]);
    return positions;
}

MeshTextFormatter::MeshTextFormatter(const std::filesystem::path& path, const MeshData& topology,
                                     PositionPrecision precision)
    : format_(meshFormatFromPath(path)), precision_(precision), vertexCount_(topology.positions.size()) {
    meshio::requireWritable(topology); // (u,v) and triangles; format() checks the positions it gets
    if (format_ == MeshFormat::Ply) {  // binary, and as fast as copying: keeps the topology
        plyTopology_ = {{}, topology.uvs, topology.triangles};
        return;
    }
    meshio::TextAroundPositions parts = format_ == MeshFormat::Obj
                                            ? meshio::objTextAroundPositions(topology)
                                            : meshio::vrmlTextAroundPositions(topology);
    head_ = std::move(parts.head);
    tail_ = std::move(parts.tail);
}

std::string MeshTextFormatter::format(std::span<const Vec3> positions) const {
    std::string out;
    format(positions, out);
    return out;
}

void MeshTextFormatter::format(std::span<const Vec3> positions, std::string& out) const {
    if (positions.size() != vertexCount_)
        throw std::invalid_argument("MeshTextFormatter: " + std::to_string(positions.size()) +
                                    " positions for a topology of " + std::to_string(vertexCount_));
    format(PositionText(positions, precision_), out);
}

void MeshTextFormatter::format(const PositionText& positions, std::string& out) const {
    requireFormatOf(positions);
    if (format_ == MeshFormat::Ply) { // binary: the values the text stands for
        out = formatPly({positions.values(), plyTopology_.uvs, plyTopology_.triangles});
        return;
    }
    out.clear();
    out.reserve(head_.size() + positions.vertexCount() * 70 + tail_.size());
    out += head_;
    appendPositions(out, positions);
    out += tail_;
}

MeshTextFormatter::Parts MeshTextFormatter::parts(const PositionText& positions, std::string& buffer) const {
    if (format_ == MeshFormat::Ply) {
        format(positions, buffer);
        return {{}, buffer, {}};
    }
    requireFormatOf(positions);
    buffer.clear();
    appendPositions(buffer, positions);
    return {head_, buffer, tail_};
}

void MeshTextFormatter::appendPositions(std::string& out, const PositionText& positions) const {
    if (format_ == MeshFormat::Obj)
        meshio::appendObjPositions(out, positions);
    else
        meshio::appendVrmlPositions(out, positions);
}

void MeshTextFormatter::requireFormatOf(const PositionText& positions) const {
    if (positions.vertexCount() != vertexCount_ || positions.precision() != precision_)
        throw std::invalid_argument("MeshTextFormatter: " + std::to_string(positions.vertexCount()) +
                                    " positions of another precision or for a topology of " +
                                    std::to_string(vertexCount_));
}

void writeMesh(const std::filesystem::path& path, const MeshData& mesh) {
    writeFileAtomically(path, formatMesh(path, mesh));
}

} // namespace vl
