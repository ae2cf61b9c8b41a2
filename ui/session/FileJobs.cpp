#include "ui/session/FileJobs.h"

#include "core/common/Error.h"

#include <utility>

namespace vl::ui {

namespace {

// Runs `work` unless a job of its kind still runs.
template <class Result, class Work>
void startJob(BackgroundTask<Result>& task, std::string label, const char* kind, const char* busy,
              Work work) {
    if (task.running()) throwInputError(kind, busy);
    task.start(std::move(label), [work = std::move(work)](const auto&) { return work(); });
}

// A finished message job: its message, or its error named by its label.
void collectMessage(BackgroundTask<std::string>& task, FileJobs::Finished& finished) {
    if (auto outcome = task.take()) {
        if (outcome->index() == 0)
            finished.infos.push_back(std::move(std::get<0>(*outcome)));
        else
            finished.errors.push_back(task.label() + ": " + std::get<1>(*outcome));
    }
}

} // namespace

void FileJobs::load(std::string label, std::function<LoadedDocument()> read) {
    if (load_.running()) throwInputError(label, "another file is still loading");
    load_.start(std::move(label), [read = std::move(read)](const auto&) { return read(); });
}

void FileJobs::save(std::string label, std::uint64_t documentRevision, std::function<void()> then,
                    std::function<std::filesystem::path()> write) {
    startJob(save_, std::move(label), "save", "a save is still running", std::move(write));
    saveRevision_ = documentRevision;
    afterSave_ = std::move(then);
}

void FileJobs::exportModel(std::string label, std::function<std::string()> write) {
    startJob(model_, std::move(label), "export", "an export is still running", std::move(write));
}

void FileJobs::exportAvatar(std::string label, std::function<std::string()> write) {
    startJob(avatar_, std::move(label), "export avatar", "an export is still running", std::move(write));
}

FileJobs::Finished FileJobs::poll() {
    Finished finished;
    if (auto outcome = load_.take()) {
        if (outcome->index() == 0)
            finished.loaded = std::move(std::get<0>(*outcome));
        else
            finished.errors.push_back(load_.label() + ": " + std::get<1>(*outcome));
    }
    if (auto outcome = save_.take()) {
        auto then = std::exchange(afterSave_, nullptr);
        if (outcome->index() == 0) {
            finished.saved = std::move(std::get<0>(*outcome));
            finished.savedRevision = saveRevision_;
            finished.afterSave = std::move(then);
        } else {
            finished.errors.push_back(save_.label() + ": " + std::get<1>(*outcome));
        }
    }
    collectMessage(model_, finished);
    if (auto outcome = avatar_.take()) { // its message lists the keys: the session keeps it
        if (outcome->index() == 0)
            finished.avatarExported = std::move(std::get<0>(*outcome));
        else
            finished.errors.push_back(avatar_.label() + ": " + std::get<1>(*outcome));
    }
    return finished;
}

void FileJobs::wait() {
    load_.wait();
    save_.wait();
    model_.wait();
    avatar_.wait();
}

} // namespace vl::ui
