#include "ui/session/EditorSession.h"

#include "core/gltf/AvatarKeyTargets.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/deform/FaceDomain.h"
#include "core/deform/Visemes.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "core/export/Gltf.h"
#include "core/export/ModelFrequencies.h"
#include "core/gltf/AvatarKeyTargets.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/Gltfpack.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "core/project/ProjectRun.h"
#include "core/reduce/Frequencies.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace vl::ui {
namespace {

constexpr std::size_t kMaxMessages = 200;

std::string exportMessage(ExportFormat format, const std::vector<std::filesystem::path>& written,
                          const std::filesystem::path& out) {
    return std::string("Exported ") + toString(format) + ": " + std::to_string(written.size()) +
           " file(s) to " + out.string();
}

// A new document made of a viseme set whose meshes come from `files` (absolute, or empty when
// the geometry exists only in memory): uniform frequencies, a target of half the set.
Document documentOfSet(std::shared_ptr<const VisemeSet> set, std::filesystem::path neutralFile,
                       std::vector<std::filesystem::path> visemeFiles) {
    Document document;
    for (const auto& viseme : set->visemes)
        document.frequencies.visemeFrequencies.entries.emplace_back(viseme.name, 1.0);
    document.target = std::max(1, static_cast<int>(set->size()) / 2);
    document.neutralFile = std::move(neutralFile);
    document.visemeFiles = std::move(visemeFiles);
    document.visemes = std::move(set);
    validateDocument(document);
    return document;
}

} // namespace

EditorSession::EditorSession(SpeechEngines engines)
    : history_(Document{}), inputs_(history_.currentShared()), engines_(std::move(engines)),
      speech_(engines_.synthesizer) {
    reduction_.track(inputs_.revision());
}

EditorSession::~EditorSession() {
    reduction_.cancel();
    refinement_.wait();
}

// --- history ---------------------------------------------------------------------------------

void EditorSession::retireCurrent() {
    frameDocuments_.push_back(history_.currentShared());
}

// Views and services follow the document that is current now.
void EditorSession::noteChange(const Document& before) {
    inputs_.update(history_.currentShared(), changedParts(before, document()));
    reduction_.track(inputs_.revision());
    if (before.visemes != document().visemes) {
        ++geometryGeneration_;
        if (selectedViseme >= static_cast<int>(visemeCount())) selectedViseme = -1;
    }
}

void EditorSession::commit(std::string name, Document next, std::string mergeKey) {
    retireCurrent();
    const Document& before = *frameDocuments_.back();
    history_.commit(std::move(name), std::move(next), std::move(mergeKey));
    noteChange(before);
}

void EditorSession::amend(Document next) {
    retireCurrent();
    const Document& before = *frameDocuments_.back();
    history_.amend(std::move(next));
    noteChange(before);
}

void EditorSession::undo() {
    if (!canUndo()) return;
    const std::string name = history_.undoName();
    retireCurrent();
    const Document& before = *frameDocuments_.back();
    history_.undo();
    noteChange(before);
    info("Undo: " + name);
}

void EditorSession::redo() {
    if (!canRedo()) return;
    retireCurrent();
    const Document& before = *frameDocuments_.back();
    history_.redo();
    noteChange(before);
    info("Redo: " + history_.undoName());
}

// --- messages --------------------------------------------------------------------------------

void EditorSession::info(std::string text) {
    messages_.push_back({StatusMessage::Kind::Info, std::move(text), ++messageSerial_});
    if (messages_.size() > kMaxMessages) messages_.pop_front();
}

void EditorSession::error(std::string text) {
    messages_.push_back({StatusMessage::Kind::Error, std::move(text), ++messageSerial_});
    if (messages_.size() > kMaxMessages) messages_.pop_front();
}

bool EditorSession::attempt(std::string_view what, const std::function<void()>& action) {
    try {
        action();
        return true;
    } catch (const std::exception& e) {
        // "Constraints: constraints: ..." says the same thing twice: a message that starts with
        // the action's name keeps only its own.
        const std::string_view message = e.what();
        const bool named = message.size() > what.size() + 1 && message[what.size()] == ':' &&
                           std::equal(what.begin(), what.end(), message.begin(), [](char a, char b) {
                               return std::tolower(static_cast<unsigned char>(a)) ==
                                      std::tolower(static_cast<unsigned char>(b));
                           });
        std::string text = named ? std::string(message) : std::string(what) + ": " + std::string(message);
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
        error(std::move(text));
        return false;
    }
}

