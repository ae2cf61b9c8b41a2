#include "core/export/GltfExport.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"

#include <tiny_gltf.h>

#include <cstring>
#include <limits>
#include <sstream>

namespace vl {
namespace {

// Appends one tightly packed array as its own buffer view + accessor; views start 4-byte aligned.
class GltfBuilder {
  public:
    tinygltf::Model model;

    GltfBuilder() { model.buffers.emplace_back(); }

    template <typename T>
    int addAccessor(const std::vector<T>& values, int componentType, int type, std::size_t count, int target,
                    bool withBounds) {
        std::vector<unsigned char>& data = model.buffers[0].data;
        while (data.size() % 4 != 0) data.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = values.size() * sizeof(T);
        view.target = target;
        const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
        data.insert(data.end(), bytes, bytes + view.byteLength);
        model.bufferViews.push_back(view);

        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
        accessor.byteOffset = 0;
        accessor.componentType = componentType;
        accessor.type = type;
        accessor.count = count;
        if (withBounds) {
            const std::size_t components = values.size() / count;
            accessor.minValues.assign(components, std::numeric_limits<double>::infinity());
            accessor.maxValues.assign(components, -std::numeric_limits<double>::infinity());
            for (std::size_t i = 0; i < values.size(); ++i) {
                const double v = static_cast<double>(values[i]);
                accessor.minValues[i % components] = std::min(accessor.minValues[i % components], v);
                accessor.maxValues[i % components] = std::max(accessor.maxValues[i % components], v);
            }
        }
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size()) - 1;
    }

    int addVec3(const std::vector<float>& xyz, bool withBounds) {
        return addAccessor(xyz, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, xyz.size() / 3,
                           TINYGLTF_TARGET_ARRAY_BUFFER, withBounds);
    }
};

// Unit normals as floats; a vertex without incident area gets +Z (glTF requires unit NORMALs).
std::vector<float> unitNormals(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles) {
    const std::vector<Vec3> normals = vertexNormals(positions, triangles);
    std::vector<float> out;
    out.reserve(normals.size() * 3);
    for (const Vec3& n : normals) {
        const double length = n.norm();
        const Vec3 unit = length > 1e-12 ? n / length : Vec3(0, 0, 1);
        for (int a = 0; a < 3; ++a) out.push_back(static_cast<float>(unit[a]));
    }
    return out;
}

std::vector<float> difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    std::vector<float> out;
    out.reserve(a.size() * 3);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(a[i][c] - b[i][c]));
    return out;
}

tinygltf::Value visemeLabExtras(const ReducedModel& model) {
    tinygltf::Value::Array names, frequencies, members;
    for (const KeyMesh& key : model.keys) {
        names.emplace_back(key.name);
        frequencies.emplace_back(key.frequency);
        tinygltf::Value::Array memberNames;
        for (const std::string& m : key.members) memberNames.emplace_back(m);
        members.emplace_back(std::move(memberNames));
    }
    tinygltf::Value::Object phonemeToTarget, phonemeFrequencies;
    for (const auto& [phoneme, key] : model.phonemeToKey) phonemeToTarget[phoneme] = tinygltf::Value(key);
    for (const auto& [phoneme, f] : model.phonemeFrequencies)
        phonemeFrequencies[phoneme] = tinygltf::Value(f);
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(std::move(names));
    extras["targetFrequencies"] = tinygltf::Value(std::move(frequencies));
    extras["targetMembers"] = tinygltf::Value(std::move(members));
    extras["phonemeToTarget"] = tinygltf::Value(std::move(phonemeToTarget));
    if (!phonemeFrequencies.empty())
        extras["phonemeFrequencies"] = tinygltf::Value(std::move(phonemeFrequencies));
    return tinygltf::Value(std::move(extras));
}

// Animation data is not vertex data: its buffer views have no target.
constexpr int kNoBufferTarget = 0;

