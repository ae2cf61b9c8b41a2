#include "core/speech/DisplacementError.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vl {

namespace {

// One basis vector of a frame's difference d = F(t) - R(t), with its nonzero coefficient.
struct FrameTerm {
    std::size_t index;
    double weight;
    bool operator==(const FrameTerm&) const = default;
};

// The blend of a face at t as coefficients of the basis (SpeechErrorBasis.h: f_k = e_k + r_p(k)).
void addBlendCoefficients(const FaceTrack& face, double t, bool full, const SpeechErrorBasis& basis,
                          std::vector<double>& coefficients) {
    runtime::KeyWeight blend[4];
    const std::size_t count = face.curve().weightsAt(t, blend);
    for (std::size_t j = 0; j < count; ++j) {
        if (blend[j].key == runtime::kRestKey) continue;
        const double weight = blend[j].weight;
        if (!full) {
            coefficients[basis.reducedIndex(blend[j].key)] += weight;
            continue;
        }
        coefficients[basis.fullIndex(blend[j].key)] += weight;
        if (const std::size_t partner = basis.fullPartner(blend[j].key);
            partner != SpeechErrorBasis::kNoPartner)
            coefficients[basis.reducedIndex(partner)] += weight;
    }
}

struct FrameSums {
    double square = 0;  // sum_v w_v |d_v|^2 over the mouth
    double largest = 0; // max_v |d_v|^2
    std::size_t largestBlock = 0;
};

// A frame's terms with their coordinate arrays at hand.
struct FrameColumn {
    double weight;
    const double *x, *y, *z;
    std::size_t index;
};

// The largest squared length of d = sum of the columns over the kLeaf vertices from `begin` (the
// basis pads the mouth to whole leaves), and its weighted sum when `square` is given. Column by
// column over a fixed-size leaf: the sums vectorise.
double leafLargest(const std::vector<FrameColumn>& columns, std::size_t begin, const double* weights,
                   double* square) {
    constexpr std::size_t kLeaf = SpeechErrorBasis::kLeaf;
    double x[kLeaf] = {}, y[kLeaf] = {}, z[kLeaf] = {};
    for (const FrameColumn& c : columns) {
        const double w = c.weight;
        const double *cx = c.x + begin, *cy = c.y + begin, *cz = c.z + begin;
        for (std::size_t i = 0; i < kLeaf; ++i) {
            x[i] += w * cx[i];
            y[i] += w * cy[i];
            z[i] += w * cz[i];
        }
    }
    double length2[kLeaf];
    for (std::size_t i = 0; i < kLeaf; ++i) length2[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    if (square)
        for (std::size_t i = 0; i < kLeaf; ++i) *square += weights[begin + i] * length2[i];
    return *std::max_element(length2, length2 + kLeaf);
}

// The squared bound (sum_a |c_a| length_a(node))^2 of |d| over a node (SpeechErrorBasis.h).
double nodeBound(const SpeechErrorBasis& basis, const std::vector<FrameColumn>& columns, std::size_t level,
                 std::size_t node) {
    const double* lengths = basis.nodeLengths(level, node);
    double bound = 0;
    for (const FrameColumn& column : columns) bound += std::abs(column.weight) * lengths[column.index];
    return bound * bound;
}

// A frame's sums without visiting every vertex. The weighted sum is the quadratic form c^T G c of
// the basis's Gram matrix (O(terms^2)), unless it cancels to below 1e-6 of its scale
// (sum_a |c_a| sqrt(G_aa))^2, where the Gram matrix's rounding (about vertices x 1e-16 of that scale)
// could show: then every vertex is summed. The maximum starts at the leaf that held the last frame's
// (speech moves smoothly) and descends the basis's tree only into nodes whose bounds allow more.
FrameSums frameSums(const SpeechErrorBasis& basis, const std::vector<FrameTerm>& terms, std::size_t start,
                    std::vector<FrameColumn>& columns,
                    std::vector<std::pair<std::size_t, std::size_t>>& stack) {
    double form = 0, scale = 0;
    columns.clear();
    for (const FrameTerm& a : terms) {
        scale += std::abs(a.weight) * std::sqrt(basis.gram(a.index, a.index));
        for (const FrameTerm& b : terms) form += a.weight * b.weight * basis.gram(a.index, b.index);
        columns.push_back({a.weight, basis.coordinate(a.index, 0), basis.coordinate(a.index, 1),
                           basis.coordinate(a.index, 2), a.index});
    }
    const double* weights = basis.mouthWeights().data();
    FrameSums sums;
    if (form < 1e-6 * scale * scale) {
        for (std::size_t leaf = 0; leaf < basis.nodeCount(0); ++leaf) {
            const double largest = leafLargest(columns, basis.nodeFirst(0, leaf), weights, &sums.square);
            if (largest > sums.largest) sums.largest = largest, sums.largestBlock = leaf;
        }
        return sums;
    }
    sums.square = form;
    sums.largest = leafLargest(columns, basis.nodeFirst(0, start), weights, nullptr);
    sums.largestBlock = start;
    stack.assign(1, {basis.levels() - 1, 0});
    while (!stack.empty()) {
        const auto [level, node] = stack.back();
        stack.pop_back();
        if ((level == 0 && node == start) || nodeBound(basis, columns, level, node) <= sums.largest) continue;
        if (level == 0) {
            const double largest = leafLargest(columns, basis.nodeFirst(0, node), weights, nullptr);
            if (largest > sums.largest) sums.largest = largest, sums.largestBlock = node;
            continue;
        }
        const std::size_t last = std::min(basis.nodeCount(level - 1), (node + 1) * SpeechErrorBasis::kFanout);
        for (std::size_t child = node * SpeechErrorBasis::kFanout; child < last; ++child)
            stack.emplace_back(level - 1, child);
    }
    return sums;
}

} // namespace

DisplacementError measureDisplacementError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                           const FaceTrack& reduced, double fps,
                                           const DisplacementUnit& unit) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("displacement error", "frames per second must be > 0");
    if (basis.fullKeys() != full.keyCount() || basis.reducedKeys() != reduced.keyCount() ||
        basis.vertexCount() != full.model().neutral.positions.size())
        throwInputError("displacement error", "the error basis was made for other faces");
    if (!(basis.totalWeight() > 0))
        throwInputError("displacement error", "every vertex weight is 0: there is no mouth");

    const double duration = std::max(full.duration(), reduced.duration());
    const auto frameCount = static_cast<std::size_t>(std::ceil(duration * fps - 1e-9)) + 1;
    DisplacementError error;
    error.unit = unit.name;
    error.fps = fps;
    error.rmsFrames.resize(frameCount);
    error.maxFrames.resize(frameCount);
    std::vector<double> fullCoefficients(basis.vectorCount()), reducedCoefficients(basis.vectorCount());
    std::vector<FrameColumn> columns;
    std::vector<std::pair<std::size_t, std::size_t>> stack;
    std::vector<FrameTerm> terms, previous;
    FrameSums sums;
    double integral = 0, previousSquare = 0, previousTime = 0;
    for (std::size_t f = 0; f < frameCount; ++f) {
        const double t = std::min(double(f) / fps, duration);
        // Summed per face first: the same blend on both faces cancels exactly.
        std::fill(fullCoefficients.begin(), fullCoefficients.end(), 0.0);
        std::fill(reducedCoefficients.begin(), reducedCoefficients.end(), 0.0);
        addBlendCoefficients(full, t, true, basis, fullCoefficients);
        addBlendCoefficients(reduced, t, false, basis, reducedCoefficients);
        terms.clear();
        for (std::size_t k = 0; k < fullCoefficients.size(); ++k)
            if (const double c = fullCoefficients[k] - reducedCoefficients[k]; c != 0.0)
                terms.push_back({k, c});
        // A held pose repeats the frame before it exactly.
        if (f == 0 || terms != previous)
            sums = terms.empty() ? FrameSums{0, 0, sums.largestBlock}
                                 : frameSums(basis, terms, sums.largestBlock, columns, stack);
        std::swap(terms, previous);
        const double square = unit.scale * unit.scale * sums.square / basis.totalWeight();
        error.rmsFrames[f] = std::sqrt(square);
        error.maxFrames[f] = unit.scale * std::sqrt(sums.largest);
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

DisplacementError measureDisplacementError(const FaceTrack& full, const FaceTrack& reduced,
                                           std::span<const double> vertexWeights, double fps,
                                           const DisplacementUnit& unit) {
    if (!(fps > 0) || !std::isfinite(fps))
        throwInputError("displacement error", "frames per second must be > 0");
    const SpeechErrorBasis basis(full.model(), reduced.model(), vertexWeights);
    return measureDisplacementError(basis, full, reduced, fps, unit);
}

} // namespace vl