// --- opening documents -----------------------------------------------------------------------

void EditorSession::beginNewDocument() {
    ++documentEpoch_;
    speech_.clear();
    refinement_.clearLast();
    lastAvatarExport_.clear();
    selectedViseme = -1;
}

void EditorSession::adopt(Loaded loaded) {
    beginNewDocument();
    reduction_.cancel();
    retireCurrent();
    const Document& before = *frameDocuments_.back();
    history_.reset(std::move(loaded.project.document));
    if (loaded.unsaved) history_.markUnsaved();
    path_ = std::move(loaded.path);
    noteChange(before);
    inputs_.reset(history_.currentShared()); // a new revision: a new document never reuses an old curve
    reduction_.track(inputs_.revision());
    ++geometryGeneration_;
    // The result the file recorded is shown until a fresh reduction replaces it.
    // (Only a result of the document's rest model: a file may record one of the other.)
    if (const auto& stored = loaded.project.reduction;
        stored && !stored->curve.empty() && static_cast<int>(stored->curve.size()) >= document().target &&
        stored->restFree == documentRestPose(document()).free)
        reduction_.seed(std::make_shared<const ReductionResult>(*stored));
    selectedViseme = visemes() ? visemes()->find(loaded.project.selectedViseme) : -1;
    info(loaded.message);
}

void EditorSession::newProject() {
    adopt({{}, {}, "New project"});
}

EditorSession::Loaded EditorSession::loadProjectFile(const std::filesystem::path& file) {
    Loaded loaded{documentFromProject(loadProject(file)), file, "Opened " + file.string()};
    // Bundled files are read-only: the document keeps its meshes (absolute paths) but has no file
    // of its own, so Save asks where to write and nothing is ever written under assets/.
    if (isBundled(file)) loaded.path.clear();
    return loaded;
}

EditorSession::Loaded EditorSession::loadFolder(const std::filesystem::path& folder) {
    const std::filesystem::path neutralFile =
        findNeutralMesh(folder); // the rule `reduce` and `project new` use
    const auto files = listVisemeFolder(folder, neutralFile);
    auto set = std::make_shared<const VisemeSet>(loadVisemeSet(neutralFile, files));
    std::vector<std::filesystem::path> visemeFiles;
    for (const auto& file : files) visemeFiles.push_back(std::filesystem::absolute(file.second));
    Loaded loaded;
    loaded.project.document =
        documentOfSet(set, std::filesystem::absolute(neutralFile), std::move(visemeFiles));
    loaded.message = "Loaded " + std::to_string(set->size()) + " visemes from " + folder.string();
    return loaded;
}

EditorSession::Loaded EditorSession::loadSampleFiles() {
    const std::filesystem::path dir = assetsDirectory();
    Loaded loaded;
    bool found = false;
    for (const char* name : {"sample/sample.vlproj", "sample.vlproj"})
        if (!found && std::filesystem::exists(dir / name)) {
            loaded = loadProjectFile(dir / name);
            found = true;
        }
    if (!found) {
        // The sample is the bundled deformable face and its 15 Oculus visemes.
        Document face;
        face.face = makeFaceModel(face::Individual::Bundled, kFaceDomainResolution);
        loaded.project.document = edit::generateVisemesFromFace(face);
    }
    loaded.path.clear();
    const Document& document = loaded.project.document;
    loaded.message = "Loaded the sample: " + std::to_string(document.visemeCount()) + " visemes, " +
                     std::to_string(document.visemes->vertexCount()) + " vertices";
    return loaded;
}

void EditorSession::openProject(const std::filesystem::path& file) {
    adopt(loadProjectFile(file));
}

void EditorSession::loadVisemeFolder(const std::filesystem::path& folder) {
    adopt(loadFolder(folder));
}

void EditorSession::loadSample() {
    adopt(loadSampleFiles());
}

void EditorSession::startLoading(std::string label, std::function<Loaded()> load) {
    files_.load(std::move(label), std::move(load));
}

void EditorSession::startOpenProject(const std::filesystem::path& file) {
    startLoading("Opening " + file.filename().string(), [file] { return loadProjectFile(file); });
}

void EditorSession::startLoadVisemeFolder(const std::filesystem::path& folder) {
    startLoading("Loading " + folder.filename().string(), [folder] { return loadFolder(folder); });
}

