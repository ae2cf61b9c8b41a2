// visemelab-cli: the headless pipeline (reduce, refine, visemes, export, freq, project, avatar, say),
// run by the launcher `visemelab` (Launcher.c).
#include "app/cli/CommandMain.h"
#include "app/cli/ProcessMemory.h"
#include "core/common/Error.h"

#include <cstdio>

int main(int argc, char** argv) {
    vl::cli::tuneProcessMemory();
    CLI::App app{vl::cli::kAppDescription};
    vl::cli::GlobalOptions options;
    vl::cli::addGlobalOptions(app, options);
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
    vl::cli::addBatchCommand(app, run);
    app.set_version_flag("--version", std::string("visemelab ") + VISEMELAB_VERSION);

    // A first argument that is neither an option nor a command is named as such (CLI11 would only
    // say that a subcommand is required).
    if (argc > 1 && argv[1][0] != '-') {
        bool known = false;
        for (const CLI::App* sub : app.get_subcommands({})) known = known || sub->check_name(argv[1]);
        if (!known) {
            std::fprintf(stderr, "visemelab: usage error: unknown command '%s' (see visemelab --help)\n",
                         vl::quoteInput(argv[1]).c_str());
            return vl::cli::kExitUsage;
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? vl::cli::kExitOk : vl::cli::kExitUsage;
    }
    return vl::cli::runCommand(argc, argv, options, run);
}
