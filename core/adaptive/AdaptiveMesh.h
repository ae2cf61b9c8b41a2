#pragma once
// Dynamic adaptive mesh on OpenMesh's half-edge TriMesh (paper sections 4-5): a semi-regular binary
// multi-triangulation (RBMT) changed only by stellar edge splits and their inverse, edge welds.
// Only the current mesh is stored, with per-element data: vertex (u,v) (TriMesh texcoord2D) and
// level, face level, and on each face the mark of its refinement edge. Invariants (checked by
// checkAdaptiveMesh):
//  - every face has exactly one refinement edge; across it lies a face of the same level that marks
//    the same edge (together a basic block), the border (a single boundary block), or a face one level
//    coarser for which the edge is not the refinement edge (that face must be split first);
//  - adjacent faces differ by at most one level (a restricted quadtree);
//  - a face of level l >= 1 has the vertex opposite its refinement edge at level l (its newest vertex);
//  - every vertex position is the surface's sample at its (u,v).
// Levels count edge bisections: uniform refinement to depth D has (base faces) * 2^D faces.
#include "core/adaptive/RbmtBase.h"
#include "core/adaptive/Surface.h"
#include "core/adaptive/UvBox.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace vl {

class Criterion;

struct AdaptStats {
    std::size_t splits = 0; // edge splits, forced ones included
    std::size_t welds = 0;  // welds kept
    std::size_t tests = 0;  // refinement tests evaluated
    bool rebuilt = false;   // adapt() refined the base mesh again instead (a change reaching most of it)
};

class AdaptiveMesh {
  public:
    using FaceHandle = OpenMesh::FaceHandle;
    using VertexHandle = OpenMesh::VertexHandle;
    using EdgeHandle = OpenMesh::EdgeHandle;
    using HalfedgeHandle = OpenMesh::HalfedgeHandle;

    // Converts the surface's base domain to RBMT form (once) and samples every vertex. The surface
    // must outlive the mesh.
    explicit AdaptiveMesh(const Surface& surface, RbmtMethod method = RbmtMethod::Auto);

    const Surface& surface() const { return *surface_; }
    const TriMesh& mesh() const { return mesh_; }
    const RbmtBase& base() const { return base_; }

    Vec2 uv(VertexHandle v) const { return mesh_.texcoord2D(v); }
    const Vec3& position(VertexHandle v) const { return mesh_.point(v); }
    int level(VertexHandle v) const { return mesh_.property(vertexLevel_, v); }
    int level(FaceHandle f) const { return mesh_.property(faceLevel_, f); }
    bool isRefinementHalfedge(HalfedgeHandle h) const { return mesh_.property(refinementMark_, h); }
    // The halfedge of f on its refinement edge.
    HalfedgeHandle refinementHalfedge(FaceHandle f) const;
    // Live (non-deleted) element counts and the finest face level.
    std::size_t faceCount() const { return mesh_.n_faces() - deletedFaces_; }
    std::size_t vertexCount() const { return mesh_.n_vertices() - deletedVertices_; }
    int maxLevel() const;

    // --- Stellar operators -----------------------------------------------------------------
    // True when e is the internal edge of a basic block (both faces mark it and have the same level)
    // or a boundary edge that its face marks.
    bool isBlockEdge(EdgeHandle e) const;
    // Splits a block edge at its (u,v) midpoint; the new vertex is sampled. Returns it.
    // Throws std::logic_error when e is not a block edge.
    VertexHandle splitBlock(EdgeHandle e);
    // Interleaved refinement: splits f's refinement edge, first splitting the coarser neighbour
    // across it (recursively) when that edge is not yet a block edge. Returns the new vertex.
    VertexHandle refineFace(FaceHandle f);
    // True when v is the centre of an unsplit block split: level >= 1, degree 4 inside (3 on the
    // border), and every incident face has v as its newest vertex and v's level.
    bool canWeld(VertexHandle v) const;
    // Edge weld: removes v and restores the block it came from. Returns the two (one on the border)
    // restored faces. Throws std::logic_error when !canWeld(v). Leaves deleted elements behind until
    // collectGarbage().
    std::vector<FaceHandle> weld(VertexHandle v);

    // --- Adaptation ------------------------------------------------------------------------
    // Splits until no face of level < criterion.maxDepth() needs refinement.
    AdaptStats refine(const Criterion& criterion);
    // Welds, finest first and repeatedly, every vertex whose weld leaves no face of the neighbourhood
    // needing refinement (the criterion's simplification test). Collects garbage afterwards.
    AdaptStats simplify(const Criterion& criterion);
    // Re-adapts after a change of the surface or the thresholds: resample(), simplify(), refine().
    // `changed` is where in (u,v) the surface changed since the mesh was last adapted to `criterion`
    // (CascadeSurface::setParameters returns it; everywhere, the default, when unknown or after a
    // change of the thresholds: then all of the mesh is re-adapted). Given a box, only vertices, welds
    // and faces that meet it are resampled and tested; elsewhere the mesh stays as it was, so it may
    // keep splits that only the old shape forced. When the box holds more than half of the vertices,
    // the mesh is rebuilt from the base mesh instead (cheaper than re-adapting, and minimal).
    AdaptStats adapt(const Criterion& criterion, const UvBox& changed = UvBox::everywhere());
    // Re-samples every vertex position (call after the surface's parameters changed).
    void resample();
    // Compacts the OpenMesh arrays (invalidates handles held outside).
    void collectGarbage();

    // Live vertices (renumbered densely) with positions and (u,v), and triangles.
    MeshData toMeshData() const;

  private:
    static std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b);
    // The base mesh again (level 0 only), sampled.
    void buildFromBase();
    // refine() starting from the faces `start` (and those their splits change) only.
    AdaptStats refineFrom(const Criterion& criterion, const std::vector<FaceHandle>& start);
    // resample() of the vertices inside `region`.
    void resampleWithin(const UvBox& region);
    // simplify() over the vertices whose ring meets `region`.
    AdaptStats simplifyWithin(const Criterion& criterion, const UvBox& region);
    // The (u,v) bounding box of a face's or a vertex ring's corners meets `region`.
    bool faceMeets(FaceHandle f, const UvBox& region) const;
    bool ringMeets(VertexHandle v, const UvBox& region) const;
    VertexHandle refineFace(FaceHandle f, std::vector<VertexHandle>* created);
    // The endpoints of the edge whose split created v, when v can be welded.
    bool weldEndpoints(VertexHandle v, VertexHandle& a, VertexHandle& b) const;
    // Sets the level of `faces` and marks their edge a-b as the refinement edge.
    void markFaces(const std::vector<FaceHandle>& faces, int faceLevel, VertexHandle a, VertexHandle b);
    // The faces whose refinement test may change when `changed` faces change.
    std::vector<FaceHandle> affectedFaces(const std::vector<FaceHandle>& changed,
                                          const Criterion& criterion) const;

    const Surface* surface_;
    RbmtBase base_;
    TriMesh mesh_;
    OpenMesh::VPropHandleT<int> vertexLevel_;
    OpenMesh::FPropHandleT<int> faceLevel_;
    OpenMesh::HPropHandleT<bool> refinementMark_;
    // Internal edges of the base blocks (base vertex indices): tells a level-1 vertex's split edge
    // from the other diagonal of its ring, which the (u,v) midpoint alone cannot for parallelograms.
    std::unordered_set<std::uint64_t> baseBlockEdges_;
    std::size_t deletedFaces_ = 0;
    std::size_t deletedVertices_ = 0;
};

} // namespace vl
