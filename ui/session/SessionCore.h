#pragma once
// What every facet of the editor's session (SessionFiles, SessionFace, ...) edits through: the
// document in its undo history, the memoized inputs derived from it (DocumentInputs), the status
// messages, the selected viseme and the revisions views key on. A facet holds this, never the whole
// session. Each edit is a validated command of the core (core/document/Commands.h) committed as one
// undo step only when it applied, so bad input changes nothing.
#include "core/document/Document.h"
#include "core/document/DocumentInputs.h"
#include "ui/session/CommandHistory.h"
#include "ui/session/StatusMessages.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vl::ui {

class SessionCore {
  public:
    using DocumentPtr = std::shared_ptr<const Document>;
    SessionCore();

    const Document& document() const { return history_.current(); }
    DocumentPtr documentShared() const { return history_.currentShared(); }
    // The memoized weights, frequencies and per-part revisions of the current document.
    const DocumentInputs& inputs() const { return inputs_; }
    // A reduction curve computed for inputs of revision `inputsRevision` (DocumentInputs::setCurve).
    void setCurve(std::shared_ptr<const ReductionResult> curve, std::uint64_t inputsRevision) {
        inputs_.setCurve(std::move(curve), inputsRevision);
    }
    StatusMessages& messages() { return messages_; }
    const StatusMessages& messages() const { return messages_; }

    // Commits `next` as an undo step named `name`; `mergeKey` collapses a slider drag into one step.
    void commit(std::string name, Document next, std::string mergeKey = {});
    // Replaces the current document without an undo step (derived data: a re-adapted mesh).
    void amend(Document next);
    // A new document (opened, loaded, imported) in a fresh history; `unsaved` marks one that exists
    // only in memory.
    void replace(Document next, bool unsaved);
    void undo();
    void redo();
    bool canUndo() const { return history_.canUndo(); }
    bool canRedo() const { return history_.canRedo(); }
    std::string undoName() const { return canUndo() ? history_.undoName() : std::string(); }
    std::string redoName() const { return canRedo() ? history_.redoName() : std::string(); }
    bool modified() const { return history_.modified(); }
    // Numbers the current document state: changes with every edit, undo and redo (not with amend).
    std::uint64_t revision() const { return history_.currentRevision(); }
    // Ends the current slider drag so the next change is a separate undo step.
    void endEdit() { history_.closeMerge(); }
    void markSaved() { history_.markSaved(); }

    // Changes when the document is replaced (new, open, sample, folder, import) or its subject is
    // built anew (Generate viseme set from face, Use my mesh): views drop their state of the old one.
    std::uint64_t documentEpoch() const { return documentEpoch_; }
    // A new document begins: the epoch changes, the selection clears, and each facet drops what it
    // held of the old one (onNewDocument). Called on every replacement, before it is current.
    void beginNewDocument();
    void onNewDocument(std::function<void()> drop) { newDocument_.push_back(std::move(drop)); }
    // Changes whenever the mesh set changes (renderers re-upload when it differs).
    std::uint64_t geometryRevision() const { return geometryRevision_; }

    // --- view state (not part of the document, not undoable): the selected viseme ---
    int selectedViseme() const { return selectedViseme_; }
    void selectViseme(int index) { selectedViseme_ = index; }
    // Selects viseme `name` (after an edit moved it), or nothing when it is gone or empty.
    void selectViseme(const std::string& name);
    std::string selectedVisemeName() const; // "" when none

    // Starts a UI frame: documents replaced during the previous frame may be released now. Every
    // reference into document() taken during a frame stays valid until the next beginFrame(), even
    // when a widget commits an edit in between (panels read the document, then edit it).
    void beginFrame() { frameDocuments_.clear(); }

  private:
    // Keeps the current document alive until the next beginFrame(); returns it.
    const Document& retireCurrent();
    void noteChange(const Document& before);

    CommandHistory<Document> history_;
    DocumentInputs inputs_;
    StatusMessages messages_;
    std::vector<DocumentPtr> frameDocuments_; // documents replaced this frame
    std::uint64_t documentEpoch_ = 1;
    std::uint64_t geometryRevision_ = 1;
    int selectedViseme_ = -1;
    std::vector<std::function<void()>> newDocument_;
};

} // namespace vl::ui
