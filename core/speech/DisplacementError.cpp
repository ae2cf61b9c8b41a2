#include "core/speech/DisplacementError.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

// The distinct key displacements (key - neutral) of both faces at the mouth's vertices, in display
// units. A key the reduction left alone is the same vector in both faces: its weights cancel in the
// coefficients, so an unreduced face has exactly zero error.
struct MouthDisplacements {
    std::vector<std::vector<Vec3>> vectors;
    std::vector<std::size_t> fullIndex, reducedIndex;
};

MouthDisplacements mouthDisplacements(const FaceTrack& full, const FaceTrack& reduced,
                                      std::span<const std::size_t> mouth, double scale) {
    MouthDisplacements result;
    const std::pair<const FaceTrack*, std::vector<std::size_t>*> faces[] = {{&full, &result.fullIndex},
                                                                            {&reduced, &result.reducedIndex}};
    for (const auto& [face, indices] : faces) {
        const ReducedModel& model = face->model();
        std::vector<std::size_t>& index = *indices;
        for (const KeyMesh& key : model.keys) {
            std::vector<Vec3> d(mouth.size());
            for (std::size_t i = 0; i < mouth.size(); ++i)
                d[i] = (key.positions[mouth[i]] - model.neutral.positions[mouth[i]]) * scale;
            const auto same = std::find(result.vectors.begin(), result.vectors.end(), d);
            index.push_back(static_cast<std::size_t>(same - result.vectors.begin()));
            if (same == result.vectors.end()) result.vectors.push_back(std::move(d));
        }
    }
    return result;
}

// The blend weights of `face` at t as coefficients of the distinct displacements.
void blendCoefficients(const FaceTrack& face, const std::vector<std::size_t>& index, double t,
                       std::vector<double>& coefficients) {
    std::fill(coefficients.begin(), coefficients.end(), 0.0);
    runtime::KeyWeight blend[4];
    const std::size_t count = face.curve().weightsAt(t, blend);
    for (std::size_t j = 0; j < count; ++j)
        if (blend[j].key != runtime::kRestKey) coefficients[index[blend[j].key]] += double(blend[j].weight);
}

} // namespace

DisplacementError measureDisplacementError(const FaceTrack& full, const FaceTrack& reduced,
                                           std::span<const double> vertexWeights, double fps,
                                           const DisplacementUnit& unit) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("displacement error", "frames per second must be > 0");
    const std::size_t vertices = full.model().neutral.positions.size();
    if (reduced.model().neutral.positions.size() != vertices || vertexWeights.size() != vertices)
        throwInputError("displacement error",
                        "the full face, the reduced face and the weights differ in vertex count");
    std::vector<std::size_t> mouth;
    std::vector<double> weights;
    double totalWeight = 0;
    for (std::size_t v = 0; v < vertices; ++v)
        if (vertexWeights[v] > 0) {
            mouth.push_back(v);
            weights.push_back(vertexWeights[v]);
            totalWeight += vertexWeights[v];
        }
    if (!(totalWeight > 0))
        throwInputError("displacement error", "every vertex weight is 0: there is no mouth");
    const MouthDisplacements keys = mouthDisplacements(full, reduced, mouth, unit.scale);

    const double duration = std::max(full.duration(), reduced.duration());
    const auto frameCount = static_cast<std::size_t>(std::ceil(duration * fps - 1e-9)) + 1;
    DisplacementError error;
    error.unit = unit.name;
    error.fps = fps;
    error.rmsFrames.resize(frameCount);
    error.maxFrames.resize(frameCount);
    std::vector<Vec3> d(mouth.size());
    std::vector<double> fullCoefficients(keys.vectors.size()), reducedCoefficients(keys.vectors.size());
    double integral = 0, previousSquare = 0, previousTime = 0;
    for (std::size_t f = 0; f < frameCount; ++f) {
        const double t = std::min(double(f) / fps, duration);
        // Summed per face first: the same blend on both faces cancels exactly.
        blendCoefficients(full, keys.fullIndex, t, fullCoefficients);
        blendCoefficients(reduced, keys.reducedIndex, t, reducedCoefficients);
        std::fill(d.begin(), d.end(), Vec3(0, 0, 0));
        for (std::size_t k = 0; k < keys.vectors.size(); ++k)
            if (const double c = fullCoefficients[k] - reducedCoefficients[k]; c != 0.0)
                for (std::size_t i = 0; i < d.size(); ++i) d[i] += keys.vectors[k][i] * c;
        double square = 0, largest = 0;
        for (std::size_t i = 0; i < d.size(); ++i) {
            const double length2 = d[i].sqrnorm();
            square += weights[i] * length2;
            largest = std::max(largest, length2);
        }
        square /= totalWeight;
        error.rmsFrames[f] = std::sqrt(square);
        error.maxFrames[f] = std::sqrt(largest);
        if (error.maxFrames[f] > error.max) {
            error.max = error.maxFrames[f];
            error.maxTime = t;
        }
        if (f > 0) integral += 0.5 * (square + previousSquare) * (t - previousTime);
        previousSquare = square;
        previousTime = t;
    }
    error.rms = duration > 0 ? std::sqrt(integral / duration) : error.rmsFrames.front();
    return error;
}

} // namespace vl
