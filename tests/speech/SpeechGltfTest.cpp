#include "SpeechTestModels.h"

#include "core/export/GltfExport.h"
#include "core/speech/SpeechGltf.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <random>

using namespace vl;

namespace {

std::vector<float> floatsOf(const tinygltf::Model& model, int accessorIndex) {
    const auto& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
    const auto& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    const auto& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    std::vector<float> values(accessor.count);
    std::memcpy(values.data(), buffer.data.data() + view.byteOffset + accessor.byteOffset, values.size() * 4);
    return values;
}

// The glTF 2.0 specification's sampler evaluation (Appendix C) of a weights channel at time t.
std::vector<double> evaluateSampler(const std::vector<float>& times, const std::vector<float>& values,
                                    bool cubic, std::size_t targets, double t) {
    const std::size_t stride = cubic ? 3 * targets : targets, valueAt = cubic ? targets : 0;
    const auto value = [&](std::size_t k, std::size_t j) { return double(values[k * stride + valueAt + j]); };
    std::vector<double> out(targets);
    if (t <= times.front() || times.size() == 1) {
        for (std::size_t j = 0; j < targets; ++j) out[j] = value(0, j);
        return out;
    }
    if (t >= times.back()) {
        for (std::size_t j = 0; j < targets; ++j) out[j] = value(times.size() - 1, j);
        return out;
    }
    std::size_t k = 0;
    while (t >= times[k + 1]) ++k;
    const double td = double(times[k + 1]) - times[k], s = (t - times[k]) / td;
    for (std::size_t j = 0; j < targets; ++j) {
        if (!cubic) {
            out[j] = (1 - s) * value(k, j) + s * value(k + 1, j);
            continue;
        }
        const double b = values[k * stride + 2 * targets + j], a = values[(k + 1) * stride + j];
        out[j] = (2 * s * s * s - 3 * s * s + 1) * value(k, j) + td * (s * s * s - 2 * s * s + s) * b +
                 (-2 * s * s * s + 3 * s * s) * value(k + 1, j) + td * (s * s * s - s * s) * a;
    }
    return out;
}

} // namespace

// The glb's animation, read back with tinygltf and evaluated as the glTF specification says,
// plays the weights the runtime's evaluator gives.
TEST(SpeechGltf, GlbAnimationPlaysTheRuntimeWeights) {
    std::mt19937 rng(4);
    const auto m = test::speechModels(4, {0, 1, 1, 2}, 21);
    std::vector<std::pair<std::string, double>> items;
    for (int i = 0; i < 25; ++i)
        items.emplace_back(i % 6 == 0 ? "sil" : "P" + std::to_string(rng() % 8),
                           std::uniform_real_distribution<double>(0.03, 0.25)(rng));
    const auto phonemes = test::timed(items);
    for (auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        SCOPED_TRACE(toString(interpolation));
        const FaceTrack face(m.reduced, phonemes, {interpolation}, "reduced");
        const GltfMorphAnimation animation = gltfAnimationOf(face, 60.0);
        const std::string glb = formatGlb(m.reduced, &animation);
        tinygltf::Model model;
        tinygltf::TinyGLTF loader;
        std::string error, warning;
        ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                reinterpret_cast<const unsigned char*>(glb.data()),
                                                static_cast<unsigned>(glb.size())))
            << error;
        ASSERT_EQ(model.animations.size(), 1u);
        const auto& channel = model.animations[0].channels.at(0);
        EXPECT_EQ(channel.target_path, "weights");
        EXPECT_EQ(channel.target_node, 0);
        const auto& sampler = model.animations[0].samplers.at(0);
        const bool cubic = sampler.interpolation == "CUBICSPLINE";
        EXPECT_EQ(cubic, interpolation == runtime::Interpolation::Cubic);
        const auto times = floatsOf(model, sampler.input), values = floatsOf(model, sampler.output);
        const std::size_t targets = face.keyCount();
        std::vector<float> expected(targets);
        // Dominance is sampled: exact at the samples only.
        const double step = interpolation == runtime::Interpolation::Dominance ? 1.0 / 60.0 : 0.0037;
        for (double t = 0; t <= face.duration(); t += step) {
            face.keyWeights(t, expected.data());
            const auto got = evaluateSampler(times, values, cubic, targets, t);
            for (std::size_t j = 0; j < targets; ++j) ASSERT_NEAR(got[j], expected[j], 2e-4) << t;
        }
    }
}
