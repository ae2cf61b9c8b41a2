#pragma once
// The mesh type of VisemeLab: an OpenMesh half-edge triangle mesh in double precision, with
// per-vertex (u,v) when the source has them. Vertex order is the file's order: interpolable viseme
// sets depend on it, so nothing in the core may reorder, split or merge vertices.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace vl {

struct MeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    using TexCoord2D = OpenMesh::Vec2d;
    VertexAttributes(OpenMesh::Attributes::Status);
    FaceAttributes(OpenMesh::Attributes::Status);
    EdgeAttributes(OpenMesh::Attributes::Status);
    HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Vec3 = OpenMesh::Vec3d;
using Vec2 = OpenMesh::Vec2d;
using Triangle = std::array<std::uint32_t, 3>;

// Plain arrays describing a triangle mesh: what the readers produce and the writers consume.
// Kept separate from TriMesh so file I/O and the reduction run on tight arrays, while topology
// queries (areas, normals, adaptive refinement) use the half-edge TriMesh.
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec2> uvs; // empty, or one per vertex
    std::vector<Triangle> triangles;

    std::size_t vertexCount() const { return positions.size(); }
    bool hasUVs() const { return !uvs.empty(); }
    bool operator==(const MeshData&) const = default;
};

// Builds a half-edge mesh with the same vertex order; throws InputError (naming `where` and the
// face) for out-of-range indices or faces OpenMesh rejects as non-manifold.
TriMesh toTriMesh(const MeshData& data, std::string_view where = "mesh");
MeshData toMeshData(const TriMesh& mesh);

// Per-vertex sum of the areas of incident triangles (the paper's S(v), weight mode "area").
std::vector<double> vertexAreas(std::span<const Vec3> positions, std::span<const Triangle> triangles);

// Area-weighted vertex normals, normalised (zero vectors stay zero for isolated vertices).
std::vector<Vec3> vertexNormals(std::span<const Vec3> positions, std::span<const Triangle> triangles);

// Axis-aligned bounds; returns false for an empty list.
bool bounds(std::span<const Vec3> positions, Vec3& lo, Vec3& hi);

} // namespace vl
