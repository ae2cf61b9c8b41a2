#pragma once
// Both speech error measures of one utterance in one pass over its frames: what `say`, `batch` and
// the editor's Say panel report. Each frame's blends are evaluated once for both (FrameBlends.h).
#include "core/speech/DisplacementError.h"
#include "core/speech/UtteranceError.h"

namespace vl {

struct SpeechErrors {
    UtteranceError utterance;       // as measureUtteranceError gives it
    DisplacementError displacement; // as measureDisplacementError gives it
};

// Throws InputError as the two measures do.
SpeechErrors measureSpeechErrors(const SpeechErrorBasis& basis, const FaceTrack& full,
                                 const FaceTrack& reduced, double fps, const DisplacementUnit& unit);

} // namespace vl
