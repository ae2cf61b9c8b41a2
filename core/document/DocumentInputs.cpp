#include "core/document/DocumentInputs.h"

namespace vl {

void DocumentInputs::reset(DocumentPtr document) {
    document_ = std::move(document);
    ++revision_;
    weights_.reset();
    frequencies_.reset();
}

void DocumentInputs::update(DocumentPtr document, DocumentParts changed) {
    document_ = std::move(document);
    // What each derived value depends on: the weights on the neutral mesh and the weight settings,
    // the frequencies on the viseme names and the table.
    if (changed & (kVisemePart | kWeightPart)) weights_.reset();
    if (changed & (kVisemePart | kFrequencyPart)) frequencies_.reset();
    if (changed & (kVisemePart | kFrequencyPart | kWeightPart | kReductionPart)) ++revision_;
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
