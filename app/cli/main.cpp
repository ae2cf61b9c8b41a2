// visemelab: the headless pipeline (reduce, refine, visemes, export, freq, project, avatar, say).
#include "app/cli/Command.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"

#include <cstdio>
#include <exception>
#include <new>

int main(int argc, char** argv) {
    CLI::App app{"VisemeLab: optimal viseme reduction and adaptive deformable faces"};
    app.require_subcommand(1, 1);
    app.fallthrough(); // the output flags below may follow the subcommand (inherited by every subcommand)
    bool followSymlinks = false, noWait = false;
    app.add_flag(
        "--follow-symlinks", followSymlinks,
        "Write outputs through symbolic links (by default an output path that is a link is refused)");
    app.add_flag("--no-wait", noWait,
                 "Refuse (exit code 3) instead of waiting when another run is writing the output folder");
    vl::cli::CommandRunner run;
    vl::cli::addReduceCommand(app, run);
    vl::cli::addFreqCommand(app, run);
    vl::cli::addVisemesCommand(app, run);
    vl::cli::addRenderCommand(app, run);
    vl::cli::addRefineCommand(app, run);
    vl::cli::addExportCommand(app, run);
    vl::cli::addProjectCommand(app, run);
    vl::cli::addFaceCommand(app, run);
    vl::cli::addAvatarCommand(app, run);
    vl::cli::addSayCommand(app, run);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? vl::cli::kExitOk : vl::cli::kExitUsage;
    }
    vl::setOutputPolicy({.followSymlinks = followSymlinks, .waitForBusyFolder = !noWait});
    try {
        const vl::InputRecording inputs; // every file read is an input no output may overwrite
        return run ? run() : vl::cli::kExitUsage;
    } catch (const vl::cli::UsageError& e) {
        std::fprintf(stderr, "visemelab: usage error: %s (see --help)\n", e.what());
        return vl::cli::kExitUsage;
    } catch (const vl::OutputOverwritesInputError& e) {
        std::fprintf(stderr, "visemelab: usage error: %s\n", e.what());
        return vl::cli::kExitUsage;
    } catch (const vl::InputError& e) {
        std::fprintf(stderr, "visemelab: error: %s\n", e.what());
        return vl::cli::kExitInvalidInput;
    } catch (const std::bad_alloc&) {
        // Readers bound memory by their input's size; this is a machine short of memory for it.
        std::fprintf(stderr, "visemelab: error: out of memory (the input is too large for this machine)\n");
        return vl::cli::kExitInvalidInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "visemelab: internal error: %s\n", e.what());
        return 1;
    }
}
