#pragma once
// What derives from a document's reduction inputs, memoized: the per-vertex weights and the
// normalised viseme frequencies, and a revision that changes exactly when the reduction's inputs
// do. The owner tells it every new document with the parts that changed (changedParts, Document.h);
// only what depends on those parts is dropped, and evaluated again on first use: a slider tick
// (kFaceParameterPart) keeps everything, a frequency edit keeps the weights. Keyed by change tags
// and revisions, never by addresses.
#include "core/document/Document.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vl {

class DocumentInputs {
  public:
    using DocumentPtr = std::shared_ptr<const Document>;
    // Held, not copied (a document is immutable): the history's own.
    explicit DocumentInputs(DocumentPtr document) { reset(std::move(document)); }

    // A new document (opened, loaded): everything is evaluated again, under a new revision.
    void reset(DocumentPtr document);
    // The current document after an edit, undo or redo that changed `changed` (changedParts).
    void update(DocumentPtr document, DocumentParts changed);

    // Numbers the reduction curve's inputs (meshes, frequencies, weights, constraints, rest model;
    // not the target, which picks a grouping of the curve): equal revisions, equal inputs.
    std::uint64_t revision() const { return revision_; }
    // documentWeights / documentFrequencies of the current document (throw InputError when invalid).
    const std::vector<double>& weights() const;
    const std::vector<double>& frequencies() const;
    // How many times weights or frequencies were computed (tests: a slider drag computes none).
    std::uint64_t evaluations() const { return evaluations_; }

  private:
    DocumentPtr document_;
    std::uint64_t revision_ = 1;
    mutable std::optional<std::vector<double>> weights_, frequencies_;
    mutable std::uint64_t evaluations_ = 0;
};

} // namespace vl
