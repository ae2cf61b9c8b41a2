#pragma once
// What derives from a document, memoized, and the revisions a cache of derived data keys on. The
// owner tells it every new document with the parts that changed (changedParts, Document.h): each
// part gets a new revision, and only what depends on those parts is dropped and evaluated again on
// first use (Blender's depsgraph does the same: tag what changed, then re-evaluate its dependents).
// A slider tick (kFaceParameterPart) keeps the weights, the frequencies and every revision but the
// parameters'; a frequency edit keeps the weights. Keyed by change tags and revisions, never by
// addresses. The reduction curve is the one input computed elsewhere (a background run, or the
// record of a loaded project): its owner pushes it here with the revision it was computed for, and
// the groupings and reduced models every view and the speech preview read derive from it here.
#include "core/document/Document.h"
#include "core/reduce/ReducedModel.h"

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

    // The reduction curve computed for reduction inputs of revision `inputsRevision` (ignored when
    // that is not the current reductionRevision(): the inputs changed while it ran).
    void setCurve(std::shared_ptr<const ReductionResult> curve, std::uint64_t inputsRevision);
    // The curve if it was computed for the current reduction inputs, else null. A recorded curve
    // may stop before p = n (a project records p = 1..m).
    const ReductionResult* curve() const;
    // Numbers every curve set so far (1, 2, ...; 0 = none): what derives from the curve keys on it.
    std::uint64_t curveRevision() const { return curve_.revision; }
    // The current curve's grouping into document().target groups, or null.
    const Grouping* grouping() const;
    // The reduced model of grouping() (merged keys, frequency-weighted means (eq. 19), phoneme ->
    // key), memoized by the curve's and the target's revisions; null without a grouping. Throws
    // InputError when it cannot be built (e.g. the phoneme map names a viseme the set lacks).
    const ReducedModel* reducedModel() const;
    // Every viseme its own key with the document's frequencies (the unreduced side of a
    // comparison), memoized by the viseme and frequency revisions. Throws InputError as above.
    const ReducedModel& fullModel() const;

  private:
    static constexpr std::size_t kParts = 9; // bits of kAllDocumentParts
    static_assert(kAllDocumentParts == (1u << kParts) - 1);
    DocumentPtr document_;
    std::uint64_t lastRevision_ = 0;
    std::array<std::uint64_t, kParts> revisions_{}; // per part bit
    mutable std::optional<std::vector<double>> weights_, frequencies_;
    mutable std::uint64_t evaluations_ = 0;
    struct Curve {
        std::shared_ptr<const ReductionResult> result;
        std::uint64_t inputsRevision = 0; // of the reduction inputs it was computed for
        std::uint64_t revision = 0;       // curveRevision()
    };
    Curve curve_;
    // A model with the revisions it was built for: rebuilt on first use after they change, so a
    // reference taken before an edit in the same frame stays valid until then.
    struct Memo {
        std::optional<ReducedModel> model;
        std::uint64_t keyA = 0, keyB = 0;
    };
    mutable Memo reduced_, full_;
};

} // namespace vl
