// Format dispatch by file extension, file reading and atomic writing.
#include "core/io/MeshIO.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"

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

std::string formatMesh(const std::filesystem::path& path, const MeshData& mesh) {
    switch (meshFormatFromPath(path)) {
    case MeshFormat::Obj:
        return formatObj(mesh);
    case MeshFormat::Ply:
        return formatPly(mesh);
    case MeshFormat::Vrml:
        return formatVrml(mesh);
    }
    throwInputError(path.string(), "unknown mesh format");
}

void writeMesh(const std::filesystem::path& path, const MeshData& mesh) {
    writeFileAtomically(path, formatMesh(path, mesh));
}

} // namespace vl