void EditorSession::startLoadSample() {
    startLoading("Loading the sample", loadSampleFiles);
}

void EditorSession::importGltf(const std::filesystem::path& file) {
    const ReducedModel model = readGltf(file);
    auto set = std::make_shared<const VisemeSet>(toVisemeSet(model, file));
    Loaded loaded;
    // Embedded: the geometry lives in the document (a save writes it into the project).
    loaded.project.document = documentOfSet(set, {}, std::vector<std::filesystem::path>(set->size()));
    loaded.project.document.frequencies = modelFrequencies(model, file.string());
    validateDocument(loaded.project.document);
    const bool phonemes = loaded.project.document.frequencies.isPhonemeBased();
    loaded.message = "Imported " + std::to_string(set->size()) + " morph targets from " + file.string() +
                     (phonemes ? " with its phoneme frequencies and map" : "");
    loaded.unsaved = true;
    adopt(std::move(loaded));
}

EditorSession::Loaded EditorSession::loadAvatarFile(const std::filesystem::path& file,
                                                    const std::string& pattern) {
    Loaded loaded;
    loaded.project.document = documentFromAvatar(loadDocumentAvatar(file, pattern),
                                                 bundledPhonemeFrequencies(assetsDirectory(), "oculus"));
    const Document& document = loaded.project.document;
    std::size_t meshes = 0;
    for (const AvatarMesh& mesh : document.avatar.scan->meshes) meshes += mesh.carriesVisemes ? 1 : 0;
    loaded.message = "Imported the avatar " + file.filename().string() + ": " +
                     std::to_string(document.visemeCount()) + " visemes on " + std::to_string(meshes) +
                     " mesh(es), " + std::to_string(document.visemes->vertexCount()) + " vertices";
    return loaded;
}

void EditorSession::importAvatar(const std::filesystem::path& file, const std::string& pattern) {
    adopt(loadAvatarFile(file, pattern));
}

void EditorSession::startImportAvatar(const std::filesystem::path& file, const std::string& pattern) {
    startLoading("Importing " + file.filename().string(),
                 [file, pattern] { return loadAvatarFile(file, pattern); });
}

void EditorSession::setAvatarPattern(const std::string& pattern) {
    if (document().avatar.isSet() && pattern == document().avatar.pattern) return;
    commit(
        pattern.empty() ? std::string("Viseme targets: Oculus names") : "Viseme targets '" + pattern + "'",
        edit::setAvatarPattern(document(), pattern, bundledPhonemeFrequencies(assetsDirectory(), "oculus")));
    info(std::to_string(visemeCount()) + " visemes selected by " + document().avatar.scan->selection);
}

void EditorSession::addAvatarRestViseme(const std::string& requestedName) {
    Document next = edit::addAvatarRestViseme(
        document(), bundledPhonemeFrequencies(assetsDirectory(), "oculus"), requestedName);
    const std::string name = next.avatar.scan->addedRest;
    commit("Add rest viseme " + name, std::move(next));
    select(name);
}

std::string EditorSession::writeAvatarExport(const Document& document, const Project& snapshot,
                                             const std::filesystem::path& out, const AvatarExport& options) {
    checkAvatarOutput(document, out);
    // The grouping shown (recorded in the snapshot), else a fresh reduction with the document's settings.
    const ReduceInputs inputs = projectReduceInputs(snapshot, document.visemes);
    const std::vector<int> groupOf = reducedGrouping(
        inputs, recordedGrouping(inputs, snapshot.reduction.result), ReductionService::policy());
    AvatarWriteSummary summary;
    std::string glb = reducedAvatarGlb(document, groupOf, options.write, &summary);
    if (options.gltfpack) {
        const std::filesystem::path gltfpack = findGltfpack();
        if (gltfpack.empty())
            throwInputError("gltfpack", std::string("not found, so the avatar cannot be re-compressed; ") +
                                            kGltfpackHint);
        recompressInPlace(glb, summary.notes, gltfpack, {document.avatar.pattern});
    }
    writeFileAtomically(out, glb);
    int keys = 0;
    for (int g : groupOf) keys = std::max(keys, g + 1);
    std::string message = "Exported the avatar: " + std::to_string(document.visemeCount()) + " visemes -> " +
                          std::to_string(keys) + " keys (names " + toString(options.write.names) + ")" +
                          (options.gltfpack ? ", re-compressed with gltfpack," : "") + " to " + out.string();
    for (const std::string& note : summary.notes) message += "; " + note;
    // Which target now carries which key, read back from what was written.
    for (const std::string& line : formatAvatarKeyTargets(avatarKeyTargets(glb, out.string())))
        message += "\n" + line;
    std::string resting;
    for (std::size_t i = 0; i < groupOf.size(); ++i)
        if (groupOf[i] == kRestGroup) resting += (resting.empty() ? "" : ", ") + visemeNames(document)[i];
    if (!resting.empty()) message += "\nresting (all weights 0, no target): " + resting;
    return message;
}

