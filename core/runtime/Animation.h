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

class KeyframeAnimation {
  public:
    // Checks the sequence (non-empty, finite strictly increasing times, keys < keyCount or
    // kRestKey, finite dominance > 0) and the rate (finite, >= 0) against `package`, which must
    // outlive the animation.
    bool setKeyframes(const Package& package, std::vector<Keyframe> keyframes, Interpolation interpolation,
                      std::string& error, double dominanceRate = kDefaultDominanceRate);

    double startTime() const { return keyframes_.empty() ? 0.0 : keyframes_.front().time; }
    double endTime() const { return keyframes_.empty() ? 0.0 : keyframes_.back().time; }

    Interpolation interpolation() const { return interpolation_; }
    const std::vector<Keyframe>& keyframes() const { return keyframes_; }

    // The blend at time t (clamped to [startTime, endTime]): up to 4 (key, weight) terms whose
    // weights sum to 1 (a key may appear in two terms). Returns the number of terms written.
    std::size_t weightsAt(double t, KeyWeight out[4]) const;

    // Vertex positions at time t, 3 floats per vertex of the package.
    void evaluate(double t, float* out) const;

  private:
    std::size_t dominanceWeightsAt(double t, KeyWeight out[4]) const;

    const Package* package_ = nullptr;
    std::vector<Keyframe> keyframes_;
    Interpolation interpolation_ = Interpolation::Linear;
    double dominanceRate_ = kDefaultDominanceRate;
};

} // namespace vl::runtime
