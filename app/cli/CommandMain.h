#pragma once
// What both programs of the commands share (visemelab-cli, main.cpp, and the lean visemelab-say,
// SayMain.cpp): the options every command takes and running the parsed command with the exit codes
// and messages of Command.h.
#include "app/cli/Command.h"

namespace vl::cli {

inline constexpr const char* kAppDescription =
    "VisemeLab: optimal viseme reduction and adaptive deformable faces";

struct GlobalOptions {
    bool followSymlinks = false;
    bool noWait = false;
};

// One subcommand, and the output flags that may follow it (inherited by every subcommand).
void addGlobalOptions(CLI::App& app, GlobalOptions& options);

// Runs the parsed command: its errors printed and turned into exit codes.
int runCommand(int argc, char** argv, const GlobalOptions& options, const CommandRunner& run);

} // namespace vl::cli