void EditorSession::noteAvatarExport(const std::string& message) {
    lastAvatarExport_.clear();
    std::size_t start = 0;
    for (std::size_t end = message.find('\n'); start <= message.size(); end = message.find('\n', start)) {
        if (end == std::string::npos) end = message.size();
        lastAvatarExport_.push_back(message.substr(start, end - start));
        start = end + 1;
    }
    info(lastAvatarExport_.front() + " (which target carries which key: Export panel)");
    lastAvatarExport_.erase(lastAvatarExport_.begin());
}

std::vector<std::string> EditorSession::exportAvatar(const std::filesystem::path& out,
                                                     const AvatarExport& options) {
    noteAvatarExport(writeAvatarExport(document(), projectSnapshot(), out, options));
    std::vector<std::string> lines{messages_.back().text};
    lines.insert(lines.end(), lastAvatarExport_.begin(), lastAvatarExport_.end());
    return lines;
}

void EditorSession::startExportAvatar(const std::filesystem::path& out, const AvatarExport& options) {
    if (!document().avatar.isSet())
        throwInputError("export avatar", "the document has no avatar: use File > Import avatar... first");
    files_.exportAvatar("Exporting " + out.filename().string(),
                        [out, options, document = history_.currentShared(), snapshot = projectSnapshot()] {
                            return writeAvatarExport(*document, snapshot, out, options);
                        });
}

bool EditorSession::isBundled(const std::filesystem::path& file) {
    std::error_code error;
    const auto assets = std::filesystem::weakly_canonical(assetsDirectory(), error);
    const auto canonical = std::filesystem::weakly_canonical(file, error);
    if (error) return false;
    const auto relative = canonical.lexically_relative(assets);
    return !relative.empty() && *relative.begin() != "..";
}

std::filesystem::path EditorSession::assetsDirectory() {
    if (const char* env = std::getenv("VISEMELAB_ASSETS"); env && *env) return env;
    return VISEMELAB_ASSETS_DIR;
}

// --- saving and exporting --------------------------------------------------------------------

Project EditorSession::projectSnapshot() const {
    std::optional<ReductionResult> last;
    if (currentGrouping()) {
        last.emplace();
        last->curve.assign(reductionCurve()->curve.begin(),
                           reductionCurve()->curve.begin() + document().target);
        last->restFree = reductionCurve()->restFree; // the model its resting visemes belong to
    }
    const std::string selected = visemes() && selectedViseme >= 0
                                     ? visemes()->visemes[static_cast<std::size_t>(selectedViseme)].name
                                     : "";
    Project snapshot = projectFromDocument(document(), last, selected);
    snapshot.path = path_;
    return snapshot;
}

std::filesystem::path EditorSession::saveTarget(const std::filesystem::path& file) const {
    const std::filesystem::path target = file.empty() ? path_ : file;
    if (target.empty()) throwInputError("save", "the project has no file yet: use Save As");
    if (isBundled(target)) throwInputError(target.string(), "bundled files are read-only: save elsewhere");
    return target;
}

bool EditorSession::recordSaved(const std::filesystem::path& target, std::uint64_t savedId) {
    path_ = target; // the file is the document's home from now on
    if (history_.currentId() != savedId) {
        // Edits (or another document) arrived while the file was written: they stay unsaved.
        info("Saved " + target.string() + " (changes made while saving are not in it)");
        return false;
    }
    history_.markSaved(); // undo history is kept
    info("Saved " + target.string());
    return true;
}

void EditorSession::saveProject(const std::filesystem::path& file) {
    const std::filesystem::path target = saveTarget(file);
    vl::saveProject(target, projectSnapshot());
    recordSaved(target, history_.currentId());
}

