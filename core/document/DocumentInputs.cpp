#include "core/document/DocumentInputs.h"

#include "core/common/Error.h"
#include "core/project/ReduceInputs.h"

#include <algorithm>

namespace vl {

void DocumentInputs::reset(DocumentPtr document) {
    document_ = std::move(document);
    revisions_.fill(++lastRevision_);
    weights_.reset();
    frequencies_.reset();
}

void DocumentInputs::update(DocumentPtr document, DocumentParts changed) {
    document_ = std::move(document);
    if (changed == 0) return;
    ++lastRevision_;
    for (std::size_t bit = 0; bit < kParts; ++bit)
        if (changed & (1u << bit)) revisions_[bit] = lastRevision_;
    // What each derived value depends on: the weights on the neutral mesh and the weight settings,
    // the frequencies on the viseme names and the table.
    if (changed & (kVisemePart | kWeightPart)) weights_.reset();
    if (changed & (kVisemePart | kFrequencyPart)) frequencies_.reset();
}

std::uint64_t DocumentInputs::revision(DocumentParts parts) const {
    std::uint64_t revision = 0;
    for (std::size_t bit = 0; bit < kParts; ++bit)
        if (parts & (1u << bit)) revision = std::max(revision, revisions_[bit]);
    return revision;
}

const std::vector<double>& DocumentInputs::weights() const {
    if (!weights_) {
        weights_ = documentWeights(*document_);
        ++evaluations_;
    }
    return *weights_;
}

const std::vector<double>& DocumentInputs::frequencies() const {
    if (!frequencies_) {
        frequencies_ = documentFrequencies(*document_);
        ++evaluations_;
    }
    return *frequencies_;
}

void DocumentInputs::setCurve(std::shared_ptr<const ReductionResult> curve, std::uint64_t inputsRevision) {
    if (!curve || inputsRevision != reductionRevision()) return;
    curve_ = {std::move(curve), inputsRevision, curve_.revision + 1};
}

const ReductionResult* DocumentInputs::curve() const {
    return curve_.result && curve_.inputsRevision == reductionRevision() ? curve_.result.get() : nullptr;
}

const Grouping* DocumentInputs::grouping() const {
    const ReductionResult* current = curve();
    const int m = document_->target;
    if (!current || m < 1 || m > static_cast<int>(current->curve.size())) return nullptr;
    return &current->curve[static_cast<std::size_t>(m - 1)];
}

const ReducedModel* DocumentInputs::reducedModel() const {
    const Grouping* groups = grouping();
    if (!groups || !document_->visemes) return nullptr;
    // The curve's revision covers the reduction inputs (a new curve for new inputs), the target's
    // which of its groupings.
    const std::uint64_t target = revision(kTargetPart);
    if (!reduced_.model || reduced_.keyA != curve_.revision || reduced_.keyB != target) {
        reduced_.model.reset();
        reduced_.model = vl::reducedModel({document_->visemes, document_->frequencies, {}}, groups,
                                          ReducePolicy::interactive());
        reduced_.keyA = curve_.revision;
        reduced_.keyB = target;
    }
    return &*reduced_.model;
}

const ReducedModel& DocumentInputs::fullModel() const {
    const std::uint64_t visemes = revision(kVisemePart), frequencies = revision(kFrequencyPart);
    if (!document_->visemes) throwInputError("document", "no viseme set");
    if (!full_.model || full_.keyA != visemes || full_.keyB != frequencies) {
        full_.model.reset();
        full_.model = unreducedModelOf({document_->visemes, document_->frequencies, {}});
        full_.keyA = visemes;
        full_.keyB = frequencies;
    }
    return *full_.model;
}

} // namespace vl
