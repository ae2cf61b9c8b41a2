#include "ui/session/EditorSession.h"

#include "core/project/BuiltinGeometry.h"
#include "core/project/ProjectCompare.h"

#include "core/adaptive/CascadeSurface.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/deform/CascadeSampler.h"
#include "core/deform/FaceDomain.h"
#include "core/deform/Visemes.h"
#include "core/export/Gltf.h"
#include "core/io/MeshIO.h"
#include "core/phonetics/EspeakTranscriber.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "core/project/ProjectRun.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/Weights.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>

namespace vl::ui {
namespace {

constexpr std::size_t kMaxMessages = 200;

std::vector<std::string> visemeNames(const VisemeSet* set) {
    std::vector<std::string> names;
    if (set)
        for (const auto& v : set->visemes) names.push_back(v.name);
    return names;
}

// Embedded viseme positions are held by the state's VisemeSet; the project copy keeps names only.
void stripEmbeddedPositions(Project& project) {
    for (ProjectViseme& viseme : project.visemes)
        if (viseme.isEmbedded()) viseme.positions.clear();
}

bool sameTable(const FrequencyTable& a, const FrequencyTable& b) {
    return a.entries == b.entries;
}

bool sameReductionInputs(const EditorState& a, const EditorState& b) {
    const Project& p = a.project;
    const Project& q = b.project;
    return a.visemes == b.visemes &&
           sameTable(p.frequencies.visemeFrequencies, q.frequencies.visemeFrequencies) &&
           sameTable(p.frequencies.phonemes, q.frequencies.phonemes) &&
           p.frequencies.map.entries == q.frequencies.map.entries && p.weights.mode == q.weights.mode &&
           p.weights.painted == q.weights.painted;
}

void requireFinite(double value, std::string_view what) {
    if (!std::isfinite(value) || value < 0.0)
        throwInputError(what, "must be a finite number >= 0, got " + formatDouble(value));
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// Checks what the reduction needs from a state, so an edit that would break it is refused.
void validateInputs(const EditorState& state) {
    if (!state.visemes) return;
    std::vector<std::string> names = visemeNames(state.visemes.get());
    vl::visemeFrequencies(state.project.frequencies, names);
    computeWeights(state.project.weights.mode, state.visemes->neutral, state.project.weights.painted);
}

std::string exportMessage(ExportFormat format, const std::vector<std::filesystem::path>& written,
                          const std::filesystem::path& out) {
    return std::string("Exported ") + toString(format) + ": " + std::to_string(written.size()) +
           " file(s) to " + out.string();
}

} // namespace

// The adaptive mesh and its surface live between refinement runs (the paper's dynamic mesh): only
// the worker touches them, one run at a time.
struct AdaptiveWork {
    std::shared_ptr<const DeformationCascade> cascade;
    std::unique_ptr<CascadeSurface> surface;
    std::unique_ptr<AdaptiveMesh> mesh;
};

EditorSession::EditorSession() : history_(EditorState{}) {}

EditorSession::~EditorSession() {
    reductionTask_.cancel();
    refinementTask_.wait();
}

// --- history ---------------------------------------------------------------------------------

void EditorSession::noteChange(const EditorState& before, const EditorState& after) {
    if (!sameReductionInputs(before, after)) ++inputsGeneration_;
    if (before.visemes != after.visemes) {
        ++geometryGeneration_;
        if (selectedViseme >= static_cast<int>(after.visemes ? after.visemes->size() : 0))
            selectedViseme = -1;
    }
}

std::shared_ptr<const EditorState> EditorSession::retireCurrent() {
    frameStates_.push_back(history_.currentShared());
    return frameStates_.back();
}

void EditorSession::commit(std::string name, EditorState next, std::string mergeKey) {
    const auto before = retireCurrent();
    history_.commit(std::move(name), std::move(next), std::move(mergeKey));
    noteChange(*before, state());
}

void EditorSession::resetTo(EditorState next) {
    const auto before = retireCurrent();
    history_.reset(std::move(next));
    noteChange(*before, state());
    ++inputsGeneration_; // a new document never reuses an old curve
}

void EditorSession::undo() {
    if (!canUndo()) return;
    const std::string name = history_.undoName();
    const auto before = retireCurrent();
    history_.undo();
    noteChange(*before, state());
    info("Undo: " + name);
}

void EditorSession::redo() {
    if (!canRedo()) return;
    const auto before = retireCurrent();
    history_.redo();
    noteChange(*before, state());
    info("Redo: " + history_.undoName());
}

// --- messages --------------------------------------------------------------------------------

void EditorSession::info(std::string text) {
    messages_.push_back({StatusMessage::Kind::Info, std::move(text)});
    if (messages_.size() > kMaxMessages) messages_.pop_front();
}

void EditorSession::error(std::string text) {
    messages_.push_back({StatusMessage::Kind::Error, std::move(text)});
    if (messages_.size() > kMaxMessages) messages_.pop_front();
}

bool EditorSession::attempt(std::string_view what, const std::function<void()>& action) {
    try {
        action();
        return true;
    } catch (const std::exception& e) {
        error(std::string(what) + ": " + e.what());
        return false;
    }
}

// --- files -----------------------------------------------------------------------------------

void EditorSession::newProject() {
    reductionTask_.cancel();
    resetTo(EditorState{});
    selectedViseme = -1;
    info("New project");
}

EditorState EditorSession::projectState(const std::filesystem::path& file) {
    EditorState next;
    next.project = loadProject(file);
    if (next.project.neutral.isSet())
        next.visemes = std::make_shared<const VisemeSet>(loadProjectVisemeSet(next.project));
    if (next.project.deformation.isSet()) {
        FaceModel& model = next.face;
        model.cascade = std::make_shared<const DeformationCascade>(next.project.deformation.cascade);
        // The retargeting choice is the base geometry the project saved (a built-in reference).
        model.individual = builtinIndividualOf(*model.cascade).value_or(face::Individual::Bundled);
        model.parameters = next.project.deformation.values;
        model.domain = std::make_shared<const MeshData>(
            face::faceDomainMesh(kSampleResolution, face::DomainDensity::MouthFocused));
        // The face model defines the (u,v) face space: colour the visemes' regions by it.
        if (next.visemes && next.visemes->neutral.hasUVs())
            next.visemeColours =
                std::make_shared<const std::vector<Vec3>>(face::faceColours(next.visemes->neutral.uvs));
    }
    validateInputs(next);
    stripEmbeddedPositions(next.project);
    if (isBundled(file)) untitle(next.project);
    return next;
}

bool EditorSession::isBundled(const std::filesystem::path& file) {
    std::error_code error;
    const auto assets = std::filesystem::weakly_canonical(assetsDirectory(), error);
    const auto canonical = std::filesystem::weakly_canonical(file, error);
    if (error) return false;
    const auto relative = canonical.lexically_relative(assets);
    return !relative.empty() && *relative.begin() != "..";
}

// Bundled files are read-only: the document keeps its meshes (absolute paths) but has no file of
// its own, so Save asks where to write and nothing is ever written under assets/.
void EditorSession::untitle(Project& project) {
    auto absolute = [&](std::filesystem::path& file) {
        if (!file.empty()) file = std::filesystem::absolute(resolveProjectFile(project, file));
    };
    absolute(project.neutral.file);
    for (ProjectViseme& viseme : project.visemes) absolute(viseme.file);
    project.path.clear();
}

void EditorSession::adopt(EditorState next, const std::string& message) {
    reductionTask_.cancel();
    resetTo(std::move(next));
    selectedViseme = visemes() ? visemes()->find(project().editor.selectedViseme) : -1;
    info(message);
}

void EditorSession::openProject(const std::filesystem::path& file) {
    adopt(projectState(file), "Opened " + file.string());
}

void EditorSession::startLoading(std::string label, std::function<EditorState()> load,
                                 std::function<std::string(const EditorState&)> describe) {
    if (loadTask_.running()) throwInputError(label, "another file is still loading");
    describeLoad_ = std::move(describe);
    loadTask_.start(std::move(label), [load = std::move(load)](const auto&) { return load(); });
}

void EditorSession::startOpenProject(const std::filesystem::path& file) {
    startLoading(
        "Opening " + file.filename().string(), [file] { return projectState(file); },
        [file](const EditorState&) { return "Opened " + file.string(); });
}

void EditorSession::startLoadVisemeFolder(const std::filesystem::path& folder) {
    startLoading(
        "Loading " + folder.filename().string(), [folder] { return folderState(folder); },
        [folder](const EditorState& next) {
            return "Loaded " + std::to_string(next.visemes->size()) + " visemes from " + folder.string();
        });
}

Project EditorSession::projectSnapshot() const {
    Project snapshot = project();
    // Embedded viseme positions are kept once, in the shared viseme set (undo steps stay small).
    if (visemes())
        for (ProjectViseme& viseme : snapshot.visemes)
            if (viseme.isEmbedded())
                if (const int i = visemes()->find(viseme.name); i >= 0)
                    viseme.positions = visemes()->visemes[static_cast<std::size_t>(i)].positions;
    snapshot.editor.selectedViseme = visemes() && selectedViseme >= 0
                                         ? visemes()->visemes[static_cast<std::size_t>(selectedViseme)].name
                                         : "";
    snapshot.reduction.result.reset();
    if (currentGrouping()) {
        ReductionResult last;
        last.curve.assign(reductionCurve()->curve.begin(),
                          reductionCurve()->curve.begin() + snapshot.reduction.target);
        snapshot.reduction.result = std::move(last);
    }
    if (face().cascade) {
        snapshot.deformation.cascade = *face().cascade;
        snapshot.deformation.values = face().parameters;
        if (snapshot.deformation.visemes.empty()) snapshot.deformation.visemes = oculusVisemes();
    }
    return snapshot;
}

std::filesystem::path EditorSession::saveTarget(const std::filesystem::path& file) const {
    const std::filesystem::path target = file.empty() ? project().path : file;
    if (target.empty()) throwInputError("save", "the project has no file yet: use Save As");
    return target;
}

Project EditorSession::writeProject(const std::filesystem::path& target, const Project& snapshot) {
    vl::saveProject(target, snapshot);
    Project saved = rebaseProject(snapshot, target);
    stripEmbeddedPositions(saved);
    return saved;
}

bool EditorSession::recordSaved(const std::filesystem::path& target, Project saved, std::uint64_t savedId) {
    if (history_.currentId() != savedId) {
        // Edits (or another document) arrived while the file was written: they stay unsaved.
        info("Saved " + target.string() + " (changes made while saving are not in it)");
        return false;
    }
    // The saved file is the project's new home: record it without an undo step.
    EditorState next = state();
    next.project = std::move(saved);
    retireCurrent();
    history_.reset(std::move(next));
    info("Saved " + target.string());
    return true;
}

void EditorSession::saveProject(const std::filesystem::path& file) {
    const std::filesystem::path target = saveTarget(file);
    recordSaved(target, writeProject(target, projectSnapshot()), history_.currentId());
}

void EditorSession::startSaveProject(const std::filesystem::path& file, std::function<void()> then) {
    const std::filesystem::path target = saveTarget(file);
    if (saveTask_.running()) throwInputError("save", "a save is still running");
    saveRequestId_ = history_.currentId();
    afterSave_ = std::move(then);
    saveTask_.start("Saving " + target.filename().string(),
                    [target, snapshot = projectSnapshot()](const auto&) {
                        return SaveOutcome{target, writeProject(target, snapshot)};
                    });
}

std::vector<std::filesystem::path> EditorSession::writeExport(const Project& snapshot, ExportFormat format,
                                                              const std::filesystem::path& out) {
    return exportModel(projectReducedModel(snapshot), format, out);
}

std::vector<std::filesystem::path> EditorSession::exportProject(ExportFormat format,
                                                                const std::filesystem::path& out) {
    if (!visemes()) throwInputError("export", "load a viseme set first");
    auto written = writeExport(projectSnapshot(), format, out);
    info(exportMessage(format, written, out));
    return written;
}

void EditorSession::startExport(ExportFormat format, const std::filesystem::path& out) {
    if (!visemes()) throwInputError("export", "load a viseme set first");
    if (exportTask_.running()) throwInputError("export", "an export is still running");
    exportFormat_ = format;
    exportOut_ = out;
    exportTask_.start(std::string("Exporting ") + toString(format),
                      [format, out, snapshot = projectSnapshot()](const auto&) {
                          return writeExport(snapshot, format, out);
                      });
}

void EditorSession::importGltf(const std::filesystem::path& file) {
    const VisemeSet imported = toVisemeSet(readGltf(file), file);
    EditorState next;
    next.project.neutral.embedded = imported.neutral;
    for (const auto& viseme : imported.visemes) {
        next.project.visemes.push_back({viseme.name, {}, {}}); // embedded: positions live in next.visemes
        next.project.frequencies.visemeFrequencies.entries.emplace_back(viseme.name, 1.0);
    }
    next.project.reduction.target = std::max(1, static_cast<int>(imported.size()) / 2);
    next.visemes = std::make_shared<const VisemeSet>(imported);
    validateInputs(next);
    reductionTask_.cancel();
    resetTo(std::move(next));
    selectedViseme = -1;
    info("Imported " + std::to_string(visemeCount()) + " morph targets from " + file.string());
}

EditorState EditorSession::folderState(const std::filesystem::path& folder) {
    auto files = listVisemeFolder(folder);
    auto neutral = std::find_if(files.begin(), files.end(), [](const auto& entry) {
        return lowercase(entry.first).find("neutral") != std::string::npos;
    });
    if (neutral == files.end()) throwInputError(folder.string(), "no mesh named *neutral* in the folder");
    const std::filesystem::path neutralFile = neutral->second;
    files.erase(neutral);
    EditorState next;
    auto set = std::make_shared<VisemeSet>(loadVisemeSet(neutralFile, files));
    next.project.neutral.file = std::filesystem::absolute(neutralFile);
    for (const auto& viseme : set->visemes) {
        next.project.visemes.push_back({viseme.name, std::filesystem::absolute(viseme.source), {}});
        next.project.frequencies.visemeFrequencies.entries.emplace_back(viseme.name, 1.0);
    }
    next.project.reduction.target = std::max(1, static_cast<int>(set->size()) / 2);
    next.visemes = std::move(set);
    validateInputs(next);
    return next;
}

void EditorSession::loadVisemeFolder(const std::filesystem::path& folder) {
    EditorState next = folderState(folder);
    const std::string message =
        "Loaded " + std::to_string(next.visemes->size()) + " visemes from " + folder.string();
    adopt(std::move(next), message);
}

std::filesystem::path EditorSession::assetsDirectory() {
    if (const char* env = std::getenv("VISEMELAB_ASSETS"); env && *env) return env;
    return VISEMELAB_ASSETS_DIR;
}

EditorState EditorSession::sampleState() {
    const std::filesystem::path dir = assetsDirectory();
    for (const char* name : {"sample/sample.vlproj", "sample.vlproj"})
        if (std::filesystem::exists(dir / name)) return projectState(dir / name);
    // The sample is the bundled deformable face and its 15 Oculus visemes.
    EditorState next;
    next.face = makeFaceModel(face::Individual::Bundled, kSampleResolution);
    setVisemesFromFace(next);
    return next;
}

std::string EditorSession::describeSample(const EditorState& sample) {
    return "Loaded the sample: " + std::to_string(sample.visemes->size()) + " visemes, " +
           std::to_string(sample.visemes->vertexCount()) + " vertices";
}

void EditorSession::loadSample() {
    EditorState next = sampleState();
    const std::string message = describeSample(next);
    adopt(std::move(next), message);
}

void EditorSession::startLoadSample() {
    startLoading("Loading the sample", sampleState, describeSample);
}

// --- deformable face -------------------------------------------------------------------------

FaceModel EditorSession::makeFaceModel(face::Individual individual, int resolution) {
    FaceModel model;
    model.individual = individual;
    auto cascade = std::make_shared<DeformationCascade>(face::makeFaceCascade(individual));
    model.parameters = cascade->defaults();
    model.cascade = std::move(cascade);
    model.domain =
        std::make_shared<const MeshData>(face::faceDomainMesh(resolution, face::DomainDensity::MouthFocused));
    return model;
}

void EditorSession::setVisemesFromFace(EditorState& next) {
    const std::vector<VisemeParameters> presets = oculusVisemes();
    auto set = std::make_shared<VisemeSet>(generateVisemeSet(*next.face.cascade, *next.face.domain, presets));
    next.project = Project{};
    next.project.neutral.embedded = set->neutral;
    for (const auto& viseme : set->visemes) {
        next.project.visemes.push_back({viseme.name, {}, {}}); // embedded: positions live in next.visemes
        next.project.frequencies.visemeFrequencies.entries.emplace_back(viseme.name, 1.0);
    }
    next.project.reduction.target = std::max(1, static_cast<int>(set->size()) * 2 / 3);
    next.visemeColours = std::make_shared<const std::vector<Vec3>>(face::faceColours(next.face.domain->uvs));
    next.visemes = std::move(set);
    validateInputs(next);
}

void EditorSession::loadFace(face::Individual individual, int resolution) {
    EditorState next = state();
    next.face = makeFaceModel(individual, resolution);
    commit("Load face", std::move(next));
    info("Loaded the " + std::string(face::individualName(individual)) + " face (" +
         std::to_string(face().cascade->parameters.size()) + " parameters)");
}

void EditorSession::setParameter(int parameter, double value) {
    const FaceModel& model = face();
    if (!model.cascade || parameter < 0 || parameter >= static_cast<int>(model.parameters.size())) return;
    std::vector<double> q = model.parameters;
    q[static_cast<std::size_t>(parameter)] = value;
    checkParameterValues(*model.cascade, q);
    EditorState next = state();
    next.face.parameters = std::move(q);
    const std::string& name = model.cascade->parameters[static_cast<std::size_t>(parameter)].name;
    commit("Set " + name, std::move(next), "parameter:" + name);
}

void EditorSession::setParameters(std::vector<double> values, const std::string& actionName) {
    if (!face().cascade) throwInputError("parameters", "no face loaded");
    checkParameterValues(*face().cascade, values);
    EditorState next = state();
    next.face.parameters = std::move(values);
    commit(actionName, std::move(next));
}

void EditorSession::applyVisemePreset(const std::string& viseme) {
    if (!face().cascade) throwInputError("viseme preset", "no face loaded");
    for (const VisemeParameters& preset : oculusVisemes())
        if (preset.name == viseme)
            return setParameters(parameterVector(*face().cascade, preset), "Preset " + viseme);
    throwInputError("viseme preset", "unknown viseme '" + viseme + "'");
}

void EditorSession::setInfluence(int stage, int influence, const InfluenceField& field) {
    if (!face().cascade) throwInputError("field", "no face loaded");
    auto cascade = std::make_shared<DeformationCascade>(*face().cascade);
    if (stage < 0 || stage >= static_cast<int>(cascade->stages.size()))
        throwInputError("field", "no such stage");
    auto& influences = cascade->stages[static_cast<std::size_t>(stage)].field.influences;
    if (influence < 0 || influence >= static_cast<int>(influences.size()))
        throwInputError("field", "no such influence region");
    influences[static_cast<std::size_t>(influence)] = field;
    validateCascade(*cascade);
    EditorState next = state();
    const std::string name = cascade->stages[static_cast<std::size_t>(stage)].name;
    next.face.cascade = std::move(cascade);
    commit("Edit field " + name, std::move(next),
           "field:" + std::to_string(stage) + ":" + std::to_string(influence));
}

void EditorSession::setIndividual(face::Individual individual) {
    if (!face().cascade) throwInputError("base geometry", "no face loaded");
    if (individual == face().individual) return;
    VectorField base;
    base.sampled = face::makeFaceGeometry(individual);
    EditorState next = state();
    next.face.cascade = std::make_shared<const DeformationCascade>(
        retarget(*face().cascade, base, std::string(face::individualName(individual))));
    next.face.individual = individual;
    commit("Retarget to " + std::string(face::individualName(individual)), std::move(next));
}

void EditorSession::generateVisemesFromFace() {
    if (!face().cascade) throwInputError("generate visemes", "no face loaded");
    EditorState next = state();
    setVisemesFromFace(next);
    next.project.path = project().path;
    // Keep the frequency table, weight mode and target when they still fit the new set (the
    // visemes keep their names; painted weights do not survive a new mesh).
    EditorState kept = next;
    kept.project.frequencies = project().frequencies;
    if (project().weights.mode != WeightMode::Painted) kept.project.weights.mode = project().weights.mode;
    if (project().reduction.target <= static_cast<int>(next.visemes->size()))
        kept.project.reduction.target = project().reduction.target;
    bool keep = true;
    try {
        validateInputs(kept);
    } catch (const InputError&) {
        keep = false;
    }
    commit("Generate visemes from face", keep ? std::move(kept) : std::move(next));
    info("Generated " + std::to_string(visemeCount()) + " visemes from the face");
}

const FaceSamples& EditorSession::faceSamples() {
    const FaceModel& model = face();
    if (!model.cascade) {
        samples_ = {};
        samplesCascade_ = nullptr;
        return samples_;
    }
    if (samplesCascade_ == model.cascade.get() && samplesDomain_ == model.domain.get()) return samples_;
    const auto& uvs = model.domain->uvs;
    const DeformationCascade& cascade = *model.cascade;
    const std::size_t k = cascade.parameters.size();
    // The cascade is linear in q: sample it at q = 0 and at each unit vector e_k. The core's
    // sampler (fields sampled once, sparse sums) does it when 0 and 1 are valid values of every
    // parameter; otherwise the per-point evaluation does.
    const bool unitVectorsValid =
        std::all_of(cascade.parameters.begin(), cascade.parameters.end(),
                    [](const DeformParameter& p) { return p.min <= 0.0 && p.max >= 1.0; });
    std::vector<double> q(k, 0.0);
    auto evaluateAll = [&](const CascadeSampler* sampler) {
        if (sampler) return sampler->evaluate(q);
        std::vector<Vec3> points;
        points.reserve(uvs.size());
        for (const Vec2& uv : uvs) points.push_back(cascade.evaluateUnchecked(uv[0], uv[1], q));
        return points;
    };
    std::optional<CascadeSampler> sampler;
    if (unitVectorsValid) sampler.emplace(cascade, uvs);
    FaceSamples out;
    out.rest = evaluateAll(sampler ? &*sampler : nullptr);
    for (std::size_t p = 0; p < k; ++p) {
        q.assign(k, 0.0);
        q[p] = 1.0;
        out.targets.push_back(evaluateAll(sampler ? &*sampler : nullptr));
    }
    out.colours = face::faceColours(uvs);
    samples_ = std::move(out);
    samplesCascade_ = model.cascade.get();
    samplesDomain_ = model.domain.get();
    return samples_;
}

void EditorSession::importViseme(const std::string& name, const std::filesystem::path& file) {
    if (!visemes()) throwInputError(file.string(), "load a neutral mesh or viseme set first");
    if (name.empty()) throwInputError(file.string(), "the viseme needs a name");
    if (visemes()->find(name) >= 0)
        throwInputError(file.string(), "a viseme named '" + name + "' already exists");
    MeshData mesh = readMesh(file);
    checkInterpolable(visemes()->neutral, visemes()->neutralSource.string(), mesh, file.string());
    EditorState next = state();
    auto set = std::make_shared<VisemeSet>(*visemes());
    set->visemes.push_back({name, file, std::move(mesh.positions)});
    next.visemes = std::move(set);
    next.project.visemes.push_back({name, std::filesystem::absolute(file), {}});
    if (!next.project.frequencies.isPhonemeBased())
        next.project.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    validateInputs(next);
    commit("Import viseme " + name, std::move(next));
    info("Imported " + name + " from " + file.string());
}

void EditorSession::removeViseme(int index) {
    if (!visemes() || index < 0 || index >= static_cast<int>(visemeCount())) return;
    if (visemeCount() <= 2) throwInputError("remove viseme", "a viseme set needs at least 2 visemes");
    const auto i = static_cast<std::size_t>(index);
    EditorState next = state();
    auto set = std::make_shared<VisemeSet>(*visemes());
    const std::string name = set->visemes[i].name;
    set->visemes.erase(set->visemes.begin() + index);
    next.visemes = std::move(set);
    auto& projectVisemes = next.project.visemes;
    projectVisemes.erase(std::remove_if(projectVisemes.begin(), projectVisemes.end(),
                                        [&](const ProjectViseme& v) { return v.name == name; }),
                         projectVisemes.end());
    auto& direct = next.project.frequencies.visemeFrequencies.entries;
    direct.erase(std::remove_if(direct.begin(), direct.end(), [&](const auto& e) { return e.first == name; }),
                 direct.end());
    next.project.reduction.target =
        std::min(next.project.reduction.target, static_cast<int>(next.visemes->size()));
    validateInputs(next);
    commit("Remove viseme " + name, std::move(next));
}

// --- frequencies -----------------------------------------------------------------------------

std::vector<double> EditorSession::visemeFrequencies() const {
    return vl::visemeFrequencies(project().frequencies, visemeNames(visemes()));
}

void EditorSession::setVisemeFrequency(int viseme, double value) {
    if (!visemes() || viseme < 0 || viseme >= static_cast<int>(visemeCount())) return;
    const std::string& name = visemes()->visemes[static_cast<std::size_t>(viseme)].name;
    requireFinite(value, "frequency of " + name);
    if (project().frequencies.isPhonemeBased())
        throwInputError("frequency of " + name, "frequencies come from the phoneme table: edit the phonemes");
    EditorState next = state();
    auto& entries = next.project.frequencies.visemeFrequencies.entries;
    auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == name; });
    if (it == entries.end())
        entries.emplace_back(name, value);
    else
        it->second = value;
    validateInputs(next);
    commit("Set frequency of " + name, std::move(next), "viseme-frequency:" + name);
}