void EditorSession::startSaveProject(const std::filesystem::path& file, std::function<void()> then) {
    const std::filesystem::path target = saveTarget(file);
    files_.save("Saving " + target.filename().string(), history_.currentId(), std::move(then),
                [target, snapshot = projectSnapshot()] {
                    vl::saveProject(target, snapshot);
                    return target;
                });
}

std::vector<std::filesystem::path> EditorSession::writeExport(const Document& document,
                                                              const Project& snapshot, ExportFormat format,
                                                              const std::filesystem::path& out) {
    // The meshes shown (the document's, in memory), never re-read from their files.
    return exportProjectModel(snapshot, *document.visemes, format, out, {}, false, ReductionService::policy())
        .files;
}

std::vector<std::filesystem::path> EditorSession::exportProject(ExportFormat format,
                                                                const std::filesystem::path& out) {
    if (!visemes()) throwInputError("export", "load a viseme set first");
    auto written = writeExport(document(), projectSnapshot(), format, out);
    info(exportMessage(format, written, out));
    return written;
}

void EditorSession::startExport(ExportFormat format, const std::filesystem::path& out) {
    if (!visemes()) throwInputError("export", "load a viseme set first");
    files_.exportModel(std::string("Exporting ") + toString(format),
                       [format, out, document = history_.currentShared(), snapshot = projectSnapshot()] {
                           return exportMessage(format, writeExport(*document, snapshot, format, out), out);
                       });
}

// --- viseme set ------------------------------------------------------------------------------

void EditorSession::importViseme(const std::string& name, const std::filesystem::path& file) {
    if (!visemes()) throwInputError(file.string(), "load a neutral mesh or viseme set first");
    commit("Import viseme " + name, edit::addViseme(document(), name, readMesh(file), file));
    info("Imported " + name + " from " + file.string());
}

void EditorSession::removeViseme(int index, const std::string& phonemesGoTo) {
    const std::string name = visemes() && index >= 0 && index < static_cast<int>(visemeCount())
                                 ? visemes()->visemes[static_cast<std::size_t>(index)].name
                                 : std::to_string(index);
    const std::string selected = selectedViseme >= 0 && selectedViseme != index
                                     ? visemes()->visemes[static_cast<std::size_t>(selectedViseme)].name
                                     : std::string();
    commit("Remove viseme " + name, edit::removeViseme(document(), index, phonemesGoTo));
    select(selected);
}

// --- frequencies -----------------------------------------------------------------------------

void EditorSession::setVisemeFrequency(int viseme, double value) {
    Document next = edit::setVisemeFrequency(document(), viseme, value);
    const std::string& name = visemes()->visemes[static_cast<std::size_t>(viseme)].name;
    commit("Set frequency of " + name, std::move(next), "viseme-frequency:" + name);
}

void EditorSession::setPhonemeFrequency(int phoneme, double value) {
    Document next = edit::setPhonemeFrequency(document(), phoneme, value);
    const std::string name = document().frequencies.phonemes.entries[static_cast<std::size_t>(phoneme)].first;
    commit("Set frequency of phoneme " + name, std::move(next), "phoneme-frequency:" + name);
}

void EditorSession::setPhonemeViseme(int phoneme, const std::string& viseme) {
    Document next = edit::setPhonemeViseme(document(), phoneme, viseme);
    const std::string name = document().frequencies.phonemes.entries[static_cast<std::size_t>(phoneme)].first;
    commit("Map phoneme " + name + " to " + viseme, std::move(next));
}

void EditorSession::loadFrequencies(const std::filesystem::path& file) {
    commit("Load frequencies " + file.filename().string(),
           edit::setFrequencies(document(), loadFrequencyFile(file)));
    info("Loaded frequencies from " + file.string());
}

void EditorSession::setFrequencySource(FrequencySource source, const std::string& actionName) {
    commit(actionName, edit::setFrequencies(document(), std::move(source)));
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
    countTask_.start("Counting phonemes", [corpus, voice, make = engines_.transcriber](const auto& progress) {
        auto transcriber = make(voice);
        return countPhonemesInFile(corpus, *transcriber, [&](std::uint64_t done, std::uint64_t total) {
            progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
        });
    });
}

// --- background jobs ---------------------------------------------------------------------------

