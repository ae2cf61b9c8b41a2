// `visemelab refine`: adaptive refinement of a deformable face (the bundled ones or a project's) under
// a criterion; writes the refined mesh (OBJ/PLY with (u,v)) and a JSON report with the counts, the
// measured contour error over the whole surface and the timing.
#include "app/cli/Command.h"
#include "app/cli/CriterionOptions.h"
#include "core/adaptive/CascadeSurface.h"
#include "core/adaptive/ContourError.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/deform/BundledFace.h"
#include "core/deform/FaceDomain.h"
#include "core/io/MeshIO.h"
#include "core/project/Project.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>

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
};

struct FaceModel {
    DeformationCascade cascade;
    std::vector<double> q;
    std::string source;
};

FaceModel loadFace(const RefineOptions& o) {
    FaceModel m;
    if (!o.project.empty()) {
        const Project project = loadProject(o.project);
        if (!project.deformation.isSet()) throwInputError(o.project, "the project has no deformable face");
        m.cascade = project.deformation.cascade;
        m.q = project.deformation.values.empty() ? m.cascade.defaults() : project.deformation.values;
        m.source = o.project;
    } else {
        m.cascade = face::makeFaceCascade(face::parseIndividual(o.face, "--face"));
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
    nlohmann::json j{{"criterion", criterionName(s.kind)}, {"max_depth", s.maxDepth}};
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

int runRefine(const RefineOptions& o) {
    const CriterionSettings settings = criterionSettings(o.criterion);
    if (o.measureSamples < 1 || o.measureSamples > 64)
        throwInputError("--measure-samples", "must be in 1..64");
    (void)meshFormatFromPath(o.out); // fail on a bad extension before the work
    const FaceModel model = loadFace(o);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    CascadeSurface surface(model.cascade, face::faceBaseDomain(o.criterion.baseResolution), model.q);
    AdaptiveMesh mesh(surface);
    const std::size_t baseTriangles = mesh.faceCount();
    const AdaptStats stats = mesh.refine(*makeCriterion(settings));
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

    const MeshData result = mesh.toMeshData();
    const ContourErrorStats error = measureContourError(result, surface, o.measureSamples);
    writeMesh(o.out, result);

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
                          {"timing_ms", ms}};
    nlohmann::json params = nlohmann::json::object();
    for (std::size_t k = 0; k < model.q.size(); ++k) params[model.cascade.parameters[k].name] = model.q[k];
    report["parameters"] = params;
    if (!o.report.empty()) writeFileAtomically(o.report, report.dump(2) + "\n");
    std::printf("%s: %zu triangles, %zu vertices, max level %d, contour error avg %.4g max %.4g, %.2f ms\n",
                o.out.c_str(), result.triangles.size(), result.positions.size(), mesh.maxLevel(),
                error.average, error.maximum, ms);
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
    cmd->add_option("--out", options->out, "Refined mesh to write (.obj or .ply, with (u,v))")->required();
    cmd->add_option("--report", options->report, "JSON report to write");
    cmd->add_option("--measure-samples", options->measureSamples,
                    "Samples per triangle side when measuring the contour error")
        ->capture_default_str();
    cmd->callback([&run, options] { run = [options] { return runRefine(*options); }; });
}

} // namespace vl::cli
