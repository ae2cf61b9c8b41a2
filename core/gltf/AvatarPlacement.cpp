#include "core/gltf/AvatarPlacement.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <map>

namespace vl {
namespace {

int attributeOf(const std::map<std::string, int>& attributes, const std::string& name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

} // namespace

AvatarPlacement avatarPlacement(const GltfDocument& doc, AccessorReader& reader, const SceneInstances& scene,
                                const AvatarMesh& mesh) {
    AvatarPlacement placement;
    if (mesh.node >= 0) placement.node = scene.world[static_cast<std::size_t>(mesh.node)];
    if (mesh.skin >= 0) placement.joints = skinRestMatrices(doc, reader, scene, mesh.skin);
    return placement;
}

std::vector<glm::dmat4> skinnedMatrices(const GltfDocument& doc, AccessorReader& reader,
                                        const tinygltf::Primitive& prim, const AvatarPlacement& placement,
                                        std::size_t vertices, const std::string& where) {
    if (placement.joints.empty()) return {};
    std::vector<glm::dmat4> blended(vertices, glm::dmat4(0.0));
    std::vector<double> total(vertices, 0.0);
    for (int set = 0;; ++set) {
        const int joints = attributeOf(prim.attributes, "JOINTS_" + std::to_string(set));
        const int weights = attributeOf(prim.attributes, "WEIGHTS_" + std::to_string(set));
        if (joints < 0 || weights < 0) break;
        const std::vector<float> j =
            reader.floats(joints, TINYGLTF_TYPE_VEC4, where + "/JOINTS_" + std::to_string(set), vertices);
        const std::vector<float> w =
            reader.floats(weights, TINYGLTF_TYPE_VEC4, where + "/WEIGHTS_" + std::to_string(set), vertices);
        for (std::size_t v = 0; v < vertices; ++v)
            for (std::size_t c = 0; c < 4; ++c) {
                const float weight = w[4 * v + c];
                if (weight == 0.0f) continue;
                const auto joint = static_cast<std::size_t>(j[4 * v + c]);
                if (j[4 * v + c] < 0 || joint >= placement.joints.size())
                    doc.fail(where + "/JOINTS_" + std::to_string(set),
                             "vertex " + std::to_string(v) + " names joint " + std::to_string(joint) +
                                 " of " + std::to_string(placement.joints.size()));
                blended[v] += static_cast<double>(weight) * placement.joints[joint];
                total[v] += weight;
            }
    }
    for (std::size_t v = 0; v < vertices; ++v)
        blended[v] = total[v] > 0 ? blended[v] / total[v] : placement.node;
    return blended;
}

std::vector<glm::dmat3> inverseWorldLinear(const GltfDocument& doc, const AvatarMesh& mesh, std::size_t p) {
    const SceneInstances scene = sceneInstances(doc);
    BufferViews views(doc);
    AccessorReader reader(doc, views);
    const AvatarPlacement placement = avatarPlacement(doc, reader, scene, mesh);
    const std::string where = "meshes/" + std::to_string(mesh.index) + "/primitives/" + std::to_string(p);
    const tinygltf::Primitive& prim = doc.model.meshes[static_cast<std::size_t>(mesh.index)].primitives[p];
    std::vector<glm::dmat4> matrices =
        skinnedMatrices(doc, reader, prim, placement, mesh.primitives[p].vertices, where);
    if (matrices.empty()) matrices.push_back(placement.node);
    std::vector<glm::dmat3> inverses;
    inverses.reserve(matrices.size());
    for (std::size_t v = 0; v < matrices.size(); ++v) {
        const glm::dmat3 linear(matrices[v]);
        const double det = glm::determinant(linear);
        if (!std::isfinite(det) || std::abs(det) < 1e-12)
            doc.fail(where,
                     "vertex " + std::to_string(v) +
                         " is placed by a singular matrix (a zero scale): a sculpted displacement cannot "
                         "be written in its space");
        inverses.push_back(glm::inverse(linear));
    }
    return inverses;
}

} // namespace vl
