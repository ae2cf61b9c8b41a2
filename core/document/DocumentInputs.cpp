#include "core/document/DocumentInputs.h"

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

} // namespace vl
