#include "app/cli/CommandMain.h"

#include "app/cli/StandardOutput.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <nlohmann/json.hpp>
#include <string>

namespace vl::cli {

namespace {

// The command-line arguments that name existing files (also the FILE of NAME=FILE), quoted, for a
// message that cannot know which input it was reading (out of memory).
std::string inputsOf(int argc, char** argv) {
    std::string names;
    for (int i = 2; i < argc; ++i) {
        std::string_view arg = argv[i];
        if (const auto eq = arg.find('='); eq != std::string_view::npos && !arg.starts_with("-"))
            arg.remove_prefix(eq + 1);
        std::error_code ec;
        if (arg.starts_with("-") || !std::filesystem::exists(std::filesystem::path(arg), ec)) continue;
        names += (names.empty() ? "" : ", ") + vl::quoteInput(arg);
        if (names.size() > vl::kMaxQuotedInput) break;
    }
    return names.empty() ? "the input" : names;
}

// The first argument that is not valid UTF-8, quoted (escaped), or empty.
std::string invalidUtf8Argument(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (!vl::isValidUtf8(argv[i])) return vl::quoteInput(argv[i]);
    return {};
}

} // namespace

void addGlobalOptions(CLI::App& app, GlobalOptions& options) {
    app.require_subcommand(1, 1);
    app.fallthrough(); // the output flags below may follow the subcommand (inherited by every subcommand)
    app.add_flag(
        "--follow-symlinks", options.followSymlinks,
        "Write outputs through symbolic links (by default an output path that is a link is refused)");
    app.add_flag("--no-wait", options.noWait,
                 "Refuse (exit code 3) instead of waiting when another run is writing the output folder");
}

int runCommand(int argc, char** argv, const GlobalOptions& options, const CommandRunner& run) {
    try {
        vl::setOutputPolicy({.followSymlinks = options.followSymlinks,
                             .waitForBusyFolder = !options.noWait,
                             .standardOutputFd = claimStandardOutput(argc, argv)});
        const vl::InputRecording inputs; // every file read is an input no output may overwrite
        return run ? run() : kExitUsage;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "visemelab: usage error: %s (see --help)\n", e.what());
        return kExitUsage;
    } catch (const vl::OutputOverwritesInputError& e) {
        std::fprintf(stderr, "visemelab: usage error: %s\n", e.what());
        return kExitUsage;
    } catch (const vl::InputError& e) {
        std::fprintf(stderr, "visemelab: error: %s\n", e.what());
        return kExitInvalidInput;
    } catch (const std::bad_alloc&) {
        // Readers bound memory by their input's size; this is a machine short of memory for it.
        std::fprintf(stderr,
                     "visemelab: error: %s: out of memory (the input is too large for this machine)\n",
                     inputsOf(argc, argv).c_str());
        return kExitInvalidInput;
    } catch (const std::filesystem::filesystem_error& e) {
        // A symlink loop, a file vanishing or unreadable while listed: the path is the culprit.
        std::fprintf(stderr, "visemelab: error: %s: %s\n", vl::quoteInput(e.path1().string()).c_str(),
                     e.code().message().c_str());
        return kExitInvalidInput;
    } catch (const nlohmann::json::type_error& e) {
        // 316: a name from argv, a file name or a table that is not UTF-8 reached a JSON output.
        if (e.id != 316) {
            std::fprintf(stderr, "visemelab: internal error: %s\n", e.what());
            return 1;
        }
        const std::string argument = invalidUtf8Argument(argc, argv);
        std::fprintf(stderr, "visemelab: error: %s: a name is not valid UTF-8 (%s)\n",
                     argument.empty() ? inputsOf(argc, argv).c_str() : argument.c_str(), e.what());
        return kExitInvalidInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "visemelab: internal error: %s\n", e.what());
        return 1;
    }
}

} // namespace vl::cli