std::vector<EditorSession::JobStatus> EditorSession::runningJobs() const {
    std::vector<JobStatus> jobs;
    if (loading()) jobs.push_back({Job::Loading, loadingLabel(), std::nullopt, std::nullopt});
    if (refinement_.running()) {
        const double p = refinement_.progress();
        jobs.push_back({Job::Refinement, "Refining", p > 0 ? std::optional(p) : std::nullopt,
                        refinement_.secondsLeft()});
    }
    if (reduction_.running())
        jobs.push_back({Job::Reduction, "Reducing", reduction_.progress(), reduction_.secondsLeft()});
    if (countTask_.running())
        jobs.push_back({Job::PhonemeCount, "Transcribing", countTask_.progress(), countTask_.secondsLeft()});
    return jobs;
}

void EditorSession::cancelJob(Job job) {
    const char* what = "";
    switch (job) {
    case Job::Loading:
        if (!loading()) return;
        files_.cancelLoad();
        what = "Loading cancelled: the document is unchanged";
        break;
    case Job::Refinement:
        if (!refinement_.running()) return;
        refinement_.cancel();
        what = "Refinement cancelled: the face keeps its mesh";
        break;
    case Job::Reduction:
        if (!reduction_.running()) return;
        reduction_.stop();
        what = "Reduction stopped";
        break;
    case Job::PhonemeCount:
        if (!countTask_.running()) return;
        countTask_.requestCancel();
        what = "Phoneme count cancelled: the frequencies are unchanged";
        break;
    }
    info(what);
}

void EditorSession::saveFrequenciesCsv(const std::filesystem::path& file) const {
    writeFileAtomically(file, formatFrequencyCsv(document().frequencies));
}

// --- weights ---------------------------------------------------------------------------------

void EditorSession::setWeightMode(WeightMode mode) {
    if (mode == document().weights.mode) return;
    commit(std::string("Weights: ") + toString(mode), edit::setWeightMode(document(), mode));
}

void EditorSession::setPaintedWeights(std::vector<double> painted, const std::string& actionName) {
    commit(actionName, edit::setPaintedWeights(document(), std::move(painted)));
}

// --- deformable face -------------------------------------------------------------------------

void EditorSession::loadFace(face::Individual individual, int resolution) {
    commit("Load face", edit::setFace(document(), makeFaceModel(individual, resolution)));
    info("Loaded the " + std::string(face::individualName(individual)) + " face (" +
         std::to_string(face().cascade->parameters.size()) + " parameters)");
}

void EditorSession::setParameter(int parameter, double value) {
    Document next = edit::setParameter(document(), parameter, value);
    const std::string& name = face().cascade->parameters[static_cast<std::size_t>(parameter)].name;
    commit("Set " + name, std::move(next), "parameter:" + name);
}

void EditorSession::setParameters(std::vector<double> values, const std::string& actionName) {
    commit(actionName, edit::setParameters(document(), std::move(values)));
}

void EditorSession::applyVisemePreset(const std::string& viseme) {
    commit("Preset " + viseme, edit::applyVisemePreset(document(), viseme));
}

void EditorSession::setInfluence(int stage, int influence, const InfluenceField& field) {
    Document next = edit::setInfluence(document(), stage, influence, field);
    const std::string name = face().cascade->stages[static_cast<std::size_t>(stage)].name;
    commit("Edit field " + name, std::move(next),
           "field:" + std::to_string(stage) + ":" + std::to_string(influence));
}

void EditorSession::setIndividual(face::Individual individual) {
    if (face().cascade && individual == face().individual) return;
    commit("Retarget to " + std::string(face::individualName(individual)),
           edit::retarget(document(), individual));
}

void EditorSession::useOwnFace(const OwnFaceCandidate& candidate) {
    face::FaceBuildReport report;
    Document next = edit::useOwnFace(document(), candidate, &report);
    beginNewDocument();
    commit("Use my mesh " + candidate.name, std::move(next));
    std::size_t islands = 0;
    for (const auto& island : report.islands) islands += island.used;
    std::string text = "Face '" + candidate.name + "' built: " + std::to_string(islands) + " of " +
                       std::to_string(report.islands.size()) + " UV islands used, " +
                       std::to_string(report.holes.size()) + " holes filled, " +
                       std::to_string(static_cast<int>(100.0 * report.domainCoverage + 0.5)) +
                       "% of the face domain covered";
    info(std::move(text));
    // Warnings (low coverage, folds) stand out and stay in the history, as the CLI's do on stderr.
    for (const auto& warning : report.warnings) error("Face '" + candidate.name + "': warning: " + warning);
}

