#pragma once
// How every writer of the core treats an output path that is a symbolic link and a folder another
// run is writing. The CLI refuses links (--follow-symlinks lifts that) and waits for a busy folder
// (--no-wait refuses instead); the editor keeps the defaults (links written through, waiting).
#include <filesystem>
#include <string_view>

namespace vl {

struct OutputPolicy {
    // false: an output path that is a symbolic link is refused (OutputRefusedError, exit code 3).
    // true: written through to its target. Either way no folder is created through a dangling link.
    bool followSymlinks = true;
    // false: a folder output whose folder another run is writing is refused at once, naming that
    // run (pid, command). true: wait for it, saying so on stderr.
    bool waitForBusyFolder = true;
    // >= 0: a file output named `-` goes to this descriptor (the CLI's standard output), whole, at
    // commit; -1: `-` is a file name like any other (the editor).
    int standardOutputFd = -1;
};

// Process-wide; set once before any output is written (not synchronised).
void setOutputPolicy(const OutputPolicy& policy);
const OutputPolicy& outputPolicy();

// True when `path` is `-` and the policy sends it to the standard output.
bool isStandardOutput(const std::filesystem::path& path);

// Where a write to `path` goes: `path` itself, or (following links) the end of its chain of links.
// Throws OutputRefusedError naming `path` for a link the policy does not follow, and for a link
// whose target's folder (`isFolder`: the target itself) does not exist: no folder is ever created
// through a link.
std::filesystem::path resolveOutputPath(const std::filesystem::path& path, bool isFolder);

} // namespace vl
