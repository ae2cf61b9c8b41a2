// The file jobs service on its own: one job of each kind at a time, and poll() hands back what
// finished for the session to apply (a loaded document, a save with the id of the document it
// wrote and the action held back for it, export messages, errors named by their job).
#include "ui/session/FileJobs.h"
#include "core/common/Error.h"
#include "ui/session/ReductionService.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace vl::ui {
namespace {

TEST(FileJobs, OneJobOfAKindAtATimeAndPollReportsWhatFinished) {
    FileJobs jobs;
    std::atomic<bool> release{false};
    jobs.load("Opening a", [&] {
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        LoadedDocument loaded;
        loaded.message = "opened a";
        return loaded;
    });
    EXPECT_TRUE(jobs.loading());
    EXPECT_EQ(jobs.loadingLabel(), "Opening a");
    EXPECT_THROW(jobs.load("Opening b", [] { return LoadedDocument{}; }), InputError);
    // Other kinds run meanwhile.
    bool heldBack = false;
    jobs.save(
        "Saving p", 42, [&] { heldBack = true; }, [] { return std::filesystem::path("p.vlproj"); });
    jobs.exportModel("Exporting glb", [] { return std::string("Exported glb"); });
    jobs.exportAvatar("Exporting x.glb", []() -> std::string { throwInputError("x.glb", "refused"); });
    release = true;
    jobs.wait();
    FileJobs::Finished finished = jobs.poll();
    ASSERT_TRUE(finished.loaded);
    EXPECT_EQ(finished.loaded->message, "opened a");
    ASSERT_TRUE(finished.saved);
    EXPECT_EQ(*finished.saved, std::filesystem::path("p.vlproj"));
    EXPECT_EQ(finished.savedRevision, 42u);
    ASSERT_TRUE(finished.afterSave);
    finished.afterSave();
    EXPECT_TRUE(heldBack);
    EXPECT_EQ(finished.infos, std::vector<std::string>{"Exported glb"});
    ASSERT_EQ(finished.errors.size(), 1u);
    EXPECT_EQ(finished.errors[0], "Exporting x.glb: x.glb: refused");
    // Each outcome is reported once.
    const FileJobs::Finished again = jobs.poll();
    EXPECT_FALSE(again.loaded || again.saved || !again.infos.empty() || !again.errors.empty());
}

TEST(FileJobs, AFailedSaveDropsTheHeldBackAction) {
    FileJobs jobs;
    bool ran = false;
    jobs.save(
        "Saving p", 7, [&] { ran = true; },
        []() -> std::filesystem::path { throwInputError("p.vlproj", "read-only"); });
    jobs.wait();
    const FileJobs::Finished finished = jobs.poll();
    EXPECT_FALSE(finished.saved);
    EXPECT_FALSE(finished.afterSave);
    ASSERT_EQ(finished.errors.size(), 1u);
    EXPECT_EQ(finished.errors[0], "Saving p: p.vlproj: read-only");
    EXPECT_FALSE(ran);
}

} // namespace
} // namespace vl::ui