void EditorSession::setPhonemeFrequency(int phoneme, double value) {
    auto& entries = project().frequencies.phonemes.entries;
    if (phoneme < 0 || phoneme >= static_cast<int>(entries.size())) return;
    const std::string name = entries[static_cast<std::size_t>(phoneme)].first;
    requireFinite(value, "frequency of phoneme " + name);
    EditorState next = state();
    next.project.frequencies.phonemes.entries[static_cast<std::size_t>(phoneme)].second = value;
    validateInputs(next);
    commit("Set frequency of phoneme " + name, std::move(next), "phoneme-frequency:" + name);
}

void EditorSession::setPhonemeViseme(int phoneme, const std::string& viseme) {
    const auto& table = project().frequencies.phonemes.entries;
    if (phoneme < 0 || phoneme >= static_cast<int>(table.size())) return;
    if (!visemes() || visemes()->find(viseme) < 0)
        throwInputError("phoneme map", "unknown viseme '" + viseme + "'");
    const std::string name = table[static_cast<std::size_t>(phoneme)].first;
    EditorState next = state();
    auto& map = next.project.frequencies.map.entries;
    auto it = std::find_if(map.begin(), map.end(), [&](const auto& e) { return e.first == name; });
    if (it == map.end())
        map.emplace_back(name, viseme);
    else
        it->second = viseme;
    validateInputs(next);
    commit("Map phoneme " + name + " to " + viseme, std::move(next));
}

