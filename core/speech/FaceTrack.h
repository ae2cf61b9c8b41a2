#pragma once
// One face speaking timed phonemes: its model as the runtime package a device would load, the
// keyframes and the runtime's KeyframeAnimation that plays them, and the cues a timeline shows.
// The CLI, the glTF animation, the utterance error and the editor all evaluate the face here.
#include "core/export/ReducedModel.h"
#include "core/runtime/Animation.h"
#include "core/runtime/Package.h"
#include "core/speech/TrackKeyframes.h"
#include "core/speech/VisemeTrack.h"

#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace vl {

class FaceTrack {
  public:
    // Throws InputError at `where` for phonemes the model's map does not map (keysOfPhonemes), and
    // for phonemes that are not contiguous or a model the runtime package cannot hold.
    FaceTrack(const ReducedModel& model, std::span<const TimedPhoneme> phonemes,
              const PlaybackSettings& settings, std::string_view where);

    const std::vector<Cue>& cues() const { return cues_; }
    const std::vector<int>& phonemeKeys() const { return keys_; } // per phoneme, kNeutralKey for rest
    const runtime::Package& package() const { return *package_; }
    const runtime::KeyframeAnimation& animation() const { return animation_; }
    std::size_t keyCount() const { return package_->keyCount(); }
    double duration() const { return duration_; }

    // Vertex positions at time t, 3 floats per vertex.
    void evaluate(double t, float* out) const { animation_.evaluate(t, out); }
    // The weight of every key at time t, keyCount() floats (glTF morph target weights; the
    // neutral's share is 1 minus their sum).
    void keyWeights(double t, float* out) const;

  private:
    std::unique_ptr<runtime::Package> package_; // on the heap: animation_ points to it
    runtime::KeyframeAnimation animation_;
    std::vector<int> keys_;
    std::vector<Cue> cues_;
    double duration_ = 0;
};

} // namespace vl
