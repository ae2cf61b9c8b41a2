#include "ui/session/SessionFace.h"

#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/phonetics/PhonemeMaps.h"
#include "ui/session/BundledAssets.h"

namespace vl::ui {

SessionFace::SessionFace(SessionCore& core) : core_(core) {
    core_.onNewDocument([this] { refinement_.clearLast(); });
}

void SessionFace::load(face::Individual individual, int resolution) {
    core_.commit("Load face", edit::setFace(core_.document(), makeFaceModel(individual, resolution)));
    core_.messages().info("Loaded the " + std::string(toString(individual)) + " face (" +
                          std::to_string(core_.document().face.cascade->parameters.size()) + " parameters)");
}

void SessionFace::setParameter(int parameter, double value) {
    Document next = edit::setParameter(core_.document(), parameter, value);
    const std::string& name =
        core_.document().face.cascade->parameters[static_cast<std::size_t>(parameter)].name;
    core_.commit("Set " + name, std::move(next), "parameter:" + name);
}

void SessionFace::setParameters(std::vector<double> values, const std::string& actionName) {
    core_.commit(actionName, edit::setParameters(core_.document(), std::move(values)));
}

void SessionFace::applyVisemePreset(const std::string& viseme) {
    core_.commit("Preset " + viseme, edit::applyVisemePreset(core_.document(), viseme));
}

void SessionFace::setInfluence(int stage, int influence, const InfluenceField& field) {
    Document next = edit::setInfluence(core_.document(), stage, influence, field);
    const std::string name = core_.document().face.cascade->stages[static_cast<std::size_t>(stage)].name;
    core_.commit("Edit field " + name, std::move(next),
                 "field:" + std::to_string(stage) + ":" + std::to_string(influence));
}

void SessionFace::setIndividual(face::Individual individual) {
    const FaceModel& face = core_.document().face;
    if (face.cascade && individual == face.individual) return;
    core_.commit("Retarget to " + std::string(toString(individual)),
                 edit::retarget(core_.document(), individual));
}

void SessionFace::useOwnFace(const OwnFaceCandidate& candidate) {
    face::FaceBuildReport report;
    Document next = edit::useOwnFace(core_.document(), candidate, &report);
    core_.beginNewDocument();
    core_.commit("Use my mesh " + candidate.name, std::move(next));
    std::size_t islands = 0;
    for (const auto& island : report.islands) islands += island.used;
    std::string text = "Face '" + candidate.name + "' built: " + std::to_string(islands) + " of " +
                       std::to_string(report.islands.size()) + " UV islands used, " +
                       std::to_string(report.holes.size()) + " holes filled, " +
                       std::to_string(static_cast<int>(100.0 * report.domainCoverage + 0.5)) +
                       "% of the face domain covered";
    core_.messages().info(std::move(text));
    // Warnings (low coverage, folds) stand out and stay in the history, as the CLI's do on stderr.
    for (const auto& warning : report.warnings)
        core_.messages().error("Face '" + candidate.name + "': warning: " + warning);
}

void SessionFace::openOwnFace(const std::filesystem::path& mesh) {
    OwnFaceCandidate candidate = loadOwnFaceCandidate(mesh);
    const std::string name = candidate.name;
    core_.commit("Open " + name + " for its landmarks",
                 edit::beginOwnFace(core_.document(), std::move(candidate)));
}

void SessionFace::placeOwnFaceLandmark(face::Landmark landmark, const Vec2& uv) {
    const std::string name(toString(landmark));
    core_.commit("Move landmark " + name, edit::placeOwnFaceLandmark(core_.document(), landmark, uv),
                 "landmark:" + name);
}

void SessionFace::buildOwnFace() {
    if (!core_.document().ownFace) throwInputError("own face", "no own-face step is open (Use my mesh...)");
    const std::shared_ptr<const OwnFaceCandidate> candidate = core_.document().ownFace; // outlives the commit
    useOwnFace(*candidate);
}

void SessionFace::cancelOwnFace() {
    if (core_.document().ownFace) core_.commit("Cancel Use my mesh", edit::cancelOwnFace(core_.document()));
}

void SessionFace::generateVisemes() {
    FrequencySource table;
    const bool spoken = core_.messages().attempt(
        "Bundled phoneme table", [&] { table = bundledPhonemeFrequencies(assetsDirectory(), "oculus"); });
    Document next = edit::generateVisemesFromFace(core_.document(), spoken ? &table : nullptr);
    core_.beginNewDocument();
    core_.commit("Generate visemes from face", std::move(next));
    core_.messages().info("Generated " + std::to_string(core_.document().visemeCount()) +
                          " visemes from the face");
}

const FaceSamples& SessionFace::samples() {
    static const FaceSamples kNone;
    const FaceModel& model = core_.document().face;
    if (!model.cascade) {
        samples_.reset();
        samplesRevision_ = 0;
        return kNone;
    }
    if (!samplesReady()) {
        samples_ = std::make_shared<const FaceSamples>(sampleFace(*model.cascade, model.domain->uvs));
        samplesRevision_ = samplesRevision();
    }
    return *samples_;
}

bool SessionFace::samplesReady() const {
    return samples_ && core_.document().face.cascade && samplesRevision_ == samplesRevision();
}

std::shared_ptr<const HeadPartSamples> SessionFace::parts() {
    const std::shared_ptr<const DeformationCascade>& cascade = core_.document().face.cascade;
    if (!cascade) {
        parts_.reset();
        partsRevision_ = 0;
        return nullptr;
    }
    if (!parts_ || partsRevision_ != core_.inputs().revision(kFacePart)) {
        partsRevision_ = core_.inputs().revision(kFacePart);
        parts_ = std::make_shared<const HeadPartSamples>();
        core_.messages().attempt("Head parts", [&] {
            parts_ = std::make_shared<const HeadPartSamples>(sampleHeadParts(*cascade));
        });
    }
    return parts_;
}

void SessionFace::setRefinementSettings(const CriterionSettings& settings) {
    core_.commit("Refinement thresholds", edit::setRefinementSettings(core_.document(), settings),
                 "refinement");
}

void SessionFace::collectRefinement() {
    auto outcome = refinement_.take();
    if (!outcome) return;
    if (outcome->index() == 1) {
        core_.messages().error("Refinement: " + std::get<1>(*outcome));
        return;
    }
    auto& finished = std::get<0>(*outcome);
    if (!core_.document().face.cascade) return;
    if (!finished.automatic) {
        refinement_.setLast(finished.report);
        core_.commit("Refinement: " + finished.report.action,
                     edit::setFaceDomain(core_.document(), finished.domain));
    } else if (refinement_.automaticInputsCurrent(core_.document())) {
        // Automatic re-adaptation is derived state: the mesh of the current step, for that step's
        // own cascade, parameters and thresholds, never an undo step of its own. A result for other
        // inputs (an undo or an edit arrived meanwhile) is dropped; poll() re-adapts to the current.
        refinement_.setLast(finished.report);
        core_.amend(edit::setFaceDomain(core_.document(), finished.domain));
    } else {
        return;
    }
    // The worker sampled the mesh it made for the view: the editor thread need not do it again.
    const FaceModel& face = core_.document().face;
    if (face.cascade == finished.cascade && face.domain == finished.domain && finished.samples) {
        samples_ = finished.samples;
        samplesRevision_ = samplesRevision();
    }
}

void SessionFace::poll() {
    collectRefinement();
    if (autoRefine_ && core_.document().face.cascade && !refinement_.running() &&
        !refinement_.automaticInputsCurrent(core_.document()))
        core_.messages().attempt("Refinement",
                                 [this] { refinement_.start(core_.document(), RefineAction::Adapt, true); });
}

} // namespace vl::ui