void EditorSession::openOwnFace(const std::filesystem::path& mesh) {
    OwnFaceCandidate candidate = loadOwnFaceCandidate(mesh);
    const std::string name = candidate.name;
    commit("Open " + name + " for its landmarks", edit::beginOwnFace(document(), std::move(candidate)));
}

void EditorSession::placeOwnFaceLandmark(face::Landmark landmark, const Vec2& uv) {
    const std::string name(face::landmarkName(landmark));
    commit("Move landmark " + name, edit::placeOwnFaceLandmark(document(), landmark, uv), "landmark:" + name);
}

void EditorSession::buildOwnFace() {
    if (!document().ownFace) throwInputError("own face", "no own-face step is open (Use my mesh...)");
    const std::shared_ptr<const OwnFaceCandidate> candidate = document().ownFace; // outlives the commit
    useOwnFace(*candidate);
}

void EditorSession::cancelOwnFace() {
    if (document().ownFace) commit("Cancel Use my mesh", edit::cancelOwnFace(document()));
}

// The bundled American English phoneme table with the Oculus map (generated sets, phoneme counts).
static FrequencySource bundledOculusTable() {
    const std::filesystem::path dir = EditorSession::assetsDirectory();
    for (const BundledPhonemeMap& map : bundledPhonemeMaps(dir))
        if (map.id == "oculus") return loadPhonemeFrequencySource(defaultPhonemeTablePath(dir), map.file);
    throwInputError("phoneme table", "the bundled Oculus map is missing from " + dir.string());
}

void EditorSession::generateVisemesFromFace() {
    FrequencySource table;
    const bool spoken = attempt("Bundled phoneme table", [&] { table = bundledOculusTable(); });
    Document next = edit::generateVisemesFromFace(document(), spoken ? &table : nullptr);
    beginNewDocument();
    commit("Generate visemes from face", std::move(next));
    info("Generated " + std::to_string(visemeCount()) + " visemes from the face");
}

const FaceSamples& EditorSession::faceSamples() {
    static const FaceSamples kNone;
    const FaceModel& model = face();
    if (!model.cascade) {
        samples_.reset();
        samplesCascade_.reset();
        return kNone;
    }
    if (!faceSamplesReady())
        adoptFaceSamples(model.cascade, model.domain,
                         std::make_shared<const FaceSamples>(sampleFace(*model.cascade, model.domain->uvs)));
    return *samples_;
}

bool EditorSession::faceSamplesReady() const {
    const FaceModel& model = face();
    return samples_ && model.cascade && samplesCascade_ == model.cascade && samplesDomain_ == model.domain;
}

std::shared_ptr<const HeadPartSamples> EditorSession::faceParts() {
    const std::shared_ptr<const DeformationCascade>& cascade = face().cascade;
    if (!cascade) {
        partsCascade_.reset();
        parts_.reset();
        return nullptr;
    }
    if (partsCascade_ != cascade || !parts_) {
        partsCascade_ = cascade;
        parts_ = std::make_shared<const HeadPartSamples>();
        attempt("Head parts",
                [&] { parts_ = std::make_shared<const HeadPartSamples>(sampleHeadParts(*cascade)); });
    }
    return parts_;
}

void EditorSession::adoptFaceSamples(std::shared_ptr<const DeformationCascade> cascade,
                                     std::shared_ptr<const MeshData> domain,
                                     std::shared_ptr<const FaceSamples> samples) {
    samplesCascade_ = std::move(cascade);
    samplesDomain_ = std::move(domain);
    samples_ = std::move(samples);
}

// --- refinement and reduction ----------------------------------------------------------------

void EditorSession::setRefinementSettings(const CriterionSettings& settings) {
    commit("Refinement thresholds", edit::setRefinementSettings(document(), settings), "refinement");
}

void EditorSession::setTarget(int m) {
    if (m == document().target) return;
    commit("Target m = " + std::to_string(m), edit::setTarget(document(), m), "target");
}

void EditorSession::setSpeech(SpeechSettings speech) {
    const SpeechSettings& current = document().speech;
    if (speech == current) return;
    const bool rateOnly = speech.text == current.text && speech.voice == current.voice;
    const std::string name = rateOnly ? "Speaking rate " + std::to_string(speech.wordsPerMinute) + " wpm"
                             : speech.voice != current.voice ? "Voice " + speech.voice
                                                             : std::string("Say text");
    commit(name, edit::setSpeech(document(), std::move(speech)), rateOnly ? "speech-rate" : "");
}

