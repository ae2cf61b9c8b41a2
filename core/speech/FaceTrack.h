#pragma once
// One face speaking timed phonemes: its model (neutral and key meshes), the keyframes and the
// runtime's keyframe evaluator (runtime::KeyframeCurve) that plays them, and the cues a timeline
// shows. The CLI, the glTF animation, the utterance error and the editor all take the face's key
// weights from here, so they show the motion a device running runtime::KeyframeAnimation shows.
#include "core/reduce/ReducedModel.h"
#include "core/runtime/Animation.h"
#include "core/speech/TrackKeyframes.h"
#include "core/speech/VisemeTrack.h"

#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace vl {

class FaceTrack {
  public:
    // Throws InputError at `where` for phonemes the model's map does not map (keysOfPhonemes), for
    // phonemes that are not contiguous, and for a model that is not valid (validateReducedModel)
    // or has more keys than a runtime package holds.
    FaceTrack(ReducedModel model, std::span<const TimedPhoneme> phonemes, const PlaybackSettings& settings,
              std::string_view where);
    // The same with the key of every phoneme given (kNeutralKey for the neutral face), e.g. a
    // sequence of viseme names typed by a designer.
    FaceTrack(ReducedModel model, std::span<const TimedPhoneme> phonemes, std::vector<int> keys,
              const PlaybackSettings& settings, std::string_view where);
    // The first form on a model shared with other tracks: a server speaking many sentences with one
    // face copies no keys per sentence (`say --stdin`). The owner of a shared model that validated it
    // once (validateReducedModel, as loadSpeakingFace does) passes AlreadyValidated: a sentence then
    // does not check every key position again.
    enum class ModelCheck { Validate, AlreadyValidated };
    FaceTrack(std::shared_ptr<const ReducedModel> model, std::span<const TimedPhoneme> phonemes,
              const PlaybackSettings& settings, std::string_view where,
              ModelCheck check = ModelCheck::Validate);

    const ReducedModel& model() const { return *model_; }
    const std::vector<Cue>& cues() const { return cues_; }
    // The runtime's evaluator of this face's keyframes.
    const runtime::KeyframeCurve& curve() const { return curve_; }
    std::size_t keyCount() const { return model_->keys.size(); }
    double duration() const { return duration_; }

    // The weight of every key at time t, keyCount() floats (glTF morph target weights; the
    // neutral's share is 1 minus their sum).
    void keyWeights(double t, float* out) const;
    std::vector<float> keyWeights(double t) const;

  private:
    void init(std::shared_ptr<const ReducedModel> model, std::span<const TimedPhoneme> phonemes,
              const PlaybackSettings& settings, std::string_view where,
              ModelCheck check = ModelCheck::Validate);

    std::shared_ptr<const ReducedModel> model_; // shared: tracks are copied into the editor's state
    runtime::KeyframeCurve curve_;
    std::vector<int> keys_;
    std::vector<Cue> cues_;
    double duration_ = 0;
};

} // namespace vl
