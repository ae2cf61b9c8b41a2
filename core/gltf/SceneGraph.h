#pragma once
// Where each mesh of a glTF file sits in the world, for measuring only (VisemeLab never bakes a
// transform into its output): node world matrices (spec section 3.5: matrix, or T * R * S, parent
// first), the node that instances each mesh (the first met in the scenes, depth first), and for a
// skinned mesh the rest-pose matrix of each joint, jointWorld * inverseBindMatrix (spec 3.7.3; the
// node's own transform does not apply to skinned meshes). The hierarchy is checked: a node with
// two parents or a cycle is an InputError naming the node, and traversal is iterative.
#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace vl {

class GltfDocument;
class AccessorReader;

struct SceneInstances {
    std::vector<glm::dmat4> world; // per node
    std::vector<int> meshNode;     // per mesh: the node used to measure it, or -1 (identity)
    std::vector<int> meshUses;     // per mesh: how many nodes instance it
};

SceneInstances sceneInstances(const GltfDocument& doc);

// jointWorld * inverseBindMatrix per joint of skin `skin`.
std::vector<glm::dmat4> skinRestMatrices(const GltfDocument& doc, AccessorReader& reader,
                                         const SceneInstances& scene, int skin);

} // namespace vl
