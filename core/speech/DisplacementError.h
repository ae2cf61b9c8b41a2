#pragma once
// The utterance error as a designer measures it: how far, in millimetres, the reduced face's mouth
// vertices are from the full face's while both speak the same phonemes. At each frame the vertex
// displacement error d_v(t) = F_v(t) - R_v(t) gives
//   RMS(t) = sqrt(sum_v w_v |d_v(t)|^2 / sum_v w_v)   and   max(t) = max over w_v > 0 of |d_v(t)|,
// with w the weights the utterance error uses (core/speech/UtteranceError.h): the mouth is the
// region of nonzero weight. Over the utterance: the RMS of RMS(t) in time (trapezoid rule over
// the frames, as the utterance error's mean) and the largest max(t) with its time.
#include "core/speech/FaceTrack.h"
#include "core/speech/SpeechErrorBasis.h"

#include <span>
#include <string>
#include <vector>

namespace vl {

// How positions read as lengths: glTF is in metres (shown as mm); a mesh file has no unit.
struct DisplacementUnit {
    std::string name = "model units"; // what a reader sees after the figures
    double scale = 1.0;               // displayed length per model length
    bool operator==(const DisplacementUnit&) const = default;
};
inline DisplacementUnit millimetresFromMetres() {
    return {"mm", 1000.0};
}

struct DisplacementError {
    std::string unit;              // DisplacementUnit::name of every figure below
    double fps = 0;                // of the frames, the utterance error's frames
    std::vector<double> rmsFrames; // RMS(t) at t = f / fps (last at the end)
    std::vector<double> maxFrames; // max(t)
    double rms = 0;
    double max = 0;
    double maxTime = 0; // seconds
};

// `full` and `reduced` speak the same phonemes on faces with the same neutral mesh; one weight per
// vertex. Throws InputError for mismatched sizes, fps <= 0 or weights that are all 0.
DisplacementError measureDisplacementError(const FaceTrack& full, const FaceTrack& reduced,
                                           std::span<const double> vertexWeights, double fps,
                                           const DisplacementUnit& unit);
// The same with the faces' basis made once (SpeechErrorBasis.h: many utterances on one face). Throws
// InputError when `basis` was made for faces of other key or vertex counts.
DisplacementError measureDisplacementError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                           const FaceTrack& reduced, double fps,
                                           const DisplacementUnit& unit);

} // namespace vl
