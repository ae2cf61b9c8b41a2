#include "core/speech/DisplacementError.h"

#include "core/common/Error.h"
#include "core/speech/ErrorFrames.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vl {

DisplacementErrorFrames::DisplacementErrorFrames(const SpeechErrorBasis& basis, const FrameBlends& frames,
                                                 double fps, const DisplacementUnit& unit)
    : basis_(basis), frames_(frames), scale_(unit.scale) {
    if (!(basis.totalWeight() > 0))
        throwInputError("displacement error", "every vertex weight is 0: there is no mouth");
    error_.unit = unit.name;
    error_.fps = fps;
    error_.rmsFrames.resize(frames.frameCount());
    error_.maxFrames.resize(frames.frameCount());
}

// The largest squared length of d = sum of the columns over the kLeaf vertices from `begin` (the
// basis pads the mouth to whole leaves), and its weighted sum when `square` is given. Column by
// column over a fixed-size leaf: the sums vectorise.
double DisplacementErrorFrames::leafLargest(std::size_t begin, double* square) const {
    constexpr std::size_t kLeaf = SpeechErrorBasis::kLeaf;
    double x[kLeaf] = {}, y[kLeaf] = {}, z[kLeaf] = {};
    for (const Column& c : columns_) {
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
    if (square) {
        const double* weights = basis_.mouthWeights().data() + begin;
        for (std::size_t i = 0; i < kLeaf; ++i) *square += weights[i] * length2[i];
    }
    return *std::max_element(length2, length2 + kLeaf);
}

// The squared bounds (sum_a |c_a| length_a(node))^2 of |d| over the kFanout nodes of `level` from
// `first` (SpeechErrorBasis.h; padding nodes get 0): vector by vector over the children, which
// vectorises.
void DisplacementErrorFrames::childBounds(std::size_t level, std::size_t first,
                                          double (&bounds)[SpeechErrorBasis::kFanout]) const {
    constexpr std::size_t kFanout = SpeechErrorBasis::kFanout;
    for (double& bound : bounds) bound = 0;
    for (const Column& column : columns_) {
        const double w = std::abs(column.weight);
        const double* lengths = basis_.vectorLengths(level, column.index) + first;
        for (std::size_t i = 0; i < kFanout; ++i) bounds[i] += w * lengths[i];
    }
    for (double& bound : bounds) bound *= bound;
}

// A frame's sums without visiting every vertex. The weighted sum is the quadratic form c^T G c of
// the basis's Gram matrix (O(terms^2)), unless it cancels to below 1e-6 of its scale
// (sum_a |c_a| sqrt(G_aa))^2, where the Gram matrix's rounding (about vertices x 1e-16 of that scale)
// could show: then every vertex is summed. The maximum starts at the leaf that held the last frame's
// (speech moves smoothly) and descends the basis's tree only into nodes whose bounds allow more
// (checked again when a node is taken: the maximum may have grown since it was put aside).
DisplacementErrorFrames::Sums DisplacementErrorFrames::frameSums(std::size_t start) {
    const double form = frames_.differenceForm(), scale = frames_.differenceScale();
    columns_.clear();
    for (const BasisTerm& a : frames_.difference())
        columns_.push_back({a.weight, basis_.coordinate(a.index, 0), basis_.coordinate(a.index, 1),
                            basis_.coordinate(a.index, 2), a.index});
    Sums sums;
    if (form < 1e-6 * scale * scale) {
        for (std::size_t leaf = 0; leaf < basis_.nodeCount(0); ++leaf) {
            const double largest = leafLargest(basis_.nodeFirst(0, leaf), &sums.square);
            if (largest > sums.largest) sums.largest = largest, sums.largestLeaf = leaf;
        }
        return sums;
    }
    sums.square = form;
    sums.largest = leafLargest(basis_.nodeFirst(0, start), nullptr);
    sums.largestLeaf = start;
    stack_.clear();
    double bounds[SpeechErrorBasis::kFanout];
    const std::size_t top = basis_.levels() - 1;
    childBounds(top, 0, bounds); // the root, alone on its level
    if (top > 0 && bounds[0] > sums.largest)
        stack_.push_back({top, 0, bounds[0]}); // else the root is `start`
    while (!stack_.empty()) {
        const Pending pending = stack_.back();
        stack_.pop_back();
        if (pending.bound <= sums.largest) continue;
        if (pending.level == 0) {
            const double largest = leafLargest(basis_.nodeFirst(0, pending.node), nullptr);
            if (largest > sums.largest) sums.largest = largest, sums.largestLeaf = pending.node;
            continue;
        }
        const std::size_t level = pending.level - 1, first = pending.node * SpeechErrorBasis::kFanout;
        childBounds(level, first, bounds);
        const std::size_t count = std::min(basis_.nodeCount(level) - first, SpeechErrorBasis::kFanout);
        for (std::size_t i = 0; i < count; ++i)
            if (bounds[i] > sums.largest && !(level == 0 && first + i == start))
                stack_.push_back({level, first + i, bounds[i]});
    }
    return sums;
}

void DisplacementErrorFrames::add(std::size_t f) {
    const double t = frames_.time(f);
    // A held pose repeats the frame before it exactly.
    if (!frames_.repeats())
        sums_ = frames_.difference().empty() ? Sums{0, 0, sums_.largestLeaf} : frameSums(sums_.largestLeaf);
    const double square = scale_ * scale_ * sums_.square / basis_.totalWeight();
    error_.rmsFrames[f] = std::sqrt(square);
    error_.maxFrames[f] = scale_ * std::sqrt(sums_.largest);
    if (error_.maxFrames[f] > error_.max) {
        error_.max = error_.maxFrames[f];
        error_.maxTime = t;
    }
    if (f > 0) integral_ += 0.5 * (square + previousSquare_) * (t - previousTime_);
    previousSquare_ = square;
    previousTime_ = t;
}

DisplacementError DisplacementErrorFrames::finish() {
    const double duration = frames_.duration();
    error_.rms = duration > 0 ? std::sqrt(integral_ / duration) : error_.rmsFrames.front();
    return std::move(error_);
}

DisplacementError measureDisplacementError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                           const FaceTrack& reduced, double fps,
                                           const DisplacementUnit& unit) {
    FrameBlends frames(basis, full, reduced, fps, "displacement error");
    DisplacementErrorFrames error(basis, frames, fps, unit);
    for (std::size_t f = 0; f < frames.frameCount(); ++f) {
        frames.load(f);
        error.add(f);
    }
    return error.finish();
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
