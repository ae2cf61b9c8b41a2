// Kill-at-every-call tests of the output commands (issue 30): strace kills the command at the K-th
// call of one system call, for K = 1, 2, ... until a run completes, for every call that creates,
// writes, syncs, links, renames, removes or locks. After every kill a reader must see the complete
// old or the complete new outputs (a user's file among them all the time), and a run after the kills
// must leave no debris.
#include "tests/cli/CliRunner.h"
#include "tests/cli/OutputFolders.h"
#include "tests/cli/SanitizerBuild.h"

#include "core/common/AtomicFile.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

namespace vl {
namespace {

namespace fs = std::filesystem;

// The calls of an output's life. A kill is tried at each of their calls, except openat, which also
// reads the inputs: every third call (every twelfth for say, which opens espeak-ng's data files
// hundreds of times before it writes anything).
const std::vector<std::string> kCalls = {"mkdir",  "openat", "write",   "writev", "fsync",
                                         "link",   "linkat", "flock",   "rename", "renameat2",
                                         "unlink", "rmdir",  "unlinkat"};

// LeakSanitizer cannot run under ptrace, and a sanitizer build would make hundreds of kills per
// command take minutes: the kill tests are about the write protocol, which the release suite checks.
constexpr bool kSanitizerBuild = test::kAddressSanitizer;

bool straceWorks() {
    static const bool works = std::system("strace -f -o /dev/null true >/dev/null 2>&1") == 0;
    return works;
}

// A command line writing into `out`; `second` selects the other of its two variants.
using Command = std::function<std::string(bool second, const fs::path& out)>;

class CrashConsistency : public ::testing::Test {
  protected:
    void SetUp() override {
        if (kSanitizerBuild)
            GTEST_SKIP() << "sanitizer build: the kill-at-every-call tests run in the release suite";
        if (!straceWorks())
            GTEST_SKIP() << "strace cannot run here: the kill-at-every-call tests of issue 30 did NOT run";
        dir = test::folderWithSample("visemelab_crash_", "sample");
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string project() const { return (dir / "sample" / "sample.vlproj").string(); }

    // Runs both variants into reference folders, then kills `command` everywhere in `out`, which
    // alternates between them; `perFile`: the outputs are separate files, each old or new on its own.
    void killEverywhere(const Command& command, bool perFile = false, int openatStride = 3) {
        const fs::path refA = dir / "refA", refB = dir / "refB", out = dir / "out";
        for (const auto& folder : {refA, refB, out}) {
            fs::create_directories(folder);
            std::ofstream(folder / "thesis.txt") << "the user's own file";
        }
        for (const auto& [folder, second] :
             {std::pair{refA, false}, std::pair{refB, true}, std::pair{out, false}}) {
            const auto r = test::runCli(command(second, folder));
            ASSERT_EQ(r.exitCode, 0) << r.output;
        }
        const test::FolderView a = test::visibleFiles(refA), b = test::visibleFiles(refB);
        ASSERT_NE(a, b);
        int kills = 0;
        for (const std::string& call : kCalls)
            for (int k = 1;; k += call == "openat" ? openatStride : 1) {
                ASSERT_LT(k, 3000) << call << ": the command never completed";
                const bool toB = test::visibleFiles(out) != b;
                const std::string strace = "strace -f -o /dev/null -e inject=" + call +
                                           ":signal=KILL:when=" + std::to_string(k) + " ";
                const auto r = test::runCliWith(strace, command(toB, out));
                expectOldOrNew(test::visibleFiles(out), a, b, perFile, call + " #" + std::to_string(k));
                if (::testing::Test::HasFailure()) return;
                if (r.exitCode == 0) break;
                ASSERT_TRUE(r.exitCode == 137 || r.exitCode == -1) << call << " #" << k << ": " << r.output;
                ++kills;
            }
        EXPECT_GT(kills, 10);
        const auto last = test::runCli(command(false, out));
        ASSERT_EQ(last.exitCode, 0) << last.output;
        EXPECT_EQ(test::visibleFiles(out), a);
        EXPECT_EQ(test::debrisOf(out), std::vector<std::string>{});
    }

    static void expectOldOrNew(const test::FolderView& now, const test::FolderView& a,
                               const test::FolderView& b, bool perFile, const std::string& where) {
        if (!perFile) {
            EXPECT_TRUE(now == a || now == b) << "killed at " << where << ", visible: " << test::namesOf(now);
            return;
        }
        EXPECT_EQ(now.size(), a.size()) << "killed at " << where << ", visible: " << test::namesOf(now);
        for (const auto& [name, bytes] : now) {
            const auto inA = a.find(name), inB = b.find(name);
            EXPECT_TRUE((inA != a.end() && inA->second == bytes) || (inB != b.end() && inB->second == bytes))
                << "killed at " << where << ": " << name << " is neither the old nor the new file";
        }
    }

    fs::path dir;
};

TEST_F(CrashConsistency, ReduceOut) {
    killEverywhere([&](bool second, const fs::path& out) {
        return "reduce --project " + project() + " --target " + (second ? "6" : "4") + " --out " +
               out.string();
    });
}

TEST_F(CrashConsistency, ExportObj) {
    killEverywhere([&](bool second, const fs::path& out) {
        return "export " + project() + " --format obj" + (second ? " --unreduced" : "") + " --out " +
               out.string();
    });
}

TEST_F(CrashConsistency, ExportVrml) {
    killEverywhere([&](bool second, const fs::path& out) {
        return "export " + project() + " --format vrml" + (second ? " --unreduced" : "") + " --out " +
               out.string();
    });
}

TEST_F(CrashConsistency, AvatarReduce) {
    writeFileAtomically(dir / "rpm.glb", test::rpmLikeAvatar());
    killEverywhere([&](bool second, const fs::path& out) {
        return "avatar reduce " + (dir / "rpm.glb").string() + " --target " + (second ? "6" : "4") +
               " --out " + (out / "avatar.glb").string();
    });
}

TEST_F(CrashConsistency, SayWav) {
    const auto probe =
        test::runCli("say hello --project " + project() + " --out " + (dir / "probe.json").string());
    if (probe.exitCode != 0)
        GTEST_SKIP() << "say does not run here (espeak-ng missing?): the kill test of say --wav did NOT run\n"
                     << probe.output;
    killEverywhere(
        [&](bool second, const fs::path& out) {
            return std::string("say '") + (second ? "How are you today?" : "Hello there.") + "' --project " +
                   project() + " --out " + (out / "track.json").string() + " --wav " +
                   (out / "audio.wav").string();
        },
        true, 12);
}

} // namespace
} // namespace vl
