#include "ui/session/SessionFiles.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "core/export/GltfExport.h"
#include "core/face/FaceDomain.h"
#include "core/gltf/AvatarKeyTargets.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/Gltfpack.h"
#include "core/import/GltfImport.h"
#include "core/import/ModelFrequencies.h"
#include "core/io/VisemeSetFiles.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/ProjectRun.h"
#include "ui/session/BundledAssets.h"

#include <algorithm>

namespace vl::ui {
namespace {

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

SessionFiles::SessionFiles(SessionCore& core, SessionReduction& reduction)
    : core_(core), reduction_(reduction) {
    core_.onNewDocument([this] { lastAvatarExport_.clear(); });
}

void SessionFiles::adopt(Loaded loaded) {
    core_.beginNewDocument();
    reduction_.cancel();
    path_ = std::move(loaded.path);
    core_.replace(std::move(loaded.project.document), loaded.unsaved);
    reduction_.seed(loaded.project);
    core_.selectViseme(loaded.project.selectedViseme);
    core_.messages().info(loaded.message);
}

void SessionFiles::newProject() {
    adopt({{}, {}, "New project"});
}

SessionFiles::Loaded SessionFiles::loadProjectFile(const std::filesystem::path& file) {
    Loaded loaded{documentFromProject(loadProject(file)), file, "Opened " + file.string()};
    // Bundled files are read-only: the document keeps its meshes (absolute paths) but has no file
    // of its own, so Save asks where to write and nothing is ever written under assets/.
    if (isBundled(file)) loaded.path.clear();
    return loaded;
}

SessionFiles::Loaded SessionFiles::loadFolder(const std::filesystem::path& folder) {
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

SessionFiles::Loaded SessionFiles::loadSampleFiles() {
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

void SessionFiles::openProject(const std::filesystem::path& file) {
    adopt(loadProjectFile(file));
}

void SessionFiles::loadVisemeFolder(const std::filesystem::path& folder) {
    adopt(loadFolder(folder));
}

void SessionFiles::loadSample() {
    adopt(loadSampleFiles());
}

void SessionFiles::startOpenProject(const std::filesystem::path& file) {
    jobs_.load("Opening " + file.filename().string(), [file] { return loadProjectFile(file); });
}

void SessionFiles::startLoadVisemeFolder(const std::filesystem::path& folder) {
    jobs_.load("Loading " + folder.filename().string(), [folder] { return loadFolder(folder); });
}

void SessionFiles::startLoadSample() {
    jobs_.load("Loading the sample", loadSampleFiles);
}

void SessionFiles::importGltf(const std::filesystem::path& file) {
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

SessionFiles::Loaded SessionFiles::loadAvatarFile(const std::filesystem::path& file,
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

void SessionFiles::importAvatar(const std::filesystem::path& file, const std::string& pattern) {
    adopt(loadAvatarFile(file, pattern));
}

void SessionFiles::startImportAvatar(const std::filesystem::path& file, const std::string& pattern) {
    jobs_.load("Importing " + file.filename().string(),
               [file, pattern] { return loadAvatarFile(file, pattern); });
}

std::string SessionFiles::writeAvatarExport(const Document& document, const Project& snapshot,
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

void SessionFiles::noteAvatarExport(const std::string& message) {
    lastAvatarExport_.clear();
    std::size_t start = 0;
    for (std::size_t end = message.find('\n'); start <= message.size(); end = message.find('\n', start)) {
        if (end == std::string::npos) end = message.size();
        lastAvatarExport_.push_back(message.substr(start, end - start));
        start = end + 1;
    }
    core_.messages().info(lastAvatarExport_.front() + " (which target carries which key: Export panel)");
    lastAvatarExport_.erase(lastAvatarExport_.begin());
}

std::vector<std::string> SessionFiles::exportAvatar(const std::filesystem::path& out,
                                                    const AvatarExport& options) {
    noteAvatarExport(writeAvatarExport(core_.document(), projectSnapshot(), out, options));
    std::vector<std::string> lines{core_.messages().list().back().text};
    lines.insert(lines.end(), lastAvatarExport_.begin(), lastAvatarExport_.end());
    return lines;
}

void SessionFiles::startExportAvatar(const std::filesystem::path& out, const AvatarExport& options) {
    if (!core_.document().avatar.isSet())
        throwInputError("export avatar", "the document has no avatar: use File > Import avatar... first");
    jobs_.exportAvatar("Exporting " + out.filename().string(),
                       [out, options, document = core_.documentShared(), snapshot = projectSnapshot()] {
                           return writeAvatarExport(*document, snapshot, out, options);
                       });
}

Project SessionFiles::projectSnapshot() const {
    std::optional<ReductionResult> last;
    if (reduction_.grouping()) {
        last.emplace();
        last->curve.assign(reduction_.curve()->curve.begin(),
                           reduction_.curve()->curve.begin() + core_.document().target);
        last->restFree = reduction_.curve()->restFree; // the model its resting visemes belong to
    }
    Project snapshot = projectFromDocument(core_.document(), last, core_.selectedVisemeName());
    snapshot.path = path_;
    return snapshot;
}

std::filesystem::path SessionFiles::saveTarget(const std::filesystem::path& file) const {
    const std::filesystem::path target = file.empty() ? path_ : file;
    if (target.empty()) throwInputError("save", "the project has no file yet: use Save As");
    if (isBundled(target)) throwInputError(target.string(), "bundled files are read-only: save elsewhere");
    return target;
}

bool SessionFiles::recordSaved(const std::filesystem::path& target, std::uint64_t savedRevision) {
    path_ = target; // the file is the document's home from now on
    if (core_.revision() != savedRevision) {
        // Edits (or another document) arrived while the file was written: they stay unsaved.
        core_.messages().info("Saved " + target.string() + " (changes made while saving are not in it)");
        return false;
    }
    core_.markSaved(); // undo history is kept
    core_.messages().info("Saved " + target.string());
    return true;
}

void SessionFiles::saveProject(const std::filesystem::path& file) {
    const std::filesystem::path target = saveTarget(file);
    vl::saveProject(target, projectSnapshot());
    recordSaved(target, core_.revision());
}

void SessionFiles::startSaveProject(const std::filesystem::path& file, std::function<void()> then) {
    const std::filesystem::path target = saveTarget(file);
    jobs_.save("Saving " + target.filename().string(), core_.revision(), std::move(then),
               [target, snapshot = projectSnapshot()] {
                   vl::saveProject(target, snapshot);
                   return target;
               });
}

std::vector<std::filesystem::path> SessionFiles::writeExport(const Document& document,
                                                             const Project& snapshot, ExportFormat format,
                                                             const std::filesystem::path& out) {
    // The meshes shown (the document's, in memory), never re-read from their files.
    return exportProjectModel(snapshot, *document.visemes, format, out, {}, false, ReductionService::policy())
        .files;
}

std::vector<std::filesystem::path> SessionFiles::exportProject(ExportFormat format,
                                                               const std::filesystem::path& out) {
    if (!core_.document().visemes) throwInputError("export", "load a viseme set first");
    auto written = writeExport(core_.document(), projectSnapshot(), format, out);
    core_.messages().info(exportMessage(format, written, out));
    return written;
}

void SessionFiles::startExport(ExportFormat format, const std::filesystem::path& out) {
    if (!core_.document().visemes) throwInputError("export", "load a viseme set first");
    jobs_.exportModel(std::string("Exporting ") + toString(format),
                      [format, out, document = core_.documentShared(), snapshot = projectSnapshot()] {
                          return exportMessage(format, writeExport(*document, snapshot, format, out), out);
                      });
}

void SessionFiles::poll() {
    FileJobs::Finished files = jobs_.poll();
    if (files.loaded) adopt(std::move(*files.loaded));
    // The held-back action (quit, open) runs only when the document it guarded is saved.
    if (files.saved && recordSaved(*files.saved, files.savedRevision) && files.afterSave) files.afterSave();
    for (const std::string& message : files.infos) core_.messages().info(message);
    if (files.avatarExported) noteAvatarExport(*files.avatarExported);
    for (const std::string& message : files.errors) core_.messages().error(message);
}

} // namespace vl::ui
