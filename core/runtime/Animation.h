#pragma once
// Keyframe facial animation on a runtime package, as MPEG-4 keyframe animation allows: a timed
// sequence of key meshes (one per spoken phoneme), interpolated linearly, with a cubic Hermite
// curve whose tangents are Catmull-Rom finite differences (C1, passes through every keyframe,
// correct for uneven keyframe spacing), or blended by dominance for coarticulation (Cohen and
// Massaro 1993, "Modeling coarticulation in synthetic visual speech"): every keyframe pulls the
// mouth towards its key with a strength that decays exponentially away from its time, and the
// shape is the dominance-weighted average, so short segments do not reach their target unless
// they dominate (lip closure of p b m). Dependency-free; errors are returned, never thrown.
#include "core/runtime/Package.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vl::runtime {

enum class Interpolation { Linear, Cubic, Dominance };

struct Keyframe {
    double time = 0.0;      // seconds, strictly increasing along a sequence
    std::uint32_t key = 0;  // key mesh index, or kRestKey for the neutral face
    float dominance = 1.0f; // Dominance only: the magnitude alpha of its dominance function, > 0
};

// Dominance only: the decay rate theta (1/s) of every dominance function
// D_i(t) = alpha_i * exp(-theta * |t - t_i|) (Cohen and Massaro's dominance function with c = 1 and
// the same rate before and after the keyframe). 25/s: a keyframe 80 ms away pulls e^-2 as much.
inline constexpr double kDefaultDominanceRate = 25.0;

struct PhonemeKeyframe {
    double time = 0.0;
    std::string phoneme; // a phoneme of the package, or "" for the neutral (silence)
};

// Maps phonemes to their key meshes. Returns false naming the first unknown phoneme.
bool keyframesFromPhonemes(const Package& package, const std::vector<PhonemeKeyframe>& phonemes,
                           std::vector<Keyframe>& keyframes, std::string& error);

// The evaluator of keyframe animation: the blend weights of the keys at any time. It needs only
// the number of keys, not their meshes, so a renderer that blends on the GPU (morph targets), an
// exporter and a package on a device all play speech through this one piece of code.
class KeyframeCurve {
  public:
    // Checks the sequence (non-empty, finite strictly increasing times, keys < keyCount or
    // kRestKey, finite dominance > 0) and the rate (finite, >= 0). On failure returns false, sets
    // `error` and leaves the curve empty.
    bool setKeyframes(std::uint32_t keyCount, std::vector<Keyframe> keyframes, Interpolation interpolation,
                      std::string& error, double dominanceRate = kDefaultDominanceRate);

    bool empty() const { return keyframes_.empty(); }
    std::uint32_t keyCount() const { return keyCount_; }
    double startTime() const { return keyframes_.empty() ? 0.0 : keyframes_.front().time; }
    double endTime() const { return keyframes_.empty() ? 0.0 : keyframes_.back().time; }
    Interpolation interpolation() const { return interpolation_; }
    double dominanceRate() const { return dominanceRate_; }
    const std::vector<Keyframe>& keyframes() const { return keyframes_; }

    // The blend at time t (clamped to [startTime, endTime]): up to 4 (key, weight) terms whose
    // weights sum to 1 (a key may appear in two terms). Returns the number of terms written (0
    // for an empty curve).
    std::size_t weightsAt(double t, KeyWeight out[4]) const;

  private:
    std::size_t dominanceWeightsAt(double t, KeyWeight out[4]) const;

    std::vector<Keyframe> keyframes_;
    std::uint32_t keyCount_ = 0;
    Interpolation interpolation_ = Interpolation::Linear;
    double dominanceRate_ = kDefaultDominanceRate;
};

// A KeyframeCurve on the key meshes of a package: vertex positions at any time.
class KeyframeAnimation {
  public:
    // As KeyframeCurve::setKeyframes with the package's key count; also refuses an empty package.
    // `package` must outlive the animation.
    bool setKeyframes(const Package& package, std::vector<Keyframe> keyframes, Interpolation interpolation,
                      std::string& error, double dominanceRate = kDefaultDominanceRate);

    double startTime() const { return curve_.startTime(); }
    double endTime() const { return curve_.endTime(); }
    Interpolation interpolation() const { return curve_.interpolation(); }
    const std::vector<Keyframe>& keyframes() const { return curve_.keyframes(); }
    const KeyframeCurve& curve() const { return curve_; }

    std::size_t weightsAt(double t, KeyWeight out[4]) const { return curve_.weightsAt(t, out); }

    // Vertex positions at time t, 3 floats per vertex of the package.
    void evaluate(double t, float* out) const;

  private:
    const Package* package_ = nullptr;
    KeyframeCurve curve_;
};

} // namespace vl::runtime
