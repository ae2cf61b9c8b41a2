#include "app/cli/Command.h"

namespace vl::cli {

void addReduceCommand(CLI::App& app, CommandRunner& run) {
    auto* cmd = app.add_subcommand("reduce", "Reduce a viseme set to m merged meshes (exact optimum)");
    cmd->callback([&run] { run = [] { return kExitUsage; }; });
}

} // namespace vl::cli
