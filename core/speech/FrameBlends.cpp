#include "core/speech/FrameBlends.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl {

FrameBlends::FrameBlends(const SpeechErrorBasis& basis, const FaceTrack& full, const FaceTrack& reduced,
                         double fps, const std::string& measure)
    : basis_(basis), full_(full), reduced_(reduced), fps_(fps) {
    if (!(fps > 0) || !std::isfinite(fps)) throwInputError(measure, "frames per second must be > 0");
    if (basis.fullKeys() != full.keyCount() || basis.reducedKeys() != reduced.keyCount() ||
        basis.vertexCount() != full.model().neutral.positions.size())
        throwInputError(measure, "the error basis was made for other faces");
    duration_ = std::max(full.duration(), reduced.duration());
    frameCount_ = static_cast<std::size_t>(std::ceil(duration_ * fps - 1e-9)) + 1;
    fullCoefficients_.assign(basis.vectorCount(), 0.0);
    reducedCoefficients_.assign(basis.vectorCount(), 0.0);
}

double FrameBlends::time(std::size_t f) const {
    return std::min(double(f) / fps_, duration_);
}

void FrameBlends::load(std::size_t f) {
    const double t = time(f);
    // Summed per face first: the same blend on both faces cancels exactly. A full key adds to its
    // deviation e_k and to its partner r_p(k) (f_k = e_k + r_p(k), SpeechErrorBasis.h).
    std::fill(fullCoefficients_.begin(), fullCoefficients_.end(), 0.0);
    std::fill(reducedCoefficients_.begin(), reducedCoefficients_.end(), 0.0);
    runtime::KeyWeight blend[4];
    std::size_t count = full_.curve().weightsAt(t, blend);
    for (std::size_t j = 0; j < count; ++j) {
        if (blend[j].key == runtime::kRestKey) continue;
        const double weight = blend[j].weight;
        fullCoefficients_[basis_.fullIndex(blend[j].key)] += weight;
        if (const std::size_t partner = basis_.fullPartner(blend[j].key);
            partner != SpeechErrorBasis::kNoPartner)
            fullCoefficients_[basis_.reducedIndex(partner)] += weight;
    }
    count = reduced_.curve().weightsAt(t, blend);
    for (std::size_t j = 0; j < count; ++j)
        if (blend[j].key != runtime::kRestKey)
            reducedCoefficients_[basis_.reducedIndex(blend[j].key)] += blend[j].weight;

    std::swap(difference_, previous_);
    difference_.clear();
    motion_.clear();
    for (std::size_t k = 0; k < fullCoefficients_.size(); ++k) {
        if (const double c = fullCoefficients_[k]; c != 0.0) motion_.push_back({k, c});
        if (const double c = fullCoefficients_[k] - reducedCoefficients_[k]; c != 0.0)
            difference_.push_back({k, c});
    }
    repeats_ = f > 0 && difference_ == previous_;
    if (repeats_) return;
    differenceForm_ = gramForm(basis_, difference_);
    differenceScale_ = 0;
    for (const BasisTerm& a : difference_)
        differenceScale_ += std::abs(a.weight) * std::sqrt(basis_.gram(a.index, a.index));
}

double gramForm(const SpeechErrorBasis& basis, const std::vector<BasisTerm>& terms) {
    // G is symmetric: the diagonal once, each pair above it twice.
    double diagonal = 0, pairs = 0;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const BasisTerm& a = terms[i];
        diagonal += a.weight * a.weight * basis.gram(a.index, a.index);
        for (std::size_t j = i + 1; j < terms.size(); ++j)
            pairs += a.weight * terms[j].weight * basis.gram(a.index, terms[j].index);
    }
    return diagonal + 2.0 * pairs;
}

} // namespace vl
