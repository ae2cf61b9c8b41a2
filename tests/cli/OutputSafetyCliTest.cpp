// Issue 30 at the command line: outputs never replace what the input project refers to (exit code 3,
// nothing changed), are never written through symbolic links unless --follow-symlinks (and never
// create folders through a dangling one), a planted manifest deletes nothing, and concurrent writers
// of one folder end with one run's complete set.
#include "tests/cli/CliRunner.h"
#include "tests/cli/OutputFolders.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sys/wait.h>

namespace vl {
namespace {

namespace fs = std::filesystem;

class OutputSafetyCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = test::folderWithSample("visemelab_outsafe_", "s");
        before = test::visibleFiles(dir / "s");
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string project() const { return (dir / "s" / "sample.vlproj").string(); }
    void expectRefused(const std::string& arguments, const std::string& naming, int exitCode = 3) const {
        const auto r = test::runCli(arguments);
        EXPECT_EQ(r.exitCode, exitCode) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(naming), std::string::npos) << r.output;
        EXPECT_EQ(test::visibleFiles(dir / "s"), before) << arguments;
        EXPECT_EQ(test::debrisOf(dir / "s"), std::vector<std::string>{}) << arguments;
    }

    fs::path dir;
    test::FolderView before;
};

TEST_F(OutputSafetyCli, OutputsNeverReplaceWhatTheProjectRefersTo) {
    const std::string s = (dir / "s").string();
    // refine reads only the neutral, yet aa.obj is the project's too.
    expectRefused("refine --project " + project() + " --out " + s + "/aa.obj", s + "/aa.obj");
    expectRefused("visemes --project " + project() + " --out " + s, s + ": output folder holds");
    expectRefused("export " + project() + " --format obj --out " + s, s + ": output folder holds");
    expectRefused("export " + project() + " --format vrml --out " + s, s + ": output folder holds");
    // A file the run reads is an input: exit code 2, as before issue 30.
    expectRefused("export " + project() + " --format glb --out " + s + "/PP.obj", s + "/PP.obj", 2);
    expectRefused("reduce --project " + project() + " --out " + s, s + ": output folder holds");
    expectRefused("reduce --project " + project() + " --out " + dir.string(),
                  dir.string() + ": output folder holds");
}

TEST_F(OutputSafetyCli, SymlinkedOutputsAreRefusedUnlessFollowedAndDanglingOnesCreateNothing) {
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "target.glb") << "not a glb";
    fs::create_symlink(dir / "real" / "target.glb", dir / "file-link.glb");
    fs::create_symlink(dir / "real", dir / "folder-link");
    fs::create_symlink(dir / "nowhere" / "deeper", dir / "dangling");
    auto r = test::runCli("export " + project() + " --format glb --out " + (dir / "file-link.glb").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find((dir / "file-link.glb").string() + ": the output is a symbolic link"),
              std::string::npos)
        << r.output;
    r = test::runCli("reduce --project " + project() + " --out " + (dir / "folder-link").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(test::visibleFiles(dir / "real"), (test::FolderView{{"target.glb", "not a glb"}}));
    for (const std::string& out : {(dir / "dangling").string(), (dir / "dangling" / "x").string()}) {
        r = test::runCli("reduce --project " + project() + " --out " + out);
        EXPECT_EQ(r.exitCode, 3) << r.output;
        r = test::runCli("say hi --project " + project() + " --out " + out + " --follow-symlinks");
        EXPECT_NE(r.exitCode, 0) << r.output;
        r = test::runCli("--follow-symlinks reduce --project " + project() + " --out " + out);
        EXPECT_NE(r.exitCode, 0) << r.output;
    }
    EXPECT_FALSE(fs::exists(dir / "nowhere"));
    // --follow-symlinks (before or after the command) writes through to the targets.
    r = test::runCli("export " + project() + " --format glb --follow-symlinks --out " +
                     (dir / "file-link.glb").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_symlink(dir / "file-link.glb"));
    EXPECT_GT(fs::file_size(dir / "real" / "target.glb"), 1000u);
    r = test::runCli("--follow-symlinks reduce --project " + project() + " --out " +
                     (dir / "folder-link").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_symlink(dir / "folder-link"));
    EXPECT_TRUE(fs::exists(dir / "real" / "mapping.json"));
}

TEST_F(OutputSafetyCli, APlantedManifestDeletesNothing) {
    const fs::path out = dir / "out";
    fs::create_directories(out);
    std::ofstream(out / "thesis.txt") << "years of work";
    std::ofstream(out / ".visemelab-reduce.manifest") << "thesis.txt\n";
    auto r = test::runCli("reduce --project " + project() + " --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Planted again, now with a hash: one that is not the file's.
    std::ofstream(out / ".visemelab-reduce.manifest") << "13 0123456789abcdef thesis.txt\n";
    r = test::runCli("reduce --project " + project() + " --target 3 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(test::visibleFiles(out)["thesis.txt"], "years of work");
}

// One process per entry, all started before any is waited for.
std::vector<test::CliResult> runAtOnce(const std::vector<std::string>& commands) {
    std::vector<FILE*> pipes;
    for (const auto& arguments : commands)
        pipes.push_back(::popen((std::string(VISEMELAB_CLI) + " " + arguments + " 2>&1").c_str(), "r"));
    std::vector<test::CliResult> results;
    for (FILE* pipe : pipes) {
        test::CliResult result;
        char buffer[4096];
        while (const auto n = std::fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
        const int status = ::pclose(pipe);
        result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        results.push_back(result);
    }
    return results;
}

TEST_F(OutputSafetyCli, ConcurrentWritersOfOneFolderEndWithOneRunsCompleteSet) {
    const auto reduceInto = [&](const fs::path& out, int target) {
        return "reduce --project " + project() + " --target " + std::to_string(target) + " --out " +
               out.string();
    };
    ASSERT_EQ(test::runCli(reduceInto(dir / "ref3", 3)).exitCode, 0);
    ASSERT_EQ(test::runCli(reduceInto(dir / "ref5", 5)).exitCode, 0);
    const test::FolderView three = test::visibleFiles(dir / "ref3"), five = test::visibleFiles(dir / "ref5");
    std::vector<std::string> commands;
    for (int pair = 0; pair < 8; ++pair) {
        const fs::path out = dir / ("out" + std::to_string(pair));
        commands.push_back(reduceInto(out, 3));
        // Half of the second writers refuse a busy folder instead of waiting.
        commands.push_back((pair % 2 ? "--no-wait " : "") + reduceInto(out, 5));
    }
    const auto results = runAtOnce(commands);
    for (std::size_t i = 0; i < results.size(); ++i) {
        const bool mayRefuse = i % 2 == 1 && (i / 2) % 2 == 1;
        if (mayRefuse && results[i].exitCode == 3)
            // Names the holder's pid and command, or "another process" when it let go in between.
            EXPECT_NE(results[i].output.find("another run is writing this folder: "), std::string::npos)
                << results[i].output;
        else
            EXPECT_EQ(results[i].exitCode, 0) << commands[i] << "\n" << results[i].output;
    }
    for (int pair = 0; pair < 8; ++pair) {
        const fs::path out = dir / ("out" + std::to_string(pair));
        const test::FolderView now = test::visibleFiles(out);
        EXPECT_TRUE(now == three || now == five) << out << ": " << test::namesOf(now);
        EXPECT_EQ(test::debrisOf(out), std::vector<std::string>{});
    }
}

} // namespace
} // namespace vl
