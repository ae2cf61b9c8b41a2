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

bool KeyframeCurve::setKeyframes(std::uint32_t keyCount, std::vector<Keyframe> keyframes,
                                 Interpolation interpolation, std::string& error, double dominanceRate) {
    keyframes_.clear();
    keyCount_ = 0;
    if (keyframes.empty()) {
        error = "no keyframes";
        return false;
    }
    if (!std::isfinite(dominanceRate) || dominanceRate < 0) {
        error = "the dominance rate must be a finite number >= 0";
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
        if (!std::isfinite(k.dominance) || !(k.dominance > 0)) {
            error = "keyframe " + std::to_string(i) + ": dominance must be a finite number > 0";
            return false;
        }
        if (k.key != kRestKey && k.key >= keyCount) {
            error = "keyframe " + std::to_string(i) + ": key " + std::to_string(k.key) + " of " +
                    std::to_string(keyCount);
            return false;
        }
    }
    keyframes_ = std::move(keyframes);
    keyCount_ = keyCount;
    interpolation_ = interpolation;
    dominanceRate_ = dominanceRate;
    return true;
}

bool KeyframeAnimation::setKeyframes(const Package& package, std::vector<Keyframe> keyframes,
                                     Interpolation interpolation, std::string& error, double dominanceRate) {
    package_ = nullptr;
    if (package.empty()) {
        curve_ = KeyframeCurve();
        error = "the package is not loaded";
        return false;
    }
    if (!curve_.setKeyframes(package.keyCount(), std::move(keyframes), interpolation, error, dominanceRate))
        return false;
    package_ = &package;
    return true;
}

namespace {

double smoothstep(double s) {
    return s * s * (3 - 2 * s);
}

} // namespace

// Cohen and Massaro's blend F(t) = sum_i D_i(t) T_i / sum_i D_i(t), with each dominance function
// limited to the two keyframes on either side of its own: a smooth taper takes it from 0 at
// t_{i-2} to full strength at t_{i-1} and back to 0 at t_{i+2}. So at most 4 keyframes (the
// Catmull-Rom neighbourhood) contribute at any time and the blend stays continuous where one
// leaves and another enters. Far keyframes matter little anyway: e^-(theta * gap).
std::size_t KeyframeCurve::dominanceWeightsAt(double t, KeyWeight out[4]) const {
    const std::size_t last = keyframes_.size() - 1;
    t = std::clamp(t, keyframes_.front().time, keyframes_[last].time);
    const auto after = std::upper_bound(keyframes_.begin(), keyframes_.end(), t,
                                        [](double time, const Keyframe& k) { return time < k.time; });
    const std::size_t j = static_cast<std::size_t>(after - keyframes_.begin()) - 1; // t_j <= t
    const std::size_t first = j > 0 ? j - 1 : 0;
    const std::size_t end = std::min(j + 2, last); // inclusive
    // Distances are measured from the nearest keyframe (j or j+1, both at full taper), so the
    // exponentials never all underflow.
    const double sinceJ = t - keyframes_[j].time;
    const double nearest = j < last ? std::min(sinceJ, keyframes_[j + 1].time - t) : sinceJ;
    double raw[4] = {0, 0, 0, 0};
    double sum = 0;
    for (std::size_t i = first; i <= end; ++i) {
        const double ti = keyframes_[i].time;
        double taper = 1.0;
        if (i >= 2 && t < keyframes_[i - 1].time) {
            const double t0 = keyframes_[i - 2].time;
            taper = smoothstep((t - t0) / (keyframes_[i - 1].time - t0));
        } else if (i + 2 <= last && t > keyframes_[i + 1].time) {
            const double t1 = keyframes_[i + 1].time;
            taper = 1.0 - smoothstep((t - t1) / (keyframes_[i + 2].time - t1));
        }
        raw[i - first] =
            keyframes_[i].dominance * taper * std::exp(-dominanceRate_ * (std::abs(t - ti) - nearest));
        sum += raw[i - first];
    }
    std::size_t count = 0;
    for (std::size_t i = first; i <= end; ++i)
        out[count++] = {keyframes_[i].key, static_cast<float>(raw[i - first] / sum)};
    return count;
}

std::size_t KeyframeCurve::weightsAt(double t, KeyWeight out[4]) const {
    if (keyframes_.empty()) return 0;
    if (interpolation_ == Interpolation::Dominance)
        return dominanceWeightsAt(std::isnan(t) ? -HUGE_VAL : t, out);
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
