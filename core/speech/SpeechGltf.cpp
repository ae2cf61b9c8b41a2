#include "core/speech/SpeechGltf.h"

#include "core/common/Error.h"

#include <cmath>

namespace vl {

namespace {

// glTF stores times as floats: keyframes closer than a float's resolution at that time (in a
// long corpus) cannot be exported as they are.
bool floatTimesIncrease(const std::vector<runtime::Keyframe>& keyframes) {
    for (std::size_t i = 1; i < keyframes.size(); ++i)
        if (!(static_cast<float>(keyframes[i].time) > static_cast<float>(keyframes[i - 1].time)))
            return false;
    return true;
}

// Weight vector of keyframe i: 1 for its key, 0 elsewhere (all 0 for the neutral).
void addOneHot(std::vector<float>& values, std::size_t targets, std::uint32_t key, float scale = 1.0f) {
    const std::size_t start = values.size();
    values.resize(start + targets, 0.0f);
    if (key != runtime::kRestKey) values[start + key] += scale;
}

} // namespace

GltfMorphAnimation sampledGltfAnimation(const FaceTrack& face, double fps) {
    if (!(fps > 0) || !std::isfinite(fps)) throwInputError("glTF animation", "frames per second must be > 0");
    GltfMorphAnimation animation;
    const std::size_t targets = face.keyCount();
    const auto frames = static_cast<std::size_t>(std::ceil(face.duration() * fps - 1e-9)) + 1;
    animation.values.resize(frames * targets);
    for (std::size_t f = 0; f < frames; ++f) {
        const double t = std::min(double(f) / fps, face.duration());
        animation.times.push_back(static_cast<float>(t));
        face.keyWeights(t, animation.values.data() + f * targets);
    }
    if (animation.times.size() >= 2 && !(animation.times.back() > animation.times[frames - 2])) {
        animation.times.pop_back(); // the end fell on the last frame's float
        animation.values.resize(animation.times.size() * targets);
    }
    return animation;
}

GltfMorphAnimation gltfAnimationOf(const FaceTrack& face, double fps) {
    const runtime::KeyframeCurve& track = face.curve();
    const auto& keyframes = track.keyframes();
    if (track.interpolation() == runtime::Interpolation::Dominance || !floatTimesIncrease(keyframes))
        return sampledGltfAnimation(face, fps);
    GltfMorphAnimation animation;
    const std::size_t targets = face.keyCount();
    for (const auto& k : keyframes) animation.times.push_back(static_cast<float>(k.time));
    if (track.interpolation() == runtime::Interpolation::Linear) {
        for (const auto& k : keyframes) addOneHot(animation.values, targets, k.key);
        return animation;
    }
    // Catmull-Rom Hermite as the runtime evaluates it: tangent m_i = (W_{i+1} - W_{i-1}) /
    // (t_{i+1} - t_{i-1}), the end keyframe standing in for a missing neighbour. glTF's
    // CUBICSPLINE with in = out tangent m_i is the same curve.
    animation.interpolation = GltfMorphAnimation::Interpolation::CubicSpline;
    const std::size_t last = keyframes.size() - 1;
    for (std::size_t i = 0; i <= last; ++i) {
        std::vector<float> tangent(targets, 0.0f);
        if (last > 0) {
            const std::size_t before = i > 0 ? i - 1 : i, after = i < last ? i + 1 : i;
            const auto span = static_cast<float>(keyframes[after].time - keyframes[before].time);
            if (keyframes[after].key != runtime::kRestKey) tangent[keyframes[after].key] += 1.0f / span;
            if (keyframes[before].key != runtime::kRestKey) tangent[keyframes[before].key] -= 1.0f / span;
        }
        animation.values.insert(animation.values.end(), tangent.begin(), tangent.end()); // in-tangent
        addOneHot(animation.values, targets, keyframes[i].key);
        animation.values.insert(animation.values.end(), tangent.begin(), tangent.end()); // out-tangent
    }
    return animation;
}

} // namespace vl
