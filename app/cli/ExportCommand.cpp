// `visemelab export PROJECT --format glb|runtime|vrml|obj --out PATH`: ship a project's reduced
// visemes to a device runtime, a glTF viewer, XfaceEd or any OBJ tool.
#include "app/cli/Command.h"
#include "core/common/Error.h"
#include "core/export/Export.h"
#include "core/project/Project.h"
#include "core/project/ProjectRun.h"

#include <cstdio>

namespace vl::cli {

namespace {

struct ExportOptions {
    std::string project;
    std::string format;
    std::string out;
    bool quantise = false;
    bool unreduced = false;
};

int runExport(const ExportOptions& o) {
    const auto format = fromString<ExportFormat>(o.format);
    if (!format) throwInputError("--format", "expected glb, runtime, vrml or obj, got '" + o.format + "'");
    if (o.quantise && *format != ExportFormat::Runtime)
        throwInputError("--quantise", "only the runtime package can be quantised");
    const Project project = loadProject(o.project);
    vl::ExportOptions options;
    options.quantise = o.quantise;
    options.faceName = std::filesystem::path(o.project).stem().string();
    const ProjectExport exported =
        exportProjectModel(project, loadProjectVisemeSet(project), *format, o.out, options, o.unreduced);
    std::fprintf(stderr, "exported %zu key meshes (%s) as %s:\n", exported.keys,
                 o.unreduced ? "unreduced" : "reduced", toString(*format));
    for (const auto& path : exported.files) std::fprintf(stderr, "  %s\n", path.string().c_str());
    return kExitOk;
}

} // namespace

void addExportCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<ExportOptions>();
    auto* cmd = app.add_subcommand("export", "Export a project's reduced visemes (glTF, runtime package, "
                                             "XfaceEd VRML + .fdp, OBJ)");
    cmd->add_option("project", options->project, "Project file (.vlproj)")->required();
    cmd->add_option("--format", options->format, "glb | runtime | vrml | obj")->required();
    cmd->add_option("--out", options->out, "Output file (glb, runtime) or folder (vrml, obj)")->required();
    cmd->add_flag("--quantise", options->quantise, "Runtime package with 16-bit quantised positions");
    cmd->add_flag("--unreduced", options->unreduced,
                  "Export every original viseme instead of the reduced set");
    cmd->callback([&run, options] { run = [options] { return runExport(*options); }; });
}

} // namespace vl::cli
