#pragma once
// The structural checks of an adaptive mesh, used by the tests after every operation sequence (and
// available to debug builds of the tools). Each violation is one human-readable line.
#include "core/adaptive/AdaptiveMesh.h"

#include <string>
#include <vector>

namespace vl {

// Checks: manifold (every live vertex has a single fan of faces, every edge one or two faces);
// consistent orientation (every face counter-clockwise in (u,v), opposite halfedges reversed) and an
// exact tiling of the domain (face (u,v) areas sum to the base area); RBMT structure (one refinement
// edge per face, partner across it at the same level marking it, or one level coarser not marking it,
// or the border); restricted levels (adjacent faces differ by at most one level, a face's newest
// vertex has its level, no vertex finer than its faces); base vertices present and unchanged; every
// vertex (u,v) inside a base triangle and its position bit-exactly the surface's sample at (u,v).
std::vector<std::string> checkAdaptiveMesh(const AdaptiveMesh& mesh);

} // namespace vl