void EditorSession::loadFrequencies(const std::filesystem::path& file) {
    EditorState next = state();
    next.project.frequencies = loadFrequencyFile(file);
    validateInputs(next);
    commit("Load frequencies " + file.filename().string(), std::move(next));
    info("Loaded frequencies from " + file.string());
}

void EditorSession::setFrequencySource(FrequencySource source, const std::string& actionName) {
    EditorState next = state();
    next.project.frequencies = std::move(source);
    validateInputs(next);
    commit(actionName, std::move(next));
}

void EditorSession::useBundledPhonemeMap(const std::string& mapId) {
    const auto dir = assetsDirectory();
    for (const BundledPhonemeMap& map : bundledPhonemeMaps(dir))
        if (map.id == mapId)
            return setFrequencySource(loadPhonemeFrequencySource(defaultPhonemeTablePath(dir), map.file),
                                      "Phoneme table with map " + map.title);
    throwInputError("phoneme map", "no bundled map '" + mapId + "'");
}

void EditorSession::startPhonemeCount(const std::filesystem::path& corpus, const std::string& voice) {
    if (!visemes()) throwInputError("phoneme count", "load a viseme set first");
    if (countTask_.running()) throwInputError("phoneme count", "a count is already running");
    countCorpus_ = corpus;
    countTask_.start("Counting phonemes", [corpus, voice](const auto& progress) {
        auto transcriber = makeEspeakTranscriber(voice);
        return countPhonemesInFile(corpus, *transcriber, [&](std::uint64_t done, std::uint64_t total) {
            progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
        });
    });
}

