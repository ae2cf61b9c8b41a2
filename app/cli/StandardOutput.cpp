#include "app/cli/StandardOutput.h"

#include "app/cli/Command.h"
#include "core/common/FileWriting.h"
#include "core/common/OutputPolicy.h"

#include <cstdio>
#include <string>
#include <string_view>
#include <unistd.h>

namespace vl::cli {

int claimStandardOutput(int argc, char** argv) {
    int dashes = 0;
    for (int i = 1; i < argc; ++i) dashes += std::string_view(argv[i]) == "-";
    if (dashes == 0) return -1;
    if (dashes > 1)
        throw UsageError("only one output can be the standard output ('-' is given " +
                         std::to_string(dashes) + " times)");
    std::fflush(stdout);
    const int data = ::dup(STDOUT_FILENO);
    if (data < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
        throw UsageError("the standard output cannot be used for an output here");
    return data;
}

bool writeToStandardOutput(std::string_view bytes) {
    const int fd = outputPolicy().standardOutputFd;
    return fd >= 0 && fileio::writeAll(fd, bytes);
}

} // namespace vl::cli
