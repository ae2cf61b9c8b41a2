#pragma once

#include <string_view>

namespace vl::cli {

// Pipelines name `-` for an output (`--out -`, `--report -`, `--json -`) to read it from the
// standard output. When an argument is `-`, the standard output is kept for that file alone: the
// returned descriptor is the original standard output (for OutputPolicy::standardOutputFd) and
// file descriptor 1 now goes to stderr, so the run's summary, notes and progress cannot mix with the
// data. Returns -1 (nothing changed) when no argument is `-`. Throws UsageError when several are.
int claimStandardOutput(int argc, char** argv);

// Writes `bytes` to the claimed standard output now (a stream of answers, not one file); false when
// its reader went away or nothing was claimed.
bool writeToStandardOutput(std::string_view bytes);

} // namespace vl::cli
