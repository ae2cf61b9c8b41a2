// What pipelines rely on (issue 34, point 4): --version, an unknown command named as such, numeric
// option errors a user can read, `-` as the standard output, notes on stderr and results on stdout.
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace vl {
namespace {

TEST(CliConventions, VersionPrintsTheProjectVersion) {
    const auto r = test::runCli("--version");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind("visemelab ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find('.'), std::string::npos) << r.output;
}

TEST(CliConventions, AnUnknownCommandIsNamed) {
    const auto r = test::runCli("frobnicate --out x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("unknown command 'frobnicate'"), std::string::npos) << r.output;
    // A known command still parses as before.
    const auto help = test::runCli("reduce --help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
}

TEST(CliConventions, NumericErrorsAreReadable) {
    for (const char* arguments :
         {"avatar reduce in.glb -m 0 --out out.glb", "say hi --avatar in.glb -m 0 --out t.json",
          "reduce --project p.vlproj --max-error-mm -1"}) {
        const auto r = test::runCli(arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find("must be greater than 0"), std::string::npos) << arguments << "\n"
                                                                              << r.output;
        EXPECT_LT(r.output.size(), 400u) << r.output; // no 309-digit bound
    }
}

struct SplitOutput {
    int exitCode = -1;
    std::string out, err;
};

// Runs the CLI with stdout and stderr captured apart (CliRunner joins them).
SplitOutput runSplit(const std::string& arguments) {
    const auto errFile = std::filesystem::temp_directory_path() /
                         ("visemelab-conventions-" + std::to_string(::getpid()) + ".err");
    const auto r = test::runCli(arguments + " 2>'" + errFile.string() + "' #"); // '#': drops CliRunner's 2>&1
    SplitOutput split{r.exitCode, r.output, {}};
    std::ifstream in(errFile);
    std::stringstream text;
    text << in.rdbuf();
    split.err = text.str();
    std::filesystem::remove(errFile);
    return split;
}

std::string sampleProject() {
    return "'" + (std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj").string() + "'";
}

TEST(CliConventions, DashIsTheStandardOutputAndOnlyTheDataGoesThere) {
    const auto r = runSplit("say 'Hello world' --project " + sampleProject() + " --out -");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto track = nlohmann::json::parse(r.out); // nothing but the track on stdout
    EXPECT_TRUE(track.contains("mouthCues")) << r.out.substr(0, 200);
    EXPECT_NE(r.err.find("Wrote"), std::string::npos) << r.err; // the summary went to stderr
    EXPECT_NE(r.err.find("of speech"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists("-"));
}

TEST(CliConventions, NotesGoToStderrResultsToStdout) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("visemelab-conventions-notes-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    const auto r = runSplit("say 'Hello world' --project " + sampleProject() + " --out '" +
                            (dir / "t.json").string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("of speech"), std::string::npos) << r.out; // the result
    EXPECT_EQ(r.out.find("Wrote"), std::string::npos) << r.out;     // a note
    EXPECT_NE(r.err.find("Wrote"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliConventions, DashIsRefusedWhereItCannotBeOneFile) {
    // Two outputs cannot share the standard output.
    auto r = runSplit("say hi --project " + sampleProject() + " --out - --wav -");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("only one output can be the standard output"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    // A folder of several files is not one stream.
    r = runSplit("reduce --project " + sampleProject() + " -m 4 --out -");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("the standard output takes one file"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists("-"));
}

} // namespace
} // namespace vl
