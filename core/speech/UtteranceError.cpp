#include "core/speech/UtteranceError.h"

#include "core/common/Error.h"
#include "core/speech/ErrorFrames.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vl {

namespace {

// (1/T) * integral by the trapezoid rule over samples at `times`.
double timeAverage(const std::vector<double>& values, const std::vector<double>& times) {
    const double duration = times.back() - times.front();
    if (!(duration > 0)) return values.front();
    double integral = 0;
    for (std::size_t f = 1; f < values.size(); ++f)
        integral += 0.5 * (values[f] + values[f - 1]) * (times[f] - times[f - 1]);
    return integral / duration;
}

} // namespace

UtteranceErrorFrames::UtteranceErrorFrames(const SpeechErrorBasis& basis, const FrameBlends& frames,
                                           double fps)
    : basis_(basis), frames_(frames), motion_(frames.frameCount()), times_(frames.frameCount()) {
    error_.fps = fps;
    error_.frames.resize(frames.frameCount());
}

void UtteranceErrorFrames::add(std::size_t f) {
    const double t = frames_.time(f);
    times_[f] = t;
    // Rounding may make a zero distance slightly negative.
    motion_[f] = std::max(gramForm(basis_, frames_.motion()), 0.0);
    error_.frames[f] = frames_.repeats() ? error_.frames[f - 1] : std::max(frames_.differenceForm(), 0.0);
    if (error_.frames[f] > error_.max) {
        error_.max = error_.frames[f];
        error_.maxTime = t;
    }
}

UtteranceError UtteranceErrorFrames::finish() {
    error_.mean = timeAverage(error_.frames, times_);
    error_.motion = timeAverage(motion_, times_);
    error_.relative = error_.motion > 0 ? error_.mean / error_.motion : 0.0;
    return std::move(error_);
}

UtteranceError measureUtteranceError(const FaceTrack& full, const FaceTrack& reduced,
                                     std::span<const double> vertexWeights, double fps) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("utterance error", "frames per second must be > 0");
    return measureUtteranceError(SpeechErrorBasis(full.model(), reduced.model(), vertexWeights), full,
                                 reduced, fps);
}

UtteranceError measureUtteranceError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                     const FaceTrack& reduced, double fps) {
    FrameBlends frames(basis, full, reduced, fps, "utterance error");
    UtteranceErrorFrames error(basis, frames, fps);
    for (std::size_t f = 0; f < frames.frameCount(); ++f) {
        frames.load(f);
        error.add(f);
    }
    return error.finish();
}

} // namespace vl
