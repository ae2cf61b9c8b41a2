#pragma once
// A mesh prepared for painting: per-vertex normals and edge neighbours, computed once per mesh and
// shared by every dab, fill and selection (the editor rebuilds it only when the mesh changes).
// Positions and triangles are copied, so the surface stays valid whatever happens to its source.
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl {

class PaintSurface {
  public:
    PaintSurface() = default;
    // Throws InputError when a triangle names a vertex past the end of `positions`.
    PaintSurface(std::span<const Vec3> positions, std::span<const Triangle> triangles);

    std::size_t vertexCount() const { return positions_.size(); }
    const std::vector<Vec3>& positions() const { return positions_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    // Area-weighted unit normals (zero for isolated vertices), oriented like the triangles' winding.
    const std::vector<Vec3>& normals() const { return normals_; }
    // The vertices sharing an edge with `v`, each listed once, increasing.
    std::span<const std::uint32_t> neighbours(std::uint32_t v) const {
        return {neighbours_.data() + offsets_[v], neighbours_.data() + offsets_[v + 1]};
    }
    // The largest side of the bounding box: the "head size" brush radii are given in % of.
    double size() const { return size_; }
    // The plane x = mirrorX halves the bounding box (left/right symmetry of a face).
    double mirrorX() const { return mirrorX_; }
    // The vertex nearest to `point` (Euclidean; the lowest index on ties). The surface must not be empty.
    std::uint32_t nearestVertex(const Vec3& point) const;

  private:
    std::vector<Vec3> positions_;
    std::vector<Triangle> triangles_;
    std::vector<Vec3> normals_;
    std::vector<std::uint32_t> offsets_{0}; // CSR: neighbours of v are [offsets_[v], offsets_[v + 1])
    std::vector<std::uint32_t> neighbours_;
    double size_ = 0.0;
    double mirrorX_ = 0.0;
};

} // namespace vl
