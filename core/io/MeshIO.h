#pragma once
// Reading and writing meshes in formats other tools read: Wavefront OBJ, Stanford PLY (ASCII and
// binary little-endian) and VRML97 IndexedFaceSet. Every reader keeps the file's vertex order
// exactly, triangulates polygons as a fan from their first corner (the same way for every member
// of a viseme set), and rejects bad input with an InputError naming the file and line/element.
#include "core/mesh/Mesh.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

enum class MeshFormat { Obj, Ply, Vrml };

// Chooses the format from the extension (.obj, .ply, .wrl/.vrml); throws InputError otherwise.
MeshFormat meshFormatFromPath(const std::filesystem::path& path);
bool isMeshFile(const std::filesystem::path& path);

// Reads any supported format; the result has at least one vertex and one triangle.
MeshData readMesh(const std::filesystem::path& path);
// Writes atomically (temp file + rename) in the format of the extension.
void writeMesh(const std::filesystem::path& path, const MeshData& mesh);

// Format-level entry points on in-memory text; `source` names the file in error messages.
MeshData parseObj(std::string_view text, std::string_view source);
std::string formatObj(const MeshData& mesh);
MeshData parsePly(std::string_view bytes, std::string_view source);
std::string formatPly(const MeshData& mesh); // binary little-endian, float64: bit-exact round trip
MeshData parseVrml(std::string_view text, std::string_view source);
std::string formatVrml(const MeshData& mesh);

} // namespace vl
