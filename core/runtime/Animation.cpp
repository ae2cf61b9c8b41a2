#include "core/runtime/Animation.h"

#include "core/runtime/PackageFormat.h"

#include <algorithm>
#include <cmath>

namespace vl::runtime {

bool keyframesFromPhonemes(const Package& package, const std::vector<PhonemeKeyframe>& phonemes,
                           std::vector<Keyframe>& keyframes, std::string& error) {
    keyframes.clear();
    keyframes.reserve(phonemes.size());
    for (std::size_t i = 0; i < phonemes.size(); ++i) {
        std::uint32_t key = kRestKey;
        if (!phonemes[i].phoneme.empty()) {
            const std::uint32_t p = package.findPhoneme(phonemes[i].phoneme);
            if (p == kNotFound) {
                error = "keyframe " + std::to_string(i) + ": unknown phoneme '" + phonemes[i].phoneme + "'";
                return false;
            }
            key = package.keyOfPhoneme(p);
        }
        keyframes.push_back({phonemes[i].time, key});
    }
    return true;
}

bool KeyframeAnimation::setKeyframes(const Package& package, std::vector<Keyframe> keyframes,
                                     Interpolation interpolation, std::string& error) {
    package_ = nullptr;
    keyframes_.clear();
    if (package.empty()) {
        error = "the package is not loaded";
        return false;
    }
    if (keyframes.empty()) {
        error = "no keyframes";
        return false;
    }
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        const Keyframe& k = keyframes[i];
        if (!std::isfinite(k.time)) {
            error = "keyframe " + std::to_string(i) + ": time is not finite";
            return false;
        }
        if (i > 0 && !(k.time > keyframes[i - 1].time)) {
            error = "keyframe " + std::to_string(i) + ": time does not increase";
            return false;
        }
        if (k.key != kRestKey && k.key >= package.keyCount()) {
            error = "keyframe " + std::to_string(i) + ": key " + std::to_string(k.key) + " of " +
                    std::to_string(package.keyCount());
            return false;
        }
    }
    package_ = &package;
    keyframes_ = std::move(keyframes);
    interpolation_ = interpolation;
    return true;
}

std::size_t KeyframeAnimation::weightsAt(double t, KeyWeight out[4]) const {
    if (keyframes_.empty()) return 0;
    const std::size_t last = keyframes_.size() - 1;
    if (!(t > keyframes_.front().time)) { // also catches NaN
        out[0] = {keyframes_.front().key, 1.0f};
        return 1;
    }
    if (t >= keyframes_[last].time) {
        out[0] = {keyframes_[last].key, 1.0f};
        return 1;
    }
    // Segment i: keyframes_[i].time <= t < keyframes_[i + 1].time.
    const auto after = std::upper_bound(keyframes_.begin(), keyframes_.end(), t,
                                        [](double time, const Keyframe& k) { return time < k.time; });
    const std::size_t i = static_cast<std::size_t>(after - keyframes_.begin()) - 1;
    const double t0 = keyframes_[i].time, t1 = keyframes_[i + 1].time;
    const double h = t1 - t0;
    const double s = (t - t0) / h;
    if (interpolation_ == Interpolation::Linear) {
        out[0] = {keyframes_[i].key, static_cast<float>(1.0 - s)};
        out[1] = {keyframes_[i + 1].key, static_cast<float>(s)};
        return 2;
    }
    // Hermite basis with tangents m_i = (P_{i+1} - P_{i-1}) / (t_{i+1} - t_{i-1}); at the ends the
    // missing neighbour is the end keyframe itself (one-sided difference). Expanded into weights of
    // P_{i-1}, P_i, P_{i+1}, P_{i+2}; they sum to 1.
    const std::size_t im1 = i > 0 ? i - 1 : i;
    const std::size_t ip2 = i + 2 <= last ? i + 2 : i + 1;
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    const double a = h10 * h / (t1 - keyframes_[im1].time); // weight of the tangent at P_i
    const double b = h11 * h / (keyframes_[ip2].time - t0); // weight of the tangent at P_{i+1}
    out[0] = {keyframes_[im1].key, static_cast<float>(-a)};
    out[1] = {keyframes_[i].key, static_cast<float>(h00 - b)};
    out[2] = {keyframes_[i + 1].key, static_cast<float>(h01 + a)};
    out[3] = {keyframes_[ip2].key, static_cast<float>(b)};
    return 4;
}

void KeyframeAnimation::evaluate(double t, float* out) const {
    if (package_ == nullptr) return;
    KeyWeight weights[4];
    const std::size_t count = weightsAt(t, weights);
    package_->blend(weights, count, out);
}

} // namespace vl::runtime