void EditorSession::saveFrequenciesCsv(const std::filesystem::path& file) const {
    const FrequencySource& source = project().frequencies;
    std::string text;
    if (source.isPhonemeBased()) {
        text = "phoneme,frequency,viseme\n";
        for (const auto& [phoneme, f] : source.phonemes.entries) {
            const std::string* viseme = source.map.visemeOf(phoneme);
            text += phoneme + "," + formatDouble(f) + "," + (viseme ? *viseme : std::string()) + "\n";
        }
    } else {
        text = "viseme,frequency\n";
        for (const auto& [name, f] : source.visemeFrequencies.entries)
            text += name + "," + formatDouble(f) + "\n";
    }
    writeFileAtomically(file, text);
}

// --- weights ---------------------------------------------------------------------------------

std::vector<double> EditorSession::weights() const {
    if (!visemes()) return {};
    return computeWeights(project().weights.mode, visemes()->neutral, project().weights.painted);
}

void EditorSession::setWeightMode(WeightMode mode) {
    if (mode == project().weights.mode) return;
    EditorState next = state();
    next.project.weights.mode = mode;
    // Painting starts from what was shown, not from all ones (an "add" stroke would be lost); weights
    // painted before are kept.
    if (mode == WeightMode::Painted && visemes() &&
        next.project.weights.painted.size() != visemes()->vertexCount())
        next.project.weights.painted =
            weightsForPainting(project().weights.mode, visemes()->neutral, project().weights.painted);
    validateInputs(next);
    commit(std::string("Weights: ") + toString(mode), std::move(next));
}

