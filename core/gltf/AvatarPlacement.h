#pragma once
// Where a mesh's vertices sit in the world, as AvatarScan measures them: the node's world matrix,
// or for a skinned mesh the rest-pose blend of its joints' matrices per vertex (spec 3.7.3). Shared
// by the scan (local -> world) and the writer of sculpted visemes (world displacement -> the mesh's
// own space).
#include "core/gltf/SceneGraph.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace tinygltf {
struct Primitive;
}

namespace vl {

struct AvatarMesh;

struct AvatarPlacement {
    glm::dmat4 node{1.0};
    std::vector<glm::dmat4> joints; // jointWorld * inverseBindMatrix; empty: not skinned
};

AvatarPlacement avatarPlacement(const GltfDocument& doc, AccessorReader& reader, const SceneInstances& scene,
                                const AvatarMesh& mesh);

// One matrix per vertex of `prim` for a skinned placement (weights renormalised; a vertex of no
// weight takes the node's matrix); empty when the placement is not skinned.
std::vector<glm::dmat4> skinnedMatrices(const GltfDocument& doc, AccessorReader& reader,
                                        const tinygltf::Primitive& prim, const AvatarPlacement& placement,
                                        std::size_t vertices, const std::string& where);

// The inverse of the linear part of each vertex's world matrix on primitive `p` of `mesh` (one
// entry when the whole primitive shares the node's matrix): a world-space displacement d maps back
// to the mesh's own space as inverse * d. Throws InputError naming the primitive when a matrix is
// singular (a zero scale), since no displacement in its space can then produce the world one.
std::vector<glm::dmat3> inverseWorldLinear(const GltfDocument& doc, const AvatarMesh& mesh, std::size_t p);

} // namespace vl
