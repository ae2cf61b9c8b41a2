// Cancel on the editor's background jobs (issue 32): a cancelled job leaves the document as it was,
// the UI is idle at once, and the worker ends within a second.
#include "ui/session/BackgroundTask.h"
#include "ui/session/BundledAssets.h"
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <unistd.h>

namespace vl::ui {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Waits (30 s at most) until `job` has reported some progress; false when it ended first.
bool waitForProgress(EditorSession& session, SessionJobs::Job job) {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (Clock::now() < deadline) {
        bool running = false;
        for (const auto& status : session.jobs().running()) {
            if (status.job != job) continue;
            running = true;
            if (status.fraction && *status.fraction > 0) return true;
        }
        if (!running) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

TEST(BackgroundTask, ACancelWithoutWaitingDropsTheOutcomeEvenOfWorkWithoutProgress) {
    BackgroundTask<int> task;
    std::atomic<bool> release{false};
    task.start("work", [&](const auto&) {
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return 7;
    });
    EXPECT_TRUE(task.running());
    task.requestCancel();
    EXPECT_FALSE(task.running()); // at once, though the worker still runs
    release = true;
    task.wait();
    EXPECT_FALSE(task.take().has_value());
}

TEST(BackgroundTask, TheTimeLeftFollowsTheProgress) {
    BackgroundTask<int> task;
    std::atomic<bool> release{false};
    task.start("work", [&](const auto& progress) {
        progress(0.01);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        progress(0.5);
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return 1;
    });
    while (task.progress() < 0.5) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const auto left = task.secondsLeft();
    ASSERT_TRUE(left.has_value());
    EXPECT_GT(*left, 0.015); // about the 20 ms elapsed: half done
    EXPECT_LT(*left, 5.0);
    release = true;
    task.wait();
    EXPECT_FALSE(task.secondsLeft().has_value());
    EXPECT_EQ(std::get<0>(*task.take()), 1);
}

TEST(JobCancel, RefiningForAllVisemesStopsWithinASecondAndTheFaceKeepsItsMesh) {
    EditorSession session;
    session.face().load();
    // The finest contour thresholds: refining for all 15 visemes then takes seconds, not milliseconds.
    CriterionSettings fine = session.document().refinement;
    fine.kind = CriterionKind::Contour;
    fine.maxDepth = 12;
    fine.contour.averageError *= 0.05;
    fine.contour.maximumError *= 0.05;
    session.face().setRefinementSettings(fine);
    const auto domain = session.document().face.domain;
    const auto revision = session.history().revision();
    const std::string undo = session.history().undoName();
    session.face().startRefinement(RefineAction::AllVisemes);
    ASSERT_TRUE(waitForProgress(session, SessionJobs::Job::Refinement));
    session.jobs().cancel(SessionJobs::Job::Refinement);
    EXPECT_TRUE(session.jobs().running().empty());
    const auto cancelled = Clock::now();
    session.finishBackgroundWork(); // joins the worker
    EXPECT_LT(secondsSince(cancelled), 1.0);
    EXPECT_EQ(session.document().face.domain, domain);
    EXPECT_FALSE(session.face().lastRefinement().has_value());
    EXPECT_EQ(session.history().revision(), revision);
    EXPECT_EQ(session.history().undoName(), undo); // no step was added
    // And it runs again afterwards.
    session.face().startRefinement(RefineAction::Refine);
    session.finishBackgroundWork();
    EXPECT_TRUE(session.face().lastRefinement().has_value());
}

TEST(JobCancel, TranscribingACorpusStopsWithinASecondAndTheFrequenciesStay) {
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_job_cancel_corpus";
    std::filesystem::create_directories(dir);
    {
        std::ofstream corpus(dir / "corpus.txt");
        for (int i = 0; i < 20000; ++i)
            corpus << "Four score and seven years ago our fathers brought forth on this continent a new "
                      "nation.\n";
    }
    EditorSession session;
    session.files().openProject(std::filesystem::path(assetsDirectory()) / "sample" / "sample.vlproj");
    const FrequencySource before = session.document().frequencies;
    const std::string undo = session.history().undoName();
    session.frequencies().startPhonemeCount(dir / "corpus.txt");
    ASSERT_TRUE(waitForProgress(session, SessionJobs::Job::PhonemeCount));
    session.jobs().cancel(SessionJobs::Job::PhonemeCount);
    EXPECT_TRUE(session.jobs().running().empty());
    const auto cancelled = Clock::now();
    session.finishBackgroundWork();
    EXPECT_LT(secondsSince(cancelled), 1.0);
    EXPECT_EQ(session.document().frequencies, before);
    EXPECT_EQ(session.history().undoName(), undo);
    std::filesystem::remove_all(dir);
}

TEST(JobCancel, ACancelledOpenLeavesTheDocumentAsItWas) {
    EditorSession session;
    const auto revision = session.history().revision();
    session.files().startOpenProject(std::filesystem::path(assetsDirectory()) / "sample" / "sample.vlproj");
    ASSERT_FALSE(session.jobs().running().empty());
    session.jobs().cancel(SessionJobs::Job::Loading);
    EXPECT_TRUE(session.jobs().running().empty());
    session.finishBackgroundWork();
    EXPECT_EQ(session.history().revision(), revision);
    EXPECT_TRUE(session.files().path().empty());
    EXPECT_EQ(session.visemes(), nullptr);
}

// A folder of `count` visemes with random shapes on a small grid (neutral.obj + v<i>.obj): no
// structure, so an exact reduction takes seconds (issue 33's certificates).
std::filesystem::path randomVisemeFolder(const std::string& name, int count) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    constexpr int kSide = 6;
    std::uint32_t seed = 12345;
    const auto random = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<double>(seed >> 8) / static_cast<double>(1u << 24) - 0.5;
    };
    const auto write = [&](const std::string& file, double amplitude) {
        std::ofstream out(dir / file);
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                out << "v " << x + amplitude * random() << ' ' << y + amplitude * random() << ' '
                    << amplitude * random() << '\n';
        for (int y = 0; y + 1 < kSide; ++y)
            for (int x = 0; x + 1 < kSide; ++x) {
                const int a = y * kSide + x + 1, b = a + 1, c = a + kSide, d = c + 1;
                out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
            }
    };
    write("neutral.obj", 0.0);
    for (int i = 0; i < count; ++i) write("v" + std::to_string(i) + ".obj", 0.8);
    return dir;
}

// A large set's Cancel is a Stop: the search ends at its next node and keeps the best groupings it
// found with their proven gaps, as at the time limit; the document is untouched.
TEST(JobCancel, AReductionStopsWithinASecondAndTheDocumentStays) {
    const auto dir = randomVisemeFolder("cancel-reduction", 30);
    EditorSession session;
    session.files().loadVisemeFolder(dir);
    session.jobs().cancel(SessionJobs::Job::Reduction); // an automatic run of the loaded set, if any
    session.reduction().setTarget(22);                  // past any curve a first run computed
    const auto revision = session.history().revision();
    const std::string undo = session.history().undoName();
    session.reduction().start();
    // The search reports its bound, not a fraction done: let it run a while, then Cancel.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto reducing = [&session] {
        for (const auto& status : session.jobs().running())
            if (status.job == SessionJobs::Job::Reduction) return true;
        return false;
    };
    ASSERT_TRUE(reducing()) << "the reduction ended before it could be cancelled";
    const auto start = Clock::now();
    session.jobs().cancel(SessionJobs::Job::Reduction);
    EXPECT_LT(secondsSince(start), 0.2) << "Cancel returns at once";
    while (reducing() && secondsSince(start) < 5) {
        session.poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_LT(secondsSince(start), 1.0) << "the search did not stop within a second";
    EXPECT_EQ(session.history().revision(), revision);
    EXPECT_EQ(session.history().undoName(), undo);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl::ui
