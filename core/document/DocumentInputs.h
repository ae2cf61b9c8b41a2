#pragma once
// What derives from a document, memoized, and the revisions a cache of derived data keys on. The
// owner tells it every new document with the parts that changed (changedParts, Document.h): each
// part gets a new revision, and only what depends on those parts is dropped and evaluated again on
// first use (Blender's depsgraph does the same: tag what changed, then re-evaluate its dependents).
// A slider tick (kFaceParameterPart) keeps the weights, the frequencies and every revision but the
// parameters'; a frequency edit keeps the weights. Keyed by change tags and revisions, never by
// addresses.
#include "core/document/Document.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vl {

class DocumentInputs {
  public:
    using DocumentPtr = std::shared_ptr<const Document>;
    // The parts the reduction curve depends on: meshes, frequencies, weights, constraints and rest
    // model (not the target, which picks a grouping of the curve).
    static constexpr DocumentParts kReductionInputs =
        kVisemePart | kFrequencyPart | kWeightPart | kReductionPart;

    // Held, not copied (a document is immutable): the history's own.
    explicit DocumentInputs(DocumentPtr document) { reset(std::move(document)); }

    // A new document (opened, loaded): everything is evaluated again, under new revisions.
    void reset(DocumentPtr document);
    // The current document after an edit, undo or redo that changed `changed` (changedParts).
    void update(DocumentPtr document, DocumentParts changed);

    // A number that changes whenever any of `parts` changes (and on reset): equal revisions, equal
    // parts. Revisions only grow, so that of several parts is the largest of theirs.
    std::uint64_t revision(DocumentParts parts) const;
    // revision(kReductionInputs): equal revisions, equal reduction inputs.
    std::uint64_t reductionRevision() const { return revision(kReductionInputs); }
    // documentWeights / documentFrequencies of the current document (throw InputError when invalid).
    const std::vector<double>& weights() const;
    const std::vector<double>& frequencies() const;
    // How many times weights or frequencies were computed (tests: a slider drag computes none).
    std::uint64_t evaluations() const { return evaluations_; }

  private:
    static constexpr std::size_t kParts = 9; // bits of kAllDocumentParts
    static_assert(kAllDocumentParts == (1u << kParts) - 1);
    DocumentPtr document_;
    std::uint64_t lastRevision_ = 0;
    std::array<std::uint64_t, kParts> revisions_{}; // per part bit
    mutable std::optional<std::vector<double>> weights_, frequencies_;
    mutable std::uint64_t evaluations_ = 0;
};

} // namespace vl
