#pragma once
// A face cascade sampled on its display mesh, ready for the GPU morph shader: positions at q = 0 and
// at each unit vector e_k (the cascade is linear in q, so the shader reproduces any q as
// rest + sum q_k (target_k - rest)), plus the skin colours. Computed where the mesh is made: the
// refinement worker samples its own result, so the editor thread does not evaluate it again.
#include "core/deform/DeformationCascade.h"
#include "core/mesh/Mesh.h"

#include <vector>

namespace vl::ui {

struct FaceSamples {
    std::vector<Vec3> rest;
    std::vector<std::vector<Vec3>> targets;
    std::vector<Vec3> colours;
};

// Samples `cascade` at every (u,v) of `uvs` (the face's display mesh).
FaceSamples sampleFace(const DeformationCascade& cascade, const std::vector<Vec2>& uvs);

} // namespace vl::ui
