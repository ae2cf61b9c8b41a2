// `visemelab avatar inspect|reduce`: real avatars (glTF / GLB / VRM) in, the same avatar out.
#include "app/cli/Command.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/TargetNames.h"

#include <cstdio>
#include <filesystem>

namespace vl::cli {

namespace {

struct InspectOptions {
    std::string input;
    std::string targets;
    std::string json;
};

// Outputs never replace an input of the run.
void refuseOverwrite(const std::string& output, const std::string& input, const char* option) {
    std::error_code ec;
    if (std::filesystem::equivalent(output, input, ec) ||
        std::filesystem::weakly_canonical(output, ec) == std::filesystem::weakly_canonical(input, ec))
        throwUsage(std::string(option) + " " + output + " is the input file; choose another path");
}

int runInspect(const InspectOptions& o) {
    if (!o.json.empty()) refuseOverwrite(o.json, o.input, "--json");
    if (!o.targets.empty()) checkGlobPattern(o.targets, "--targets");
    const AvatarScan scan = scanAvatar(loadGltfDocument(o.input), {o.targets});
    std::fputs(formatAvatarReport(scan).c_str(), stdout);
    if (!o.json.empty()) writeFileAtomically(o.json, avatarReportJson(scan).dump(2) + "\n");
    return kExitOk;
}

} // namespace

void addAvatarCommand(CLI::App& app, CommandRunner& run) {
    auto* avatar =
        app.add_subcommand("avatar", "Avatars (glTF, GLB, VRM): inspect their visemes, reduce them");
    avatar->require_subcommand(1, 1);

    auto inspect = std::make_shared<InspectOptions>();
    auto* cmd =
        avatar->add_subcommand("inspect", "Report meshes, primitives, vertex counts and which morph targets "
                                          "are visemes (and why the others are not)");
    cmd->add_option("input", inspect->input, "Avatar file (.glb, .gltf, .vrm)")->required();
    cmd->add_option("--targets", inspect->targets,
                    "Glob selecting the viseme targets by name (*, ?, [AIUEO]); default: the Oculus visemes, "
                    "with or without the viseme_ prefix");
    cmd->add_option("--json", inspect->json, "Also write the report as JSON to this file");
    cmd->callback([&run, inspect] { run = [inspect] { return runInspect(*inspect); }; });
}

} // namespace vl::cli
