#include "core/gltf/SceneGraph.h"

#include "core/gltf/Accessors.h"
#include "core/gltf/GltfDocument.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace vl {
namespace {

glm::dmat4 localMatrix(const GltfDocument& doc, const tinygltf::Node& node, std::size_t index) {
    const std::string where = "nodes/" + std::to_string(index);
    glm::dmat4 m(1.0);
    if (node.matrix.size() == 16) {
        m = glm::make_mat4(node.matrix.data()); // glTF matrices are column-major, like glm
    } else {
        if (!node.matrix.empty()) doc.fail(where + "/matrix", "needs 16 numbers");
        glm::dvec3 t(0.0), s(1.0);
        glm::dquat r(1.0, 0.0, 0.0, 0.0);
        if (node.translation.size() == 3) t = {node.translation[0], node.translation[1], node.translation[2]};
        if (node.rotation.size() == 4)
            r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
        m = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) doc.fail(where, "non-finite transform");
    return m;
}

} // namespace

SceneInstances sceneInstances(const GltfDocument& doc) {
    const auto& nodes = doc.model.nodes;
    const std::size_t count = nodes.size();
    std::vector<int> parent(count, -1);
    for (std::size_t i = 0; i < count; ++i)
        for (int child : nodes[i].children) {
            const std::string where = "nodes/" + std::to_string(i) + "/children";
            if (child < 0 || static_cast<std::size_t>(child) >= count)
                doc.fail(where, "node " + std::to_string(child) + " does not exist");
            if (parent[static_cast<std::size_t>(child)] != -1)
                doc.fail(where, "node " + std::to_string(child) + " already is a child of node " +
                                    std::to_string(parent[static_cast<std::size_t>(child)]));
            parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
        }

    SceneInstances out;
    out.world.assign(count, glm::dmat4(1.0));
    // Roots first, then children: a node is placed once its parent is. Nodes never reached sit on a cycle.
    std::vector<char> placed(count, 0);
    std::vector<std::size_t> stack;
    for (std::size_t i = 0; i < count; ++i)
        if (parent[i] == -1) stack.push_back(i);
    std::vector<std::size_t> order; // depth-first from the roots
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        placed[i] = 1;
        order.push_back(i);
        const glm::dmat4 local = localMatrix(doc, nodes[i], i);
        out.world[i] = parent[i] >= 0 ? out.world[static_cast<std::size_t>(parent[i])] * local : local;
        for (auto c = nodes[i].children.rbegin(); c != nodes[i].children.rend(); ++c)
            stack.push_back(static_cast<std::size_t>(*c));
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!placed[i]) doc.fail("nodes/" + std::to_string(i), "is part of a cycle of children");

    const std::size_t meshCount = doc.model.meshes.size();
    out.meshNode.assign(meshCount, -1);
    out.meshUses.assign(meshCount, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const int mesh = nodes[i].mesh;
        if (mesh < 0) continue;
        if (static_cast<std::size_t>(mesh) >= meshCount)
            doc.fail("nodes/" + std::to_string(i) + "/mesh",
                     "mesh " + std::to_string(mesh) + " does not exist");
        ++out.meshUses[static_cast<std::size_t>(mesh)];
    }
    // Scene order first (the default scene, then the others), then nodes outside every scene.
    std::vector<std::size_t> sceneOrder;
    std::vector<int> scenes;
    if (doc.model.defaultScene >= 0 &&
        static_cast<std::size_t>(doc.model.defaultScene) < doc.model.scenes.size())
        scenes.push_back(doc.model.defaultScene);
    for (std::size_t s = 0; s < doc.model.scenes.size(); ++s)
        if (static_cast<int>(s) != doc.model.defaultScene) scenes.push_back(static_cast<int>(s));
    std::vector<char> rootOf(count, 0);
    for (int s : scenes)
        for (int root : doc.model.scenes[static_cast<std::size_t>(s)].nodes)
            if (root >= 0 && static_cast<std::size_t>(root) < count)
                rootOf[static_cast<std::size_t>(root)] = 1;
    // `order` lists every subtree contiguously after its root, so a node inherits its root's flag.
    std::vector<char> inScene(count, 0);
    for (std::size_t i : order)
        inScene[i] = parent[i] >= 0 ? inScene[static_cast<std::size_t>(parent[i])] : rootOf[i];
    for (std::size_t i : order)
        if (inScene[i]) sceneOrder.push_back(i);
    for (std::size_t i : order)
        if (!inScene[i]) sceneOrder.push_back(i);
    for (std::size_t i : sceneOrder) {
        const int mesh = nodes[i].mesh;
        if (mesh >= 0 && out.meshNode[static_cast<std::size_t>(mesh)] < 0)
            out.meshNode[static_cast<std::size_t>(mesh)] = static_cast<int>(i);
    }
    return out;
}

std::vector<glm::dmat4> skinRestMatrices(const GltfDocument& doc, AccessorReader& reader,
                                         const SceneInstances& scene, int skin) {
    const std::string where = "skins/" + std::to_string(skin);
    if (skin < 0 || static_cast<std::size_t>(skin) >= doc.model.skins.size())
        doc.fail(where, "does not exist");
    const tinygltf::Skin& s = doc.model.skins[static_cast<std::size_t>(skin)];
    std::vector<float> inverseBind;
    if (s.inverseBindMatrices >= 0)
        inverseBind =
            reader.floats(s.inverseBindMatrices, TINYGLTF_TYPE_MAT4, where + "/inverseBindMatrices");
    if (!inverseBind.empty() && inverseBind.size() < 16 * s.joints.size())
        doc.fail(where + "/inverseBindMatrices", "fewer matrices than joints");
    std::vector<glm::dmat4> out;
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
        const int joint = s.joints[j];
        if (joint < 0 || static_cast<std::size_t>(joint) >= scene.world.size())
            doc.fail(where + "/joints", "node " + std::to_string(joint) + " does not exist");
        glm::dmat4 ibm(1.0);
        if (!inverseBind.empty())
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    ibm[c][r] = inverseBind[16 * j + static_cast<std::size_t>(4 * c + r)];
        out.push_back(scene.world[static_cast<std::size_t>(joint)] * ibm);
    }
    return out;
}

} // namespace vl
