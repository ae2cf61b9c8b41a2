#pragma once
// A face cascade sampled on its display mesh, ready for the GPU morph shader: positions at q = 0 and
// at each unit vector e_k (the cascade is linear in q, so the shader reproduces any q as
// rest + sum q_k (target_k - rest)), plus the skin colours. Computed where the mesh is made: the
// refinement worker samples its own result, so the editor thread does not evaluate it again.
#include "core/deform/DeformationCascade.h"
#include "core/mesh/Mesh.h"

#include <string>
#include <vector>

namespace vl::ui {

struct FaceSamples {
    std::vector<Vec3> rest;
    std::vector<std::vector<Vec3>> targets;
    std::vector<Vec3> colours;
};

// Samples `cascade` at every (u,v) of `uvs` (the face's display mesh).
FaceSamples sampleFace(const DeformationCascade& cascade, const std::vector<Vec2>& uvs);

// The head's parts (face::makeHeadParts: eyeballs, teeth, tongue, mouth cavity) of a face, in the
// same morph form: positions at q = 0 and at each unit vector e_k, triangles, the preview colours of
// their (u,v) tiles. They depend on the cascade only (the refined skin does not change them).
struct HeadPartSamples {
    struct Part {
        std::string name;
        std::size_t first = 0, count = 0; // its vertices in rest / targets
    };
    std::vector<Part> parts;
    std::vector<Vec3> rest;
    std::vector<Triangle> triangles;
    std::vector<std::vector<Vec3>> targets;
    std::vector<Vec3> colours;
};

HeadPartSamples sampleHeadParts(const DeformationCascade& cascade);

} // namespace vl::ui