// Appends `animation` as one sampler and one "weights" channel on node 0.
void addMorphAnimation(GltfBuilder& b, const GltfMorphAnimation& animation, std::size_t targets) {
    const bool cubic = animation.interpolation == GltfMorphAnimation::Interpolation::CubicSpline;
    const std::size_t perTime = targets * (cubic ? 3 : 1);
    if (animation.times.empty() || targets == 0 ||
        animation.values.size() != animation.times.size() * perTime)
        throwInputError("glTF export", "animation '" + animation.name +
                                           "': " + std::to_string(animation.values.size()) + " values for " +
                                           std::to_string(animation.times.size()) + " times and " +
                                           std::to_string(targets) + " morph targets");
    for (std::size_t i = 1; i < animation.times.size(); ++i)
        if (!(animation.times[i] > animation.times[i - 1]))
            throwInputError("glTF export", "animation '" + animation.name + "': time " + std::to_string(i) +
                                               " does not increase");
    tinygltf::AnimationSampler sampler;
    sampler.input = b.addAccessor(animation.times, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                  animation.times.size(), kNoBufferTarget, true); // input needs min/max
    sampler.output = b.addAccessor(animation.values, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                   animation.values.size(), kNoBufferTarget, false);
    sampler.interpolation = cubic ? "CUBICSPLINE" : "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation gltfAnimation;
    gltfAnimation.name = animation.name;
    gltfAnimation.samplers.push_back(std::move(sampler));
    gltfAnimation.channels.push_back(std::move(channel));
    b.model.animations.push_back(std::move(gltfAnimation));
}

} // namespace

std::string formatGlb(const ReducedModel& model, const GltfMorphAnimation* animation) {
    validateReducedModel(model, "glTF export");
    const MeshData& mesh = model.neutral;
    GltfBuilder b;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;

    std::vector<float> positions;
    for (const Vec3& p : mesh.positions)
        for (int a = 0; a < 3; ++a) positions.push_back(static_cast<float>(p[a]));
    primitive.attributes["POSITION"] = b.addVec3(positions, true);
    const std::vector<float> normals = unitNormals(mesh.positions, mesh.triangles);
    primitive.attributes["NORMAL"] = b.addVec3(normals, false);
    if (mesh.hasUVs()) {
        std::vector<float> uvs;
        for (const Vec2& uv : mesh.uvs) {
            uvs.push_back(static_cast<float>(uv[0]));
            uvs.push_back(static_cast<float>(1.0 - uv[1]));
        }
        primitive.attributes["TEXCOORD_0"] =
            b.addAccessor(uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, mesh.uvs.size(),
                          TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    // 65535 is the primitive-restart value, which glTF forbids as an index.
    const std::size_t corners = mesh.triangles.size() * 3;
    if (mesh.positions.size() <= 0xFFFF) {
        std::vector<std::uint16_t> indices;
        for (const Triangle& t : mesh.triangles)
            for (std::uint32_t i : t) indices.push_back(static_cast<std::uint16_t>(i));
        primitive.indices =
            b.addAccessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, corners,
                          TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, false);
    } else {
        std::vector<std::uint32_t> indices;
        for (const Triangle& t : mesh.triangles)
            for (std::uint32_t i : t) indices.push_back(i);
        primitive.indices = b.addAccessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                          corners, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, false);
    }

    for (const KeyMesh& key : model.keys) {
        std::map<std::string, int> target;
        target["POSITION"] = b.addVec3(difference(key.positions, mesh.positions), true);
        const std::vector<float> keyNormals = unitNormals(key.positions, mesh.triangles);
        std::vector<float> normalDelta(keyNormals.size());
        for (std::size_t i = 0; i < keyNormals.size(); ++i) normalDelta[i] = keyNormals[i] - normals[i];
        target["NORMAL"] = b.addVec3(normalDelta, false);
        primitive.targets.push_back(std::move(target));
    }

    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "face";
    gltfMesh.primitives.push_back(std::move(primitive));
    gltfMesh.weights.assign(model.keys.size(), 0.0);
    gltfMesh.extras = visemeLabExtras(model);
    b.model.meshes.push_back(std::move(gltfMesh));

    tinygltf::Node node;
    node.name = "face";
    node.mesh = 0;
    b.model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    b.model.scenes.push_back(scene);
    b.model.defaultScene = 0;
    if (animation) addMorphAnimation(b, *animation, model.keys.size());
    b.model.asset.version = "2.0";
    b.model.asset.generator = "VisemeLab";
    b.model.buffers[0].data.resize((b.model.buffers[0].data.size() + 3) & ~std::size_t{3}, 0);

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&b.model, stream, false, true))
        throwInputError("glTF export", "tinygltf could not serialise the model");
    return stream.str();
}

void writeGlb(const std::filesystem::path& path, const ReducedModel& model,
              const GltfMorphAnimation* animation) {
    writeFileAtomically(path, formatGlb(model, animation));
}

} // namespace vl
