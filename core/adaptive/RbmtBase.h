#pragma once
// One-time conversion of an arbitrary (u,v) triangulation into the base mesh of a regular binary
// multi-triangulation (RBMT, paper section 4.2): a union of basic blocks. A basic block is a pair of
// triangles sharing their refinement edge (the block's internal edge) or, at the border, a single
// triangle whose refinement edge is a boundary edge. Construction (docs/adaptive-mesh.md):
//  1. pair triangles across mutually longest edges (grids with diagonals pair along the diagonals);
//  2. pair the rest greedily, least-connected triangle first;
//  3. search augmenting paths (re-pairing along alternating chains, or freeing a border triangle)
//     for each triangle still alone; left-over border triangles become single boundary blocks;
//  4. only if some interior triangle is still alone (no block pairing found): split edges instead.
//     A spanning tree of the triangle adjacency (rooted at the border) picks a set of edges such that
//     every triangle has an odd number of them (1 or 3); splitting them at their (u,v) midpoints
//     turns each triangle into 2 or 4 triangles that pair up inside it.
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <vector>

namespace vl {

enum class RbmtMethod {
    Auto,       // steps 1-4: no edge split unless a pairing is impossible to find
    SplitEdges, // step 4 only (always applicable; tests use it to exercise the construction)
};

struct RbmtBase {
    std::vector<Vec2> uvs;
    std::vector<Triangle> triangles; // counter-clockwise in (u,v)
    // refinementEdge[t] = k: the edge from triangles[t][k] to triangles[t][(k+1)%3].
    std::vector<std::uint8_t> refinementEdge;
    std::size_t splitEdges = 0; // edges the conversion split (0 when a pairing was found)
};

// Throws InputError naming the triangle/edge for an empty domain, missing or non-finite (u,v),
// out-of-range indices, degenerate or inconsistently oriented triangles and non-manifold edges.
// Vertices used by no triangle are dropped.
RbmtBase makeRbmtBase(const MeshData& domain, RbmtMethod method = RbmtMethod::Auto);

// True when every triangle's refinement edge is a boundary edge or the refinement edge of the
// triangle on its other side (the base is a union of basic blocks).
bool isUnionOfBasicBlocks(const RbmtBase& base);

} // namespace vl
