#include "core/speech/FaceTrack.h"

#include "core/common/Error.h"
#include "core/runtime/PackageFormat.h"

#include <algorithm>

namespace vl {

FaceTrack::FaceTrack(ReducedModel model, std::span<const TimedPhoneme> phonemes,
                     const PlaybackSettings& settings, std::string_view where) {
    keys_ = keysOfPhonemes(phonemes, model, where);
    init(std::make_shared<const ReducedModel>(std::move(model)), phonemes, settings, where);
}

FaceTrack::FaceTrack(std::shared_ptr<const ReducedModel> model, std::span<const TimedPhoneme> phonemes,
                     const PlaybackSettings& settings, std::string_view where, ModelCheck check) {
    keys_ = keysOfPhonemes(phonemes, *model, where);
    init(std::move(model), phonemes, settings, where, check);
}

FaceTrack::FaceTrack(ReducedModel model, std::span<const TimedPhoneme> phonemes, std::vector<int> keys,
                     const PlaybackSettings& settings, std::string_view where)
    : keys_(std::move(keys)) {
    init(std::make_shared<const ReducedModel>(std::move(model)), phonemes, settings, where);
}

void FaceTrack::init(std::shared_ptr<const ReducedModel> shared, std::span<const TimedPhoneme> phonemes,
                     const PlaybackSettings& settings, std::string_view where, ModelCheck check) {
    const ReducedModel& model = *shared;
    checkTimedPhonemes(phonemes, where);
    if (check == ModelCheck::Validate) validateReducedModel(model, where);
    if (model.keys.size() > runtime::kMaxKeys)
        throwInputError(where, std::to_string(model.keys.size()) + " keys; a runtime package holds at most " +
                                   std::to_string(runtime::kMaxKeys));
    if (keys_.size() != phonemes.size())
        throwInputError(where, "one key per phoneme expected, got " + std::to_string(keys_.size()) + " for " +
                                   std::to_string(phonemes.size()) + " phonemes");
    for (const int key : keys_)
        if (key != kNeutralKey && (key < 0 || static_cast<std::size_t>(key) >= model.keys.size()))
            throwInputError(where, "key " + std::to_string(key) + " of " + std::to_string(model.keys.size()));
    cues_ = cuesOf(phonemes, keys_, model);
    duration_ = phonemes.back().end;
    std::string error;
    if (!curve_.setKeyframes(static_cast<std::uint32_t>(model.keys.size()),
                             keyframesOf(phonemes, keys_, settings), settings.interpolation, error,
                             settings.dominanceRate))
        throwInputError(where, "animation: " + error);
    model_ = std::move(shared);
}

void FaceTrack::keyWeights(double t, float* out) const {
    std::fill(out, out + keyCount(), 0.0f);
    runtime::KeyWeight terms[4];
    const std::size_t count = curve_.weightsAt(t, terms);
    for (std::size_t j = 0; j < count; ++j)
        if (terms[j].key != runtime::kRestKey) out[terms[j].key] += terms[j].weight;
}

std::vector<float> FaceTrack::keyWeights(double t) const {
    std::vector<float> weights(keyCount());
    keyWeights(t, weights.data());
    return weights;
}

} // namespace vl
