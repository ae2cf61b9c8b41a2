#include "ui/session/SessionCore.h"

namespace vl::ui {

SessionCore::SessionCore() : history_(Document{}), inputs_(history_.currentShared()) {}

const Document& SessionCore::retireCurrent() {
    frameDocuments_.push_back(history_.currentShared());
    return *frameDocuments_.back();
}

// The memoized inputs, the selection and the facets follow the document that is current now.
void SessionCore::noteChange(const Document& before) {
    inputs_.update(history_.currentShared(), changedParts(before, document()));
    if (before.visemes != document().visemes) {
        ++geometryRevision_;
        if (selectedViseme_ >= static_cast<int>(document().visemeCount())) selectedViseme_ = -1;
    }
}

void SessionCore::commit(std::string name, Document next, std::string mergeKey) {
    const Document& before = retireCurrent();
    history_.commit(std::move(name), std::move(next), std::move(mergeKey));
    noteChange(before);
}

void SessionCore::amend(Document next) {
    const Document& before = retireCurrent();
    history_.amend(std::move(next));
    noteChange(before);
}

void SessionCore::replace(Document next, bool unsaved) {
    retireCurrent();
    history_.reset(std::move(next));
    if (unsaved) history_.markUnsaved();
    inputs_.reset(history_.currentShared()); // new revisions: a new document never reuses an old curve
    ++geometryRevision_;
    if (selectedViseme_ >= static_cast<int>(document().visemeCount())) selectedViseme_ = -1;
}

void SessionCore::undo() {
    if (!history_.canUndo()) return;
    const std::string name = history_.undoName();
    const Document& before = retireCurrent();
    history_.undo();
    noteChange(before);
    messages_.info("Undo: " + name);
}

void SessionCore::redo() {
    if (!history_.canRedo()) return;
    const Document& before = retireCurrent();
    history_.redo();
    noteChange(before);
    messages_.info("Redo: " + history_.undoName());
}

void SessionCore::beginNewDocument() {
    ++documentEpoch_;
    selectedViseme_ = -1;
    for (const auto& drop : newDocument_) drop();
}

void SessionCore::selectViseme(const std::string& name) {
    selectedViseme_ = document().visemes && !name.empty() ? document().visemes->find(name) : -1;
}

std::string SessionCore::selectedVisemeName() const {
    const VisemeSet* set = document().visemes.get();
    return set && selectedViseme_ >= 0 && selectedViseme_ < static_cast<int>(set->size())
               ? set->visemes[static_cast<std::size_t>(selectedViseme_)].name
               : std::string();
}

} // namespace vl::ui
