#pragma once
// The editor's file jobs on worker threads, like ReductionService for the reduction: loading a
// document (project, folder, sample, avatar), saving a project snapshot, and exporting (the reduced
// model in any format, or an avatar). One job of each kind runs at a time. The session hands in the
// work (what to read or write, from a snapshot taken when it asks) and applies what poll() reports.
#include "core/document/Document.h"
#include "ui/session/BackgroundTask.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

// A document read from files, ready to replace the session's.
struct LoadedDocument {
    LoadedProject project;
    std::filesystem::path path; // empty = untitled
    std::string message;
    bool unsaved = false; // exists only in memory (imported): modified until saved
};

class FileJobs {
  public:
    // What finished since the last poll(), for the session to apply.
    struct Finished {
        std::optional<LoadedDocument> loaded;       // becomes the session's document
        std::optional<std::filesystem::path> saved; // the file a save wrote ...
        std::uint64_t savedRevision = 0;            // ... from the document with this history revision
        std::function<void()> afterSave;            // the action held back until that save
        std::vector<std::string> infos, errors;     // messages; errors name the job
        std::optional<std::string> avatarExported;  // a finished avatar export's message
    };

    // Each throws InputError naming the job when one of its kind still runs.
    void load(std::string label, std::function<LoadedDocument()> read);
    // `write` writes the snapshot it holds and returns the file; `documentRevision` is the history revision
    // of the document the snapshot was taken from, `then` runs in the session when the save recorded it.
    void save(std::string label, std::uint64_t documentRevision, std::function<void()> then,
              std::function<std::filesystem::path()> write);
    // `write` writes and returns the message that says what it wrote.
    void exportModel(std::string label, std::function<std::string()> write);
    void exportAvatar(std::string label, std::function<std::string()> write);

    bool loading() const { return load_.running(); }
    // Drops a load (open, import, folder) at once: its result is never applied.
    void cancelLoad() { load_.requestCancel(); }
    std::string loadingLabel() const { return load_.label(); }
    bool saving() const { return save_.running(); }
    std::string savingLabel() const { return save_.label(); }
    bool exporting() const { return model_.running() || avatar_.running(); }
    std::string exportingLabel() const { return model_.running() ? model_.label() : avatar_.label(); }

    Finished poll();
    void wait(); // until every running job ended (tests, the screenshot mode)

  private:
    BackgroundTask<LoadedDocument> load_;
    BackgroundTask<std::filesystem::path> save_;
    std::uint64_t saveRevision_ = 0;
    std::function<void()> afterSave_;
    BackgroundTask<std::string> model_;  // its result is the message to show
    BackgroundTask<std::string> avatar_; // its result is the message to show
};

} // namespace vl::ui
