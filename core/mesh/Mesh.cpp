#include "core/mesh/Mesh.h"

#include "core/common/Error.h"

#include <algorithm>
#include <string>

namespace vl {

TriMesh toTriMesh(const MeshData& data, std::string_view where) {
    TriMesh mesh;
    const bool withUV = data.hasUVs();
    if (withUV) mesh.request_vertex_texcoords2D();
    mesh.reserve(data.positions.size(), data.triangles.size() * 3 / 2 + 3, data.triangles.size());
    for (std::size_t i = 0; i < data.positions.size(); ++i) {
        const auto vh = mesh.add_vertex(data.positions[i]);
        if (withUV) mesh.set_texcoord2D(vh, data.uvs[i]);
    }
    const auto n = static_cast<std::uint32_t>(data.positions.size());
    for (std::size_t f = 0; f < data.triangles.size(); ++f) {
        const auto& t = data.triangles[f];
        if (t[0] >= n || t[1] >= n || t[2] >= n)
            throwInputError(where, "triangle " + std::to_string(f) + " has a vertex index out of range");
        const auto fh =
            mesh.add_face(mesh.vertex_handle(t[0]), mesh.vertex_handle(t[1]), mesh.vertex_handle(t[2]));
        if (!fh.is_valid())
            throwInputError(where, "triangle " + std::to_string(f) +
                                       " is degenerate or makes the mesh non-manifold");
    }
    return mesh;
}

MeshData toMeshData(const TriMesh& mesh) {
    MeshData data;
    data.positions.reserve(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) data.positions.push_back(mesh.point(vh));
    if (mesh.has_vertex_texcoords2D()) {
        data.uvs.reserve(mesh.n_vertices());
        for (const auto vh : mesh.vertices()) data.uvs.push_back(mesh.texcoord2D(vh));
    }
    data.triangles.reserve(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        if (mesh.status(fh).deleted()) continue;
        Triangle t{};
        int k = 0;
        for (const auto vh : mesh.fv_range(fh)) t[k++] = static_cast<std::uint32_t>(vh.idx());
        data.triangles.push_back(t);
    }
    return data;
}

std::vector<double> vertexAreas(std::span<const Vec3> positions, std::span<const Triangle> triangles) {
    std::vector<double> area(positions.size(), 0.0);
    for (const auto& t : triangles) {
        const Vec3 e1 = positions[t[1]] - positions[t[0]];
        const Vec3 e2 = positions[t[2]] - positions[t[0]];
        const double a = 0.5 * OpenMesh::cross(e1, e2).norm();
        for (const auto v : t) area[v] += a;
    }
    return area;
}

std::vector<Vec3> vertexNormals(std::span<const Vec3> positions, std::span<const Triangle> triangles) {
    std::vector<Vec3> normal(positions.size(), Vec3(0, 0, 0));
    for (const auto& t : triangles) {
        // The unnormalised cross product weights each face normal by twice its area.
        const Vec3 n = OpenMesh::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        for (const auto v : t) normal[v] += n;
    }
    for (auto& n : normal) {
        const double len = n.norm();
        if (len > 0) n /= len;
    }
    return normal;
}

bool bounds(std::span<const Vec3> positions, Vec3& lo, Vec3& hi) {
    if (positions.empty()) return false;
    lo = hi = positions[0];
    for (const auto& p : positions) {
        lo.minimize(p);
        hi.maximize(p);
    }
    return true;
}

} // namespace vl
