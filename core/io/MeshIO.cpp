// Format dispatch by file extension, file reading and atomic writing.
#include "core/io/MeshIO.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/MeshIOSupport.h"

#include <algorithm>
#include <cctype>
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
    const std::string bytes = readFileToString(path);
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

MeshData readMeshLike(const std::filesystem::path& path, const ReferenceMesh& reference) {
    if (reference.objStructure.empty() || meshFormatFromPath(path) != MeshFormat::Obj) return readMesh(path);
    const std::string bytes = readFileToString(path);
    const std::string source = path.string();
    try {
        if (auto positions = parseObjPositionsMatching(bytes, source, reference.objStructure)) {
            MeshData mesh;
            mesh.positions = std::move(*positions);
            mesh.triangles = reference.mesh.triangles;
            mesh.uvs = reference.mesh.uvs;
            return mesh;
        }
        return parseObj(bytes, source);
    } catch (const std::bad_alloc&) {
        throwInputError(source,
                        "not enough memory to read this mesh (" + std::to_string(bytes.size()) + " bytes)");
    }
}

std::string formatMesh(const std::filesystem::path& path, const MeshData& mesh, PositionPrecision precision) {
    const MeshFormat format = meshFormatFromPath(path);
    if (precision == PositionPrecision::Exact) {
        switch (format) {
        case MeshFormat::Obj:
            return formatObj(mesh);
        case MeshFormat::Ply:
            return formatPly(mesh);
        case MeshFormat::Vrml:
            return formatVrml(mesh);
        }
    }
    meshio::requireWritable(mesh, precision);
    switch (format) {
    case MeshFormat::Obj:
        return meshio::joinAroundPositions(meshio::objTextAroundPositions(mesh), mesh.positions, precision,
                                           meshio::appendObjPositions);
    case MeshFormat::Ply: {
        MeshData rounded = mesh;
        for (Vec3& p : rounded.positions)
            for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(p[k]);
        return formatPly(rounded);
    }
    case MeshFormat::Vrml:
        return meshio::joinAroundPositions(meshio::vrmlTextAroundPositions(mesh), mesh.positions, precision,
                                           meshio::appendVrmlPositions);
    }
    throwInputError(path.string(), "unknown mesh format");
}

MeshTextFormatter::MeshTextFormatter(const std::filesystem::path& path, const MeshData& topology,
                                     PositionPrecision precision)
    : format_(meshFormatFromPath(path)), precision_(precision), topology_(topology) {
    meshio::requireWritable(topology_);     // (u,v) and triangles; format() checks the positions it gets
    if (format_ == MeshFormat::Ply) return; // binary, and as fast as copying
    meshio::TextAroundPositions parts = format_ == MeshFormat::Obj
                                            ? meshio::objTextAroundPositions(topology_)
                                            : meshio::vrmlTextAroundPositions(topology_);
    head_ = std::move(parts.head);
    tail_ = std::move(parts.tail);
}

std::string MeshTextFormatter::format(std::span<const Vec3> positions) const {
    std::string out;
    format(positions, out);
    return out;
}

void MeshTextFormatter::format(std::span<const Vec3> positions, std::string& out) const {
    if (positions.size() != topology_.positions.size())
        throw std::invalid_argument("MeshTextFormatter: " + std::to_string(positions.size()) +
                                    " positions for a topology of " +
                                    std::to_string(topology_.positions.size()));
    if (format_ == MeshFormat::Ply) {
        out =
            formatMesh("mesh.ply", {{positions.begin(), positions.end()}, topology_.uvs, topology_.triangles},
                       precision_);
        return;
    }
    meshio::requireWritablePositions(positions, precision_);
    out.clear();
    out.reserve(head_.size() + positions.size() * 70 + tail_.size());
    out += head_;
    if (format_ == MeshFormat::Obj)
        meshio::appendObjPositions(out, positions, precision_);
    else
        meshio::appendVrmlPositions(out, positions, precision_);
    out += tail_;
}

void writeMesh(const std::filesystem::path& path, const MeshData& mesh) {
    writeFileAtomically(path, formatMesh(path, mesh));
}

} // namespace vl
