#include "core/speech/SpeechErrors.h"

#include "core/speech/ErrorFrames.h"

namespace vl {

SpeechErrors measureSpeechErrors(const SpeechErrorBasis& basis, const FaceTrack& full,
                                 const FaceTrack& reduced, double fps, const DisplacementUnit& unit) {
    FrameBlends frames(basis, full, reduced, fps, "speech error");
    UtteranceErrorFrames utterance(basis, frames, fps);
    DisplacementErrorFrames displacement(basis, frames, fps, unit);
    for (std::size_t f = 0; f < frames.frameCount(); ++f) {
        frames.load(f);
        utterance.add(f);
        displacement.add(f);
    }
    return {utterance.finish(), displacement.finish()};
}

} // namespace vl