void EditorSession::setPaintedWeights(std::vector<double> painted, const std::string& actionName) {
    if (!visemes()) throwInputError("weights", "no mesh loaded");
    EditorState next = state();
    next.project.weights.mode = WeightMode::Painted;
    next.project.weights.painted = std::move(painted);
    validateInputs(next);
    commit(actionName, std::move(next));
}

// --- adaptive refinement ---------------------------------------------------------------------

void EditorSession::setRefinementSettings(const CriterionSettings& settings) {
    validateCriterionSettings(settings);
    EditorState next = state();
    next.project.refinement = settings;
    commit("Refinement thresholds", std::move(next), "refinement");
}

void EditorSession::startRefinement(RefineAction action) {
    startRefinementTask(action, false);
}

void EditorSession::startRefinementTask(RefineAction action, bool automatic) {
    if (!face().cascade) throwInputError("refinement", "no face loaded: load the bundled face first");
    if (refinementTask_.running()) throwInputError("refinement", "a refinement is already running");
    validateCriterionSettings(project().refinement);
    // The worker gets copies: later edits do not reach it.
    const std::shared_ptr<const DeformationCascade> cascade = face().cascade;
    const std::vector<double> q = face().parameters;
    const CriterionSettings settings = project().refinement;
    std::vector<std::vector<double>> poses;
    if (action == RefineAction::AllVisemes)
        for (const VisemeParameters& viseme : oculusVisemes())
            poses.push_back(parameterVector(*cascade, viseme));
    if (!adaptive_) adaptive_ = std::make_shared<AdaptiveWork>();
    if (automatic) {
        autoCascade_ = cascade;
        autoParameters_ = q;
        autoSettings_ = settings;
    }
    refinementTask_.start(
        "Refining", [work = adaptive_, cascade, q, settings, poses, action, automatic](const auto&) {
            const auto start = std::chrono::steady_clock::now();
            const std::unique_ptr<Criterion> criterion = makeCriterion(settings);
            RefineOutcome outcome;
            outcome.automatic = automatic;
            MeshData result;
            if (action == RefineAction::AllVisemes) {
                result = refineFaceMesh(*cascade, 10, settings, poses, &outcome.report.stats);
                outcome.report.action = "refined for all visemes";
            } else {
                if (work->cascade != cascade || !work->mesh) {
                    // A new cascade (field edit, retargeting): start again from the base mesh.
                    work->mesh.reset();
                    work->surface = std::make_unique<CascadeSurface>(*cascade, face::faceBaseDomain(10), q);
                    work->mesh = std::make_unique<AdaptiveMesh>(*work->surface);
                    work->cascade = cascade;
                } else {
                    work->surface->setParameters(q);
                }
                if (action == RefineAction::Refine) {
                    work->mesh->resample();
                    outcome.report.stats = work->mesh->refine(*criterion);
                    outcome.report.action = "refined";
                } else if (action == RefineAction::Simplify) {
                    work->mesh->resample();
                    outcome.report.stats = work->mesh->simplify(*criterion);
                    outcome.report.action = "simplified";
                } else {
                    outcome.report.stats = work->mesh->adapt(*criterion);
                    outcome.report.action = "re-adapted";
                }
                outcome.report.maxLevel = work->mesh->maxLevel();
                result = work->mesh->toMeshData();
            }
            outcome.report.triangles = result.triangles.size();
            outcome.report.vertices = result.positions.size();
            if (action == RefineAction::AllVisemes) outcome.report.maxLevel = -1;
            outcome.domain = std::make_shared<const MeshData>(std::move(result));
            outcome.report.milliseconds =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            return outcome;
        });
}

