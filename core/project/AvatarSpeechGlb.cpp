#include "core/project/AvatarSpeechGlb.h"

#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/gltf/GlbRepack.h"
#include "core/speech/SpeechGltf.h"

#include <cstring>

namespace vl {

namespace {

int addFloatAccessor(GlbRepack& out, const std::vector<float>& values, bool bounds) {
    std::string bytes(values.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    Json accessor{{"bufferView", out.addView(std::move(bytes))},
                  {"componentType", 5126},
                  {"count", values.size()},
                  {"type", "SCALAR"}};
    if (bounds) { // glTF requires min and max on animation inputs
        accessor["min"] = Json::array({values.front()});
        accessor["max"] = Json::array({values.back()});
    }
    return out.addAccessor(std::move(accessor));
}

// The sampler output of one mesh: per time (and per block: in-tangent, value, out-tangent for
// CUBICSPLINE) one weight per morph target of the mesh.
std::vector<float> meshWeights(const GltfMorphAnimation& animation, std::size_t keys, const MeshDrive& drive,
                               const std::vector<double>& defaults) {
    const bool cubic = animation.interpolation == GltfMorphAnimation::Interpolation::CubicSpline;
    const std::size_t blocks = cubic ? 3 : 1, valueBlock = cubic ? 1 : 0;
    const std::size_t targets = drive.keyOfTarget.size();
    std::vector<float> out;
    out.reserve(animation.times.size() * blocks * targets);
    for (std::size_t time = 0; time < animation.times.size(); ++time)
        for (std::size_t block = 0; block < blocks; ++block)
            for (std::size_t t = 0; t < targets; ++t) {
                const int key = drive.keyOfTarget[t];
                float weight = 0.0f;
                if (key >= 0)
                    weight = animation.values[(time * blocks + block) * keys + static_cast<std::size_t>(key)];
                else if (key == MeshDrive::kDefaultWeight && block == valueBlock && t < defaults.size())
                    weight = static_cast<float>(defaults[t]);
                out.push_back(weight);
            }
    return out;
}

} // namespace

std::string speakingAvatarGlb(const AvatarSpeech& speech, const FaceTrack& track, double fps) {
    const GltfDocument& doc = *speech.animated;
    const GltfMorphAnimation animation = gltfAnimationOf(track, fps);
    GlbRepack out(doc);
    const int input = addFloatAccessor(out, animation.times, true);
    Json samplers = Json::array(), channels = Json::array();
    for (const MeshDrive& drive : speech.drives) {
        const auto& mesh = doc.model.meshes[static_cast<std::size_t>(drive.mesh)];
        const int sampler = static_cast<int>(samplers.size());
        bool used = false;
        for (std::size_t n = 0; n < doc.model.nodes.size(); ++n) {
            if (doc.model.nodes[n].mesh != drive.mesh) continue;
            channels.push_back({{"sampler", sampler}, {"target", {{"node", n}, {"path", "weights"}}}});
            used = true;
        }
        if (!used) continue;
        const int output =
            addFloatAccessor(out, meshWeights(animation, track.keyCount(), drive, mesh.weights), false);
        samplers.push_back(
            {{"input", input},
             {"output", output},
             {"interpolation", animation.interpolation == GltfMorphAnimation::Interpolation::CubicSpline
                                   ? "CUBICSPLINE"
                                   : "LINEAR"}});
    }
    if (channels.empty()) doc.fail("nodes", "no node instances a mesh carrying visemes: nothing to animate");
    if (!out.json.contains("animations")) out.json["animations"] = Json::array();
    out.json["animations"].push_back(
        {{"name", animation.name}, {"samplers", std::move(samplers)}, {"channels", std::move(channels)}});
    return out.finish();
}

} // namespace vl
