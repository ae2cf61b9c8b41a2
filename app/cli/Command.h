#pragma once
// Each subcommand registers itself on the CLI11 app and, when it is the one selected, sets `run`.
// Exit codes: 0 success, 2 usage error, 3 invalid input (InputError), 1 anything unexpected.
#include <CLI/CLI.hpp>

#include <functional>
#include <stdexcept>
#include <string>

namespace vl::cli {

using CommandRunner = std::function<int()>;

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitInvalidInput = 3;

// A combination of flags that CLI11 cannot check by itself; main prints it and exits with 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};
[[noreturn]] inline void throwUsage(const std::string& message) {
    throw UsageError(message);
}

// A number > 0, said in words a user reads (CLI11's PositiveNumber prints DBL_MAX's 309 digits).
inline const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "expected a number, got '" + text + "'";
        return value > 0 ? std::string() : "must be greater than 0, got " + text;
    },
    "> 0");

void addReduceCommand(CLI::App& app, CommandRunner& run);
void addFreqCommand(CLI::App& app, CommandRunner& run);
void addVisemesCommand(CLI::App& app, CommandRunner& run);
void addRenderCommand(CLI::App& app, CommandRunner& run);
void addRefineCommand(CLI::App& app, CommandRunner& run);
void addExportCommand(CLI::App& app, CommandRunner& run);
void addProjectCommand(CLI::App& app, CommandRunner& run);
void addFaceCommand(CLI::App& app, CommandRunner& run);
void addFaceMouthCommand(CLI::App& face, CommandRunner& run); // `face mouth`, added by addFaceCommand
void addAvatarCommand(CLI::App& app, CommandRunner& run);
void addSayCommand(CLI::App& app, CommandRunner& run);
void addBatchCommand(CLI::App& app, CommandRunner& run);

} // namespace vl::cli