// --- reduction -------------------------------------------------------------------------------

void EditorSession::setTarget(int m) {
    const int n = static_cast<int>(visemeCount());
    if (m < 1 || m > std::max(n, 1))
        throwInputError("target", "m must be in 1.." + std::to_string(n) + ", got " + std::to_string(m));
    if (m == project().reduction.target) return;
    EditorState next = state();
    next.project.reduction.target = m;
    commit("Target m = " + std::to_string(m), std::move(next), "target");
}

const ReductionResult* EditorSession::reductionCurve() const {
    return curve_.result && curve_.inputsGeneration == inputsGeneration_ ? curve_.result.get() : nullptr;
}

const Grouping* EditorSession::currentGrouping() const {
    const ReductionResult* curve = reductionCurve();
    const int m = project().reduction.target;
    if (!curve || m < 1 || m > static_cast<int>(curve->curve.size())) return nullptr;
    return &curve->curve[static_cast<std::size_t>(m - 1)];
}

const std::vector<std::vector<Vec3>>& EditorSession::mergedShapes() {
    const Grouping* grouping = currentGrouping();
    if (!grouping) {
        merged_.clear();
        mergedFor_ = nullptr;
        return merged_;
    }
    if (mergedFor_ != reductionCurve() || mergedGroups_ != project().reduction.target) {
        std::vector<std::vector<Vec3>> shapes;
        for (const auto& v : visemes()->visemes) shapes.push_back(v.positions);
        const std::vector<double> f = visemeFrequencies();
        merged_.clear();
        for (const auto& group : grouping->groups) merged_.push_back(mergeGroup(shapes, f, group));
        mergedFor_ = reductionCurve();
        mergedGroups_ = project().reduction.target;
    }
    return merged_;
}

