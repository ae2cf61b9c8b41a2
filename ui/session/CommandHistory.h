#pragma once
// Undo/redo as a list of named document states. Every edit commits the complete new state under a
// name ("Paint stroke", "Set frequency of AA"); the heavy parts of a state (meshes) are shared
// immutable pointers, so a commit copies little. Consecutive commits with the same merge key
// (the drags of one slider) collapse into one undo step.
// States are held as shared immutable objects: a caller that must keep the current state alive
// across an edit (a UI frame reading it while a widget commits) pins it with currentShared().
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace vl::ui {

template <class State> class CommandHistory {
  public:
    explicit CommandHistory(State initial, std::size_t limit = 200) : limit_(limit) {
        entries_.push_back({"Initial state", share(std::move(initial)), {}, nextRevision_++});
    }

    const State& current() const { return *entries_[index_].state; }
    std::shared_ptr<const State> currentShared() const { return entries_[index_].state; }

    void commit(std::string name, State state, std::string mergeKey = {}) {
        entries_.resize(index_ + 1); // drops the redo branch
        const bool merge =
            !mergeKey.empty() && index_ > 0 && entries_[index_].mergeKey == mergeKey && savedIndex_ != index_;
        if (merge) {
            entries_[index_].state = share(std::move(state));
            entries_[index_].revision = nextRevision_++;
        } else {
            entries_.push_back(
                {std::move(name), share(std::move(state)), std::move(mergeKey), nextRevision_++});
            ++index_;
        }
        if (entries_.size() > limit_) {
            entries_.erase(entries_.begin());
            --index_;
            savedIndex_ = savedIndex_ == 0 ? kNever : savedIndex_ - 1;
        }
    }
    // Replaces the current state without a new undo step (derived data such as a re-adapted mesh).
    void amend(State state) { entries_[index_].state = share(std::move(state)); }
    // Ends merging: the next commit with the same key becomes a new step (a slider was released).
    void closeMerge() { entries_[index_].mergeKey.clear(); }

    bool canUndo() const { return index_ > 0; }
    bool canRedo() const { return index_ + 1 < entries_.size(); }
    const std::string& undoName() const { return entries_[index_].name; }
    const std::string& redoName() const { return entries_[index_ + 1].name; }
    void undo() {
        if (canUndo()) --index_;
        closeMerge();
    }
    void redo() {
        if (canRedo()) ++index_;
        closeMerge();
    }

    // Starts over with `state` as the only entry, marked as saved (after open or new).
    void reset(State state) {
        entries_.clear();
        entries_.push_back({"Initial state", share(std::move(state)), {}, nextRevision_++});
        index_ = 0;
        savedIndex_ = 0;
    }
    void markSaved() { savedIndex_ = index_; }
    // No state is the saved one (a document that exists only in memory, e.g. imported).
    void markUnsaved() { savedIndex_ = kNever; }
    bool modified() const { return savedIndex_ != index_; }
    std::size_t size() const { return entries_.size(); }
    // Numbers the current document state: it changes with every commit, undo, redo and reset,
    // but not with amend (derived data), so a background save can tell whether it is still current.
    std::uint64_t currentRevision() const { return entries_[index_].revision; }

  private:
    static constexpr std::size_t kNever = static_cast<std::size_t>(-1);
    static std::shared_ptr<const State> share(State state) {
        return std::make_shared<const State>(std::move(state));
    }
    struct Entry {
        std::string name;
        std::shared_ptr<const State> state;
        std::string mergeKey;
        std::uint64_t revision = 0;
    };
    std::vector<Entry> entries_;
    std::size_t index_ = 0;
    std::size_t savedIndex_ = 0;
    std::size_t limit_;
    std::uint64_t nextRevision_ = 1;
};

} // namespace vl::ui
