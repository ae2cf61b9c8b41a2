#include "ui/session/RefinementService.h"

#include "core/adaptive/CascadeSurface.h"
#include "core/common/Error.h"
#include "core/face/FaceDomain.h"

#include <chrono>
#include <optional>

namespace vl::ui {
namespace {
// Cells per side of the coarse (u,v) base mesh every refinement starts from.
constexpr int kBaseResolution = 10;
} // namespace

struct AdaptiveWork {
    std::shared_ptr<const DeformationCascade> cascade;
    std::unique_ptr<CascadeSurface> surface;
    std::unique_ptr<AdaptiveMesh> mesh;
    // The thresholds the mesh was last refined, simplified or adapted under: with the same ones, a
    // re-adaptation only needs to look where the sliders changed the surface.
    std::optional<CriterionSettings> settings;
};

RefinementService::RefinementService() : work_(std::make_shared<AdaptiveWork>()) {}

RefinementService::~RefinementService() {
    task_.wait();
}

bool RefinementService::automaticInputsCurrent(const Document& document) const {
    return autoCascade_ == document.face.cascade && autoParameters_ == document.face.parameters &&
           autoSettings_ == document.refinement;
}

std::optional<std::variant<RefinementService::Finished, std::string>> RefinementService::take() {
    auto outcome = task_.take();
    if (!outcome) return std::nullopt;
    if (outcome->index() == 1) return std::get<1>(*outcome);
    return std::get<0>(*outcome);
}

void RefinementService::start(const Document& document, RefineAction action, bool automatic) {
    if (!document.face.cascade) throwInputError("refinement", "no face loaded: load the bundled face first");
    if (task_.running()) throwInputError("refinement", "a refinement is already running");
    validateCriterionSettings(document.refinement);
    const std::shared_ptr<const DeformationCascade> cascade = document.face.cascade;
    const std::vector<double> q = document.face.parameters;
    const CriterionSettings settings = document.refinement;
    std::vector<std::vector<double>> poses;
    if (action == RefineAction::AllVisemes)
        for (const VisemeParameters& viseme :
             document.face.presets.empty() ? oculusVisemes() : document.face.presets)
            poses.push_back(parameterVector(*cascade, viseme));
    const std::size_t verticesBefore = document.face.domain ? document.face.domain->positions.size() : 0;
    const std::size_t trianglesBefore = document.face.domain ? document.face.domain->triangles.size() : 0;
    if (automatic) {
        autoCascade_ = cascade;
        autoParameters_ = q;
        autoSettings_ = settings;
    }
    task_.start("Refining", [work = work_, cascade, q, settings, poses, action, automatic, verticesBefore,
                             trianglesBefore](const auto& progress) {
        const auto start = std::chrono::steady_clock::now();
        const std::unique_ptr<Criterion> criterion = makeCriterion(settings);
        Finished outcome;
        outcome.automatic = automatic;
        outcome.report.verticesBefore = verticesBefore;
        outcome.report.trianglesBefore = trianglesBefore;
        MeshData result;
        if (action == RefineAction::AllVisemes) {
            result =
                refineFaceMesh(*cascade, kBaseResolution, settings, poses, &outcome.report.stats, progress);
            outcome.report.action = "refined for all visemes";
        } else {
            if (work->cascade != cascade || !work->mesh) {
                // A new cascade (field edit, retargeting): start again from the base mesh.
                work->mesh.reset();
                work->surface =
                    std::make_unique<CascadeSurface>(*cascade, face::faceBaseDomain(kBaseResolution), q);
                work->mesh = std::make_unique<AdaptiveMesh>(*work->surface);
                work->cascade = cascade;
                work->settings.reset();
                outcome.report.fromBaseMesh = true;
            }
            UvBox changed = work->surface->setParameters(q);
            if (work->settings != settings) changed = UvBox::everywhere();
            outcome.report.verticesAtStart = work->mesh->mesh().n_vertices();
            if (action == RefineAction::Refine) {
                work->mesh->resample();
                outcome.report.stats = work->mesh->refine(*criterion);
                outcome.report.action = "refined";
            } else if (action == RefineAction::Simplify) {
                work->mesh->resample();
                outcome.report.stats = work->mesh->simplify(*criterion);
                outcome.report.action = "simplified";
            } else {
                outcome.report.stats = work->mesh->adapt(*criterion, changed);
                outcome.report.action = outcome.report.stats.rebuilt
                                            ? "rebuilt (the change reached most of the face)"
                                            : "re-adapted";
            }
            // Each of the three leaves every face satisfying these thresholds (or at the cap).
            work->settings = settings;
            outcome.report.maxLevel = work->mesh->maxLevel();
            result = work->mesh->toMeshData();
        }
        outcome.report.triangles = result.triangles.size();
        outcome.report.vertices = result.positions.size();
        if (action == RefineAction::AllVisemes) outcome.report.maxLevel = -1;
        outcome.domain = std::make_shared<const MeshData>(std::move(result));
        outcome.cascade = cascade;
        outcome.samples = std::make_shared<const FaceSamples>(sampleFace(*cascade, outcome.domain->uvs));
        outcome.report.milliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return outcome;
    });
}

} // namespace vl::ui
