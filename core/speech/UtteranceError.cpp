#include "core/speech/UtteranceError.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

// The distinct key displacements (key - neutral) of both faces. A key the reduction left alone is
// the same vector in both faces: sharing it makes its terms cancel exactly instead of up to
// rounding.
struct Displacements {
    std::vector<std::vector<double>> vectors;
    std::vector<std::size_t> fullIndex, reducedIndex;
};

Displacements displacements(const FaceTrack& full, const FaceTrack& reduced) {
    Displacements result;
    for (const FaceTrack* face : {&full, &reduced}) {
        const ReducedModel& model = face->model();
        const std::vector<Vec3>& neutral = model.neutral.positions;
        auto& index = face == &full ? result.fullIndex : result.reducedIndex;
        for (const KeyMesh& key : model.keys) {
            std::vector<double> d(3 * neutral.size());
            for (std::size_t v = 0; v < neutral.size(); ++v)
                for (std::size_t c = 0; c < 3; ++c) d[3 * v + c] = key.positions[v][c] - neutral[v][c];
            const auto same = std::find(result.vectors.begin(), result.vectors.end(), d);
            index.push_back(static_cast<std::size_t>(same - result.vectors.begin()));
            if (same == result.vectors.end()) result.vectors.push_back(std::move(d));
        }
    }
    return result;
}

// G[a][b] = sum_v w_v <d_a(v), d_b(v)>.
std::vector<double> weightedGram(const std::vector<std::vector<double>>& d, std::span<const double> weights) {
    const std::size_t keys = d.size();
    std::vector<double> gram(keys * keys);
    for (std::size_t a = 0; a < keys; ++a)
        for (std::size_t b = a; b < keys; ++b) {
            double sum = 0;
            for (std::size_t v = 0; v < weights.size(); ++v)
                for (std::size_t c = 0; c < 3; ++c) sum += weights[v] * d[a][3 * v + c] * d[b][3 * v + c];
            gram[a * keys + b] = gram[b * keys + a] = sum;
        }
    return gram;
}

struct Term {
    std::size_t index; // into the Gram matrix
    double weight;
};

// Adds the blend of `face` at t with `sign`, one term per distinct displacement.
void addBlend(const FaceTrack& face, double t, const std::vector<std::size_t>& index, double sign,
              std::vector<Term>& terms) {
    runtime::KeyWeight blend[4];
    const std::size_t count = face.curve().weightsAt(t, blend);
    for (std::size_t j = 0; j < count; ++j) {
        if (blend[j].key == runtime::kRestKey) continue;
        const std::size_t at = index[blend[j].key];
        const double weight = sign * double(blend[j].weight);
        const auto same =
            std::find_if(terms.begin(), terms.end(), [&](const Term& term) { return term.index == at; });
        if (same != terms.end())
            same->weight += weight;
        else
            terms.push_back({at, weight});
    }
}

double quadraticForm(const std::vector<double>& gram, std::size_t keys, const std::vector<Term>& terms) {
    double sum = 0;
    for (const Term& a : terms)
        for (const Term& b : terms) sum += a.weight * b.weight * gram[a.index * keys + b.index];
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
    const std::size_t vertices = full.model().neutral.positions.size();
    if (reduced.model().neutral.positions.size() != vertices || vertexWeights.size() != vertices)
        throwInputError("utterance error",
                        "the full face, the reduced face and the weights differ in vertex count");
    const Displacements d = displacements(full, reduced);
    const std::size_t keys = d.vectors.size();
    const std::vector<double> gram = weightedGram(d.vectors, vertexWeights);

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
        addBlend(full, t, d.fullIndex, 1.0, terms);
        motion[f] = quadraticForm(gram, keys, terms);
        addBlend(reduced, t, d.reducedIndex, -1.0, terms);
        error.frames[f] = quadraticForm(gram, keys, terms);
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
