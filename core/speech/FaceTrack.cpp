#include "core/speech/FaceTrack.h"

#include "core/common/Error.h"
#include "core/export/RuntimePackageWriter.h"

#include <algorithm>

namespace vl {

FaceTrack::FaceTrack(const ReducedModel& model, std::span<const TimedPhoneme> phonemes,
                     const PlaybackSettings& settings, std::string_view where)
    : package_(std::make_unique<runtime::Package>()) {
    checkTimedPhonemes(phonemes, where);
    keys_ = keysOfPhonemes(phonemes, model, where);
    cues_ = cuesOf(phonemes, keys_, model);
    duration_ = phonemes.back().end;
    const std::string bytes = encodeRuntimePackage(model);
    std::string error;
    if (!package_->load(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), error))
        throwInputError(where, "runtime package: " + error);
    if (!animation_.setKeyframes(*package_, keyframesOf(phonemes, keys_, settings), settings.interpolation,
                                 error, settings.dominanceRate))
        throwInputError(where, "animation: " + error);
}

void FaceTrack::keyWeights(double t, float* out) const {
    std::fill(out, out + keyCount(), 0.0f);
    runtime::KeyWeight terms[4];
    const std::size_t count = animation_.weightsAt(t, terms);
    for (std::size_t j = 0; j < count; ++j)
        if (terms[j].key != runtime::kRestKey) out[terms[j].key] += terms[j].weight;
}

} // namespace vl
