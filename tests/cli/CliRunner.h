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

<<<<<<< Updated upstream
// `shellPrefix` runs first in the same shell, e.g. "ulimit -t 20; " to bound the CLI.
inline CliResult runCliWith(const std::string& shellPrefix, const std::string& arguments) {
    const std::string command = shellPrefix + std::string(VISEMELAB_CLI) + " " + arguments + " 2>&1";
=======
// `environment`: optional NAME=VALUE assignments for this run.
inline CliResult runCli(const std::string& arguments, const std::string& environment = {}) {
    const std::string command =
        (environment.empty() ? "" : environment + " ") + std::string(VISEMELAB_CLI) + " " + arguments + " 2>&1";
>>>>>>> Stashed changes
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

inline CliResult runCli(const std::string& arguments) {
    return runCliWith("", arguments);
}

} // namespace vl::test