void EditorSession::startReduction() {
    if (!visemes() || visemeCount() < 2)
        throwInputError("reduction", "load a viseme set with at least 2 visemes");
    if (reductionCurve()) return;
    if (reductionTask_.running() && runningGeneration_ == inputsGeneration_) return;
    const int n = static_cast<int>(visemeCount());
    if (n > kMaxExactVisemes)
        throwInputError("reduction", "exact reduction handles at most " + std::to_string(kMaxExactVisemes) +
                                         " visemes, the set has " + std::to_string(n));
    // Inputs are copied: the worker must not see later edits.
    auto shapes = std::make_shared<std::vector<std::vector<Vec3>>>();
    for (const auto& v : visemes()->visemes) shapes->push_back(v.positions);
    auto frequencies = std::make_shared<std::vector<double>>(visemeFrequencies());
    auto w = std::make_shared<std::vector<double>>(weights());
    runningGeneration_ = inputsGeneration_;
    reductionTask_.start("Reducing " + std::to_string(n) + " visemes",
                         [shapes, frequencies, w, n](const auto& progress) {
                             ReductionProblem problem{*shapes, *frequencies, *w, n};
                             return std::make_shared<const ReductionResult>(reduceVisemes(problem, progress));
                         });
}

void EditorSession::poll() {
    if (auto outcome = loadTask_.take()) {
        if (outcome->index() == 0) {
            const std::string message = describeLoad_(std::get<0>(*outcome));
            adopt(std::move(std::get<0>(*outcome)), message);
        } else {
            error(loadTask_.label() + ": " + std::get<1>(*outcome));
        }
    }
    if (auto outcome = saveTask_.take()) {
        auto then = std::exchange(afterSave_, nullptr);
        if (outcome->index() == 0) {
            SaveOutcome& saved = std::get<0>(*outcome);
            // The held-back action (quit, open) runs only when the document it guarded is saved.
            if (recordSaved(saved.target, std::move(saved.saved), saveRequestId_) && then) then();
        } else {
            error(saveTask_.label() + ": " + std::get<1>(*outcome));
        }
    }
    if (auto outcome = exportTask_.take()) {
        if (outcome->index() == 0) {
            info(exportMessage(exportFormat_, std::get<0>(*outcome), exportOut_));
        } else {
            error(exportTask_.label() + ": " + std::get<1>(*outcome));
        }
    }
    if (auto outcome = countTask_.take()) {
        if (outcome->index() == 0) {
            const PhonemeCountResult& counted = std::get<0>(*outcome);
            attempt("Phoneme frequencies", [&] {
                FrequencySource source;
                source.phonemes = counted.counts;
                if (project().frequencies.isPhonemeBased()) {
                    source.map = project().frequencies.map;
                } else {
                    for (const BundledPhonemeMap& map : bundledPhonemeMaps(assetsDirectory()))
                        if (map.id == "oculus")
                            source.map = loadPhonemeFrequencySource(
                                             defaultPhonemeTablePath(assetsDirectory()), map.file)
                                             .map;
                }
                setFrequencySource(std::move(source),
                                   "Phoneme frequencies from " + countCorpus_.filename().string());
                info("Counted " + std::to_string(counted.phonemeTotal) + " phonemes");
            });
        } else {
            error("Phoneme count: " + std::get<1>(*outcome));
        }
    }
    if (auto outcome = refinementTask_.take()) {
        if (outcome->index() == 0) {
            RefineOutcome& result = std::get<0>(*outcome);
            if (!result.automatic) {
                lastRefinement_ = result.report;
                if (face().cascade) {
                    EditorState next = state();
                    next.face.domain = result.domain;
                    commit("Refinement: " + result.report.action, std::move(next));
                }
            } else if (face().cascade && autoInputsCurrent()) {
                // Automatic re-adaptation is derived state: the mesh of the current step, for that
                // step's own cascade, parameters and thresholds, never an undo step of its own. A
                // result for other inputs (an undo or an edit arrived meanwhile) is dropped; the
                // check below re-adapts to the current inputs.
                lastRefinement_ = result.report;
                EditorState next = state();
                next.face.domain = result.domain;
                retireCurrent();
                history_.amend(std::move(next));
            }
        } else {
            error("Refinement: " + std::get<1>(*outcome));
        }
    }
    if (autoRefine && face().cascade && !refinementTask_.running() && !autoInputsCurrent())
        attempt("Refinement", [this] { startRefinementTask(RefineAction::Adapt, true); });
    if (auto outcome = reductionTask_.take()) {
        if (outcome->index() == 0) {
            if (runningGeneration_ == inputsGeneration_) curve_ = {std::get<0>(*outcome), runningGeneration_};
        } else {
            error("Reduction: " + std::get<1>(*outcome));
            runningGeneration_ = 0;
        }
    }
    const int n = static_cast<int>(visemeCount());
    const bool failedOnThese = runningGeneration_ == inputsGeneration_ && !reductionTask_.running();
    if (autoReduce && n >= 2 && n <= kMaxExactVisemes && !reductionCurve() && !failedOnThese &&
        !reductionTask_.running())
        attempt("Reduction", [this] { startReduction(); });
}

bool EditorSession::autoInputsCurrent() const {
    return autoCascade_ == face().cascade && autoParameters_ == face().parameters &&
           sameRefinement(autoSettings_, project().refinement);
}

void EditorSession::finishBackgroundWork() {
    // poll() may start automatic re-runs; a few rounds settle them.
    for (int round = 0; round < 4; ++round) {
        loadTask_.wait();
        saveTask_.wait();
        exportTask_.wait();
        countTask_.wait();
        refinementTask_.wait();
        reductionTask_.wait();
        poll();
        if (!refinementTask_.running() && !reductionTask_.running()) break;
    }
}

} // namespace vl::ui
