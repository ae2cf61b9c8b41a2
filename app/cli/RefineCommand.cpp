// `visemelab refine`: adaptive refinement of a deformable face (the bundled ones or a project's) under
// a criterion; writes the refined mesh (OBJ/PLY with (u,v)) and a JSON report with the counts, the
// measured contour error over the whole surface and the timing. With --save the face of the project
// is refined for every one of its visemes and the refined (u,v) mesh is stored in the project (its
// viseme meshes regenerated on it when the face made them), as the editor's "Refine for all visemes".
#include "app/cli/Command.h"
#include "app/cli/CriterionOptions.h"
#include "core/adaptive/CascadeSurface.h"
#include "core/adaptive/ContourError.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/TextParsing.h"
#include "core/document/Commands.h"
#include "core/document/Document.h"
#include "core/document/VisemeCommands.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/io/MeshIO.h"
#include "core/project/Project.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <optional>

namespace vl::cli {

namespace {

CriterionOptions withDefaultCriterion(std::string kind) {
    CriterionOptions o;
    o.criterion = std::move(kind);
    return o;
}

struct RefineOptions {
    CriterionOptions criterion = withDefaultCriterion("depth");
    std::string face = "bundled";
    std::string project;
    std::vector<std::string> params; // NAME=VALUE
    std::string out;
    std::string report;
    int measureSamples = 8;
    bool save = false;
    const CLI::App* command = nullptr; // which criterion options were given
};

struct RefineFace {
    DeformationCascade cascade;
    std::vector<double> q;
    std::string source;
    std::optional<Project> project;
};

RefineFace loadFace(const RefineOptions& o) {
    RefineFace m;
    if (!o.project.empty()) {
        Project project = loadProject(o.project);
        if (!project.deformation.isSet()) throwInputError(o.project, "the project has no deformable face");
        m.cascade = project.deformation.cascade;
        m.q = project.deformation.values.empty() ? m.cascade.defaults() : project.deformation.values;
        m.source = o.project;
        m.project = std::move(project);
    } else {
        m.cascade = face::makeFaceCascade(parseEnum<face::Individual>(o.face, "--face"));
        m.q = m.cascade.defaults();
        m.source = o.face;
    }
    for (const auto& assignment : o.params) {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos)
            throwInputError("--param", "expected NAME=VALUE, got '" + assignment + "'");
        const std::string name = assignment.substr(0, eq);
        const int k = m.cascade.findParameter(name);
        if (k < 0) throwInputError("--param", "unknown parameter '" + name + "'");
        m.q[static_cast<std::size_t>(k)] =
            parseFiniteDouble(std::string_view(assignment).substr(eq + 1), "--param " + name);
    }
    checkParameterValues(m.cascade, m.q);
    return m;
}

nlohmann::json settingsJson(const CriterionSettings& s) {
    nlohmann::json j{{"criterion", toString(s.kind)}, {"max_depth", s.maxDepth}};
    if (s.kind == CriterionKind::Depth) j["depth"] = s.depth.depth;
    if (s.kind == CriterionKind::Normals) {
        j["angle_deg"] = s.normals.dihedralAngleDeg;
        j["normal_angle_deg"] = s.normals.normalAngleDeg;
    }
    if (s.kind == CriterionKind::Contour) {
        j["avg_error"] = s.contour.averageError;
        j["max_error"] = s.contour.maximumError;
        j["samples_per_side"] = s.contour.samplesPerSide;
    }
    return j;
}

// Stores the refined (u,v) mesh in the project through the editor's own edits (setFaceDomain, then
// generateVisemesFromFace when the face made the viseme meshes) and saves it over the file. Returns
// what happened to the viseme meshes.
std::string saveRefinedFace(const Project& project, const MeshData& refined) {
    const LoadedProject loaded = documentFromProject(project);
    Document document = edit::setFaceDomain(loaded.document, std::make_shared<const MeshData>(refined));
    // Only a set the face generated on its own (u,v) mesh is regenerated: a whole-head set (skin and
    // parts, as `visemes` writes it) or meshes from files stay as they are.
    const Document& before = loaded.document;
    const bool regenerate = edit::visemeSetMadeByFace(before) && before.face.domain &&
                            before.visemes->neutral.uvs == before.face.domain->uvs &&
                            before.visemes->neutral.triangles == before.face.domain->triangles;
    if (regenerate) document = edit::generateVisemesFromFace(document);
    allowUpdatingInPlace(project.path); // the project is this run's input and, with --save, its output
    saveProject(project.path, projectFromDocument(document, regenerate ? std::nullopt : loaded.reduction,
                                                  loaded.selectedViseme));
    return regenerate ? "the " + std::to_string(document.visemeCount()) +
                            " viseme meshes regenerated on it (the last reduction result discarded)"
                      : std::string(document.visemes
                                        ? "its viseme meshes kept (not the face's own on its (u,v) mesh)"
                                        : "no viseme meshes");
}

int runRefine(const RefineOptions& o) {
    if (o.measureSamples < 1 || o.measureSamples > 64)
        throwInputError("--measure-samples", "must be in 1..64");
    // Missing or contradictory flags are usage errors (exit 2), not bad input data (exit 3).
    if (o.save && o.project.empty())
        throwUsage("--save stores the refined mesh in a project: give --project");
    if (!o.save && o.out.empty()) throwUsage("--out is required (or --save with --project)");
    if (!o.out.empty()) (void)meshFormatFromPath(o.out); // fail on a bad extension before the work
    const RefineFace model = loadFace(o);
    // A project's own thresholds (scaled with its face) unless the command line gives others.
    const CriterionSettings settings =
        model.project ? criterionSettingsOver(o.criterion, model.project->refinement, *o.command)
                      : criterionSettings(o.criterion);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    CascadeSurface surface(model.cascade, face::faceBaseDomain(o.criterion.baseResolution), model.q);
    AdaptiveMesh mesh(surface);
    const std::size_t baseTriangles = mesh.faceCount();
    AdaptStats stats;
    std::size_t poses = 1;
    if (o.save) {
        // One (u,v) mesh for every viseme of the face, so the set generated on it is interpolable.
        std::vector<std::vector<double>> vectors;
        for (const VisemeParameters& viseme : model.project->deformation.visemes.empty()
                                                  ? oculusVisemes()
                                                  : model.project->deformation.visemes)
            vectors.push_back(parameterVector(model.cascade, viseme));
        vectors.push_back(model.q); // last: the mesh's positions are those at the project's sliders
        poses = vectors.size();
        stats = refineForPoses(mesh, surface, *makeCriterion(settings), vectors);
    } else {
        stats = mesh.refine(*makeCriterion(settings));
    }
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

    const MeshData result = mesh.toMeshData();
    const ContourErrorStats error = measureContourError(result, surface, o.measureSamples);
    if (!o.out.empty()) writeMesh(o.out, result);

    nlohmann::json report{{"face", model.source},
                          {"settings", settingsJson(settings)},
                          {"base_resolution", o.criterion.baseResolution},
                          {"base_triangles", baseTriangles},
                          {"triangles", result.triangles.size()},
                          {"vertices", result.positions.size()},
                          {"max_level", mesh.maxLevel()},
                          {"splits", stats.splits},
                          {"tests", stats.tests},
                          {"contour_error",
                           {{"average", error.average},
                            {"maximum", error.maximum},
                            {"samples_per_triangle", o.measureSamples * o.measureSamples}}},
                          {"poses", poses},
                          {"timing_ms", ms}};
    nlohmann::json params = nlohmann::json::object();
    for (std::size_t k = 0; k < model.q.size(); ++k) params[model.cascade.parameters[k].name] = model.q[k];
    report["parameters"] = params;
    std::string saved;
    if (o.save) saved = saveRefinedFace(*model.project, result);
    if (!o.report.empty()) writeFileAtomically(o.report, report.dump(2) + "\n");
    std::printf("%s: %zu triangles, %zu vertices, max level %d, contour error avg %.4g max %.4g, %.2f ms%s\n",
                o.out.empty() ? "refined" : o.out.c_str(), result.triangles.size(), result.positions.size(),
                mesh.maxLevel(), error.average, error.maximum, ms,
                o.save ? (" (refined for " + std::to_string(poses) + " poses)").c_str() : "");
    if (o.save) std::fprintf(stderr, "stored the refined mesh in %s: %s\n", o.project.c_str(), saved.c_str());
    return kExitOk;
}

} // namespace

void addRefineCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<RefineOptions>();
    auto* cmd =
        app.add_subcommand("refine", "Adaptively refine a deformable face and report its contour error");
    addCriterionOptions(cmd, options->criterion);
    cmd->add_option("--face", options->face, "Bundled individual: bundled or retarget")
        ->capture_default_str();
    cmd->add_option("--project", options->project, "Use the deformable face of this project file instead");
    cmd->add_option("--param", options->params, "Deformation parameter NAME=VALUE (repeatable)");
    cmd->add_option("--out", options->out,
                    "Refined mesh to write (.obj or .ply, with (u,v)); required unless --save");
    cmd->add_flag("--save", options->save,
                  "Refine the --project face for all its visemes and store the refined mesh in the project "
                  "(viseme meshes regenerated on it when the face made them)");
    cmd->add_option("--report", options->report, "JSON report to write");
    cmd->add_option("--measure-samples", options->measureSamples,
                    "Samples per triangle side when measuring the contour error")
        ->capture_default_str();
    cmd->callback([&run, options, cmd] {
        options->command = cmd;
        run = [options] { return runRefine(*options); };
    });
}

} // namespace vl::cli
