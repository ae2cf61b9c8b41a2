#pragma once
// Binary PLY files of many meshes of one topology (the key meshes of a large reduction): positions as
// float32 (what every consumer of key meshes stores; PositionPrecision::Float32), (u,v) as float64
// (exact), little-endian, faces as uchar/int lists. The header and the faces are formatted once; a
// key adds only its positions' bytes, copied without text formatting: 12 bytes a vertex against about
// 60 as OBJ + VRML text. parsePly reads the file back to the same float32 positions and exact faces.
#include "core/mesh/Mesh.h"

#include <span>
#include <string>
#include <string_view>

namespace vl {

class PlyKeyWriter {
  public:
    explicit PlyKeyWriter(const MeshData& topology);
    // The topology alone: `vertexCount` vertices (the neutral's positions need not be held).
    PlyKeyWriter(std::size_t vertexCount, std::span<const Triangle> triangles, std::span<const Vec2> uvs);
    // The file is head() + the bytes `positions` leaves in `buffer` + faces(). Throws InputError
    // "mesh to write: ..." for a non-finite position or one beyond float32's range, or a vertex count
    // other than the topology's.
    std::string_view head() const { return head_; }
    std::string_view faces() const { return faces_; }
    std::string_view positions(std::span<const Vec3> positions, std::string& buffer) const;
    // The same from float32 x, y, z (3 per vertex), copied as they are (keys merged by mergeKeyInto).
    std::string_view positions(std::span<const float> xyz, std::string& buffer) const;

  private:
    std::size_t vertexCount_;
    std::vector<Vec2> uvs_;
    std::string head_, faces_;
};

} // namespace vl