void EditorSession::setConstraints(ConstraintNames constraints) {
    if (constraints == document().constraints) return;
    commit("Constraints", edit::setConstraints(document(), std::move(constraints)));
}

void EditorSession::setRest(RestChoice rest, const std::string& restViseme) {
    if (rest == document().rest && restViseme == document().restViseme) return;
    commit(rest == RestChoice::Key    ? "Rest is a key"
           : rest == RestChoice::Free ? "Rest free"
                                      : "Rest free with a rest viseme",
           edit::setRest(document(), rest, restViseme));
}

void EditorSession::collectRefinement() {
    auto outcome = refinement_.take();
    if (!outcome) return;
    if (outcome->index() == 1) {
        error("Refinement: " + std::get<1>(*outcome));
        return;
    }
    auto& finished = std::get<0>(*outcome);
    if (!face().cascade) return;
    if (!finished.automatic) {
        refinement_.setLast(finished.report);
        commit("Refinement: " + finished.report.action, edit::setFaceDomain(document(), finished.domain));
    } else if (refinement_.automaticInputsCurrent(document())) {
        // Automatic re-adaptation is derived state: the mesh of the current step, for that step's
        // own cascade, parameters and thresholds, never an undo step of its own. A result for other
        // inputs (an undo or an edit arrived meanwhile) is dropped; poll() re-adapts to the current.
        refinement_.setLast(finished.report);
        amend(edit::setFaceDomain(document(), finished.domain));
    } else {
        return;
    }
    // The worker sampled the mesh it made for the view: the editor thread need not do it again.
    if (face().cascade == finished.cascade && face().domain == finished.domain && finished.samples)
        adoptFaceSamples(finished.cascade, finished.domain, finished.samples);
}

void EditorSession::poll() {
    FileJobs::Finished files = files_.poll();
    if (files.loaded) adopt(std::move(*files.loaded));
    // The held-back action (quit, open) runs only when the document it guarded is saved.
    if (files.saved && recordSaved(*files.saved, files.savedId) && files.afterSave) files.afterSave();
    for (const std::string& message : files.infos) info(message);
    if (files.avatarExported) noteAvatarExport(*files.avatarExported);
    for (const std::string& message : files.errors) error(message);
    if (auto failed = speech_.poll()) error("Say: " + *failed);
    if (auto outcome = countTask_.take()) {
        if (outcome->index() == 0) {
            const PhonemeCountResult& counted = std::get<0>(*outcome);
            attempt("Phoneme frequencies", [&] {
                FrequencySource source;
                source.phonemes = counted.counts;
                source.map = document().frequencies.isPhonemeBased() ? document().frequencies.map
                                                                     : bundledOculusTable().map;
                setFrequencySource(std::move(source),
                                   "Phoneme frequencies from " + countCorpus_.filename().string());
                info("Counted " + std::to_string(counted.phonemeTotal) + " phonemes");
            });
        } else {
            error("Phoneme count: " + std::get<1>(*outcome));
        }
    }
    collectRefinement();
    if (autoRefine && face().cascade && !refinement_.running() &&
        !refinement_.automaticInputsCurrent(document()))
        attempt("Refinement", [this] { refinement_.start(document(), RefineAction::Adapt, true); });
    if (auto failure = reduction_.poll()) error("Reduction: " + *failure);
    const int n = static_cast<int>(visemeCount());
    if (autoReduce && n >= 2 && n <= kMaxReductionVisemes && !reduction_.complete(document()) &&
        !reduction_.failedOnCurrentInputs() && !reduction_.running())
        attempt("Reduction", [this] { startReduction(); });
}

void EditorSession::finishBackgroundWork() {
    // poll() may start automatic re-runs; a few rounds settle them.
    for (int round = 0; round < 4; ++round) {
        files_.wait();
        countTask_.wait();
        speech_.wait();
        refinement_.wait();
        reduction_.wait();
        poll();
        if (refinement_.running() || reduction_.running()) continue;
        // A run poll() started may have finished already (running() is false from the worker's last
        // step): one more poll collects it, or starts the next automatic run.
        poll();
        if (!refinement_.running() && !reduction_.running()) break;
    }
}

} // namespace vl::ui
