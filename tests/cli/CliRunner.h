#pragma once
// Runs the visemelab CLI as a child process and captures its exit code and output.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace vl::test {

struct CliResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// Runs `program` with `arguments` through the shell; `shellPrefix` runs first in the same shell.
inline CliResult runProgram(const std::string& shellPrefix, const std::string& program,
                            const std::string& arguments) {
    const std::string command = shellPrefix + program + " " + arguments + " 2>&1";
    CliResult result;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (const auto n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// `shellPrefix` runs first in the same shell, e.g. "ulimit -t 20; " to bound the CLI.
inline CliResult runCliWith(const std::string& shellPrefix, const std::string& arguments) {
    return runProgram(shellPrefix, VISEMELAB_CLI, arguments);
}

inline CliResult runCli(const std::string& arguments) {
    return runCliWith("", arguments);
}

} // namespace vl::test
