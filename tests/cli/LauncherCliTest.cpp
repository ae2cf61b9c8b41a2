// The launcher (app/cli/Launcher.c): `visemelab --help`, `-h` and `--version` answered without
// loading the commands are byte for byte what the commands print; everything else reaches the
// commands with its arguments, output and exit status unchanged.
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace vl::test {
namespace {

const std::string kLauncher = VISEMELAB_CLI;
const std::string kCommands = (std::filesystem::path(VISEMELAB_CLI).parent_path() / "visemelab-cli").string();

CliResult run(const std::string& program, const std::string& arguments) {
    return runProgram("", program, arguments);
}

// The commands' help names the program as called: compare with that name replaced.
std::string withProgram(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

TEST(Launcher, HelpAndVersionAreTheCommandsOwn) {
    const CliResult commands = run(kCommands, "--help");
    ASSERT_EQ(commands.exitCode, 0) << commands.output;
    ASSERT_NE(commands.output.find("Usage: " + kCommands + " [OPTIONS] SUBCOMMAND"), std::string::npos);
    for (const char* option : {"--help", "-h"}) {
        const CliResult launcher = run(kLauncher, option);
        EXPECT_EQ(launcher.exitCode, 0) << option;
        EXPECT_EQ(launcher.output, withProgram(commands.output, kCommands, kLauncher)) << option;
    }
    const CliResult version = run(kLauncher, "--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.output, run(kCommands, "--version").output);
    EXPECT_EQ(version.output.rfind("visemelab ", 0), 0u) << version.output;
}

TEST(Launcher, EveryOtherCallReachesTheCommandsUnchanged) {
    // A subcommand's help, an unknown command, no command and a bad option: same output and status.
    for (const char* arguments :
         {"reduce --help", "frobnicate", "", "--help extra", "reduce -m 0 --dir /nonexistent",
          // `say` runs visemelab-say, which hands what it does not serve to the commands.
          "say --help", "say", "say hi --project /nonexistent.vlproj --out x.json", "say hi --frobnicate"}) {
        const CliResult launcher = run(kLauncher, arguments);
        const CliResult commands = run(kCommands, arguments);
        EXPECT_EQ(launcher.exitCode, commands.exitCode) << arguments;
        EXPECT_EQ(withProgram(launcher.output, kLauncher, kCommands), commands.output) << arguments;
    }
}

} // namespace
} // namespace vl::test
