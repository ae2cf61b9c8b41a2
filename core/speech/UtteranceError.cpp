#include "core/speech/UtteranceError.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

struct Term {
    std::size_t index; // into the Gram matrix
    double weight;
};

// Adds the blend of `face` at t with `sign`, one term per basis vector (SpeechErrorBasis.h).
void addBlend(const FaceTrack& face, double t, const SpeechErrorBasis& basis, bool full, double sign,
              std::vector<Term>& terms) {
    runtime::KeyWeight blend[4];
    const std::size_t count = face.curve().weightsAt(t, blend);
    auto add = [&terms](std::size_t at, double weight) {
        const auto same =
            std::find_if(terms.begin(), terms.end(), [&](const Term& term) { return term.index == at; });
        if (same != terms.end())
            same->weight += weight;
        else
            terms.push_back({at, weight});
    };
    for (std::size_t j = 0; j < count; ++j) {
        if (blend[j].key == runtime::kRestKey) continue;
        const double weight = sign * double(blend[j].weight);
        if (!full) {
            add(basis.reducedIndex(blend[j].key), weight);
            continue;
        }
        add(basis.fullIndex(blend[j].key), weight); // f_k = e_k + r_p(k) (SpeechErrorBasis.h)
        if (const std::size_t partner = basis.fullPartner(blend[j].key);
            partner != SpeechErrorBasis::kNoPartner)
            add(basis.reducedIndex(partner), weight);
    }
}

double quadraticForm(const SpeechErrorBasis& basis, const std::vector<Term>& terms) {
    double sum = 0;
    for (const Term& a : terms)
        for (const Term& b : terms) sum += a.weight * b.weight * basis.gram(a.index, b.index);
    return std::max(sum, 0.0); // rounding may make a zero distance slightly negative
}

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

UtteranceError measureUtteranceError(const FaceTrack& full, const FaceTrack& reduced,
                                     std::span<const double> vertexWeights, double fps) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("utterance error", "frames per second must be > 0");
    return measureUtteranceError(SpeechErrorBasis(full.model(), reduced.model(), vertexWeights), full,
                                 reduced, fps);
}

UtteranceError measureUtteranceError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                     const FaceTrack& reduced, double fps) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("utterance error", "frames per second must be > 0");
    if (basis.fullKeys() != full.keyCount() || basis.reducedKeys() != reduced.keyCount() ||
        basis.vertexCount() != full.model().neutral.positions.size())
        throwInputError("utterance error", "the error basis was made for other faces");

    const double duration = std::max(full.duration(), reduced.duration());
    const auto frameCount = static_cast<std::size_t>(std::ceil(duration * fps - 1e-9)) + 1;
    UtteranceError error;
    error.fps = fps;
    error.frames.resize(frameCount);
    std::vector<double> motion(frameCount), times(frameCount);
    std::vector<Term> terms;
    for (std::size_t f = 0; f < frameCount; ++f) {
        const double t = std::min(double(f) / fps, duration);
        times[f] = t;
        terms.clear();
        addBlend(full, t, basis, true, 1.0, terms);
        motion[f] = quadraticForm(basis, terms);
        addBlend(reduced, t, basis, false, -1.0, terms);
        error.frames[f] = quadraticForm(basis, terms);
        if (error.frames[f] > error.max) {
            error.max = error.frames[f];
            error.maxTime = t;
        }
    }
    error.mean = timeAverage(error.frames, times);
    error.motion = timeAverage(motion, times);
    error.relative = error.motion > 0 ? error.mean / error.motion : 0.0;
    return error;
}

} // namespace vl
