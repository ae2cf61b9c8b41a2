#pragma once
// The session's file facet: new, open, load a folder or the sample, import (glTF, avatar), save and
// export, each also on a worker thread (FileJobs) so the window stays responsive. A loaded document
// replaces the session's in a fresh history.
#include "core/document/Document.h"
#include "core/export/Export.h"
#include "core/gltf/AvatarWriter.h"
#include "core/project/Project.h"
#include "ui/session/FileJobs.h"
#include "ui/session/SessionCore.h"
#include "ui/session/SessionReduction.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vl::ui {

class SessionFiles {
  public:
    SessionFiles(SessionCore& core, SessionReduction& reduction);

    // The project file the document was opened from or last saved to; empty = untitled (new,
    // imported, or a bundled sample, which is never written).
    const std::filesystem::path& path() const { return path_; }
    void newProject();
    void openProject(const std::filesystem::path& file);
    // A folder of meshes: the neutral by findNeutralMesh (core/io/VisemeSetFiles.h), the others are
    // visemes sorted by name; frequencies start uniform.
    void loadVisemeFolder(const std::filesystem::path& folder);
    // The bundled sample (assets/), whatever form the core ships it in.
    void loadSample();
    // The same on a worker thread (the window stays responsive while large meshes load); the
    // result replaces the document in poll(), an error becomes a message and changes nothing.
    void startOpenProject(const std::filesystem::path& file);
    void startLoadVisemeFolder(const std::filesystem::path& folder);
    void startLoadSample();
    bool loading() const { return jobs_.loading(); }
    std::string loadingLabel() const { return jobs_.loadingLabel(); }
    // The morph targets of a glTF/GLB file become the viseme set (a new, untitled document, unsaved:
    // its geometry exists only in memory) with the frequencies the file carries (ModelFrequencies.h).
    void importGltf(const std::filesystem::path& file);
    // Opens an avatar (glTF, GLB, VRM) as a new untitled document: its visemes selected by `pattern`
    // (empty: the Oculus names) over every mesh carrying them; the others are shown greyed.
    void importAvatar(const std::filesystem::path& file, const std::string& pattern = {});
    void startImportAvatar(const std::filesystem::path& file, const std::string& pattern = {});

    // Saves to `file`, or to the document's own path when empty (throws InputError when it has none).
    void saveProject(const std::filesystem::path& file = {});
    // The same on a worker thread: the document is snapshotted now (later edits are not in the file).
    // poll() records the saved file and then runs `then` (the action the unsaved-changes prompt held
    // back) when nothing was edited meanwhile; a failed save is a message and changes nothing.
    void startSaveProject(const std::filesystem::path& file = {}, std::function<void()> then = {});
    bool saving() const { return jobs_.saving(); }
    std::string savingLabel() const { return jobs_.savingLabel(); }
    // The project a save would write now: the document, the current reduction and selection.
    Project projectSnapshot() const;

    // Exports the reduced model of the document in memory (glb/runtime file, vrml/obj folder);
    // returns the files written.
    std::vector<std::filesystem::path> exportProject(ExportFormat format, const std::filesystem::path& out);
    // The same on a worker thread (it may run a fresh reduction) from a snapshot taken now; the
    // result or the error is a message in poll().
    void startExport(ExportFormat format, const std::filesystem::path& out);
    bool exporting() const { return jobs_.exporting(); }
    std::string exportingLabel() const { return jobs_.exportingLabel(); }
    // How an avatar is exported: the writer's options, and whether gltfpack re-compresses the result
    // (core/gltf/Gltfpack.h: EXT_meshopt_compression + KHR_mesh_quantization, checked by reading back).
    struct AvatarExport {
        AvatarWriteOptions write;
        bool gltfpack = false;
    };
    // Writes the avatar with its visemes reduced (the current grouping, else a fresh reduction with
    // the document's settings) as a GLB; never over the avatar it was read from. Returns the message
    // and which target carries which key (lastAvatarExport()).
    std::vector<std::string> exportAvatar(const std::filesystem::path& out, const AvatarExport& options);
    // The same on a worker thread from a snapshot taken now; the result is a message in poll().
    void startExportAvatar(const std::filesystem::path& out, const AvatarExport& options);
    // The last avatar export's keys: "key 2 (viseme_PP+viseme_FF): target 'viseme_PP' on ..." and the
    // visemes that rest (empty before any export).
    const std::vector<std::string>& lastAvatarExport() const { return lastAvatarExport_; }

    // For the session: applies finished jobs (once per frame); Cancel of a load; waiting for them.
    void poll();
    void cancelLoad() { jobs_.cancelLoad(); }
    void wait() { jobs_.wait(); }

  private:
    using Loaded = LoadedDocument;
    // Replaces the document by a loaded one (a fresh history).
    void adopt(Loaded loaded);
    static Loaded loadProjectFile(const std::filesystem::path& file);
    static Loaded loadFolder(const std::filesystem::path& folder);
    static Loaded loadSampleFiles();
    static Loaded loadAvatarFile(const std::filesystem::path& file, const std::string& pattern);
    // The message: one line saying what was written, then one line per key (and the resting visemes).
    static std::string writeAvatarExport(const Document& document, const Project& snapshot,
                                         const std::filesystem::path& out, const AvatarExport& options);
    void noteAvatarExport(const std::string& message); // status message + lastAvatarExport_
    static std::vector<std::filesystem::path> writeExport(const Document& document, const Project& snapshot,
                                                          ExportFormat format,
                                                          const std::filesystem::path& out);
    // The target of a save request (throws InputError when there is none).
    std::filesystem::path saveTarget(const std::filesystem::path& file) const;
    // Records a finished save of the document `savedRevision` (CommandHistory::currentRevision); false
    // when the document changed meanwhile (it stays unsaved).
    bool recordSaved(const std::filesystem::path& target, std::uint64_t savedRevision);

    SessionCore& core_;
    SessionReduction& reduction_;
    std::filesystem::path path_;
    std::vector<std::string> lastAvatarExport_;
    FileJobs jobs_; // open, save and export on worker threads
};

} // namespace vl::ui
