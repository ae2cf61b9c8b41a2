#pragma once
// The application side of the adaptive mesh (paper section 5): a surface object gives the base domain
// (a coarse triangulation of (u,v) points) and the sampling function (u,v) -> R^3. The refinement and
// simplification tests live in Criterion (core/adaptive/Criteria.h) so one surface can be adapted
// under different criteria and thresholds.
#include "core/mesh/Mesh.h"

namespace vl {

class Surface {
  public:
    virtual ~Surface() = default;
    // The base domain: uvs and triangles (positions are ignored). Triangles may be listed in either
    // orientation in (u,v) as long as all agree.
    virtual const MeshData& baseDomain() const = 0;
    // The point of the surface at (u,v); must be deterministic (the mesh checks positions bit-exactly)
    // and safe to call from several threads at once (AdaptiveMesh::resample runs in parallel).
    virtual Vec3 sample(const Vec2& uv) const = 0;
};

} // namespace vl
