#pragma once
// Keyframe facial animation on a runtime package, as MPEG-4 keyframe animation allows: a timed
// sequence of key meshes (one per spoken phoneme), interpolated linearly or with a cubic Hermite
// curve whose tangents are Catmull-Rom finite differences (C1, passes through every keyframe,
// correct for uneven keyframe spacing). Dependency-free; errors are returned, never thrown.
#include "core/runtime/Package.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vl::runtime {

enum class Interpolation { Linear, Cubic };

struct Keyframe {
    double time = 0.0;     // seconds, strictly increasing along a sequence
    std::uint32_t key = 0; // key mesh index, or kRestKey for the neutral face
};

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
    // kRestKey) against `package`, which must outlive the animation.
    bool setKeyframes(const Package& package, std::vector<Keyframe> keyframes, Interpolation interpolation,
                      std::string& error);

    double startTime() const { return keyframes_.empty() ? 0.0 : keyframes_.front().time; }
    double endTime() const { return keyframes_.empty() ? 0.0 : keyframes_.back().time; }

    // The blend at time t (clamped to [startTime, endTime]): up to 4 (key, weight) terms whose
    // weights sum to 1. Returns the number of terms written to `out`.
    std::size_t weightsAt(double t, KeyWeight out[4]) const;

    // Vertex positions at time t, 3 floats per vertex of the package.
    void evaluate(double t, float* out) const;

  private:
    const Package* package_ = nullptr;
    std::vector<Keyframe> keyframes_;
    Interpolation interpolation_ = Interpolation::Linear;
};

} // namespace vl::runtime
