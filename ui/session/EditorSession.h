#pragma once
// The editor's session: the document (core/document/Document.h, the one source of truth of what
// the designer edits) in an undo history, the services that compute what derives from it
// (reduction, refinement) and the file jobs. No GL or ImGui: the panels call these methods, and so
// do the tests. Each edit is a validated command of the core (core/document/Commands.h) committed
// as one undo step only when it applied, so bad input changes nothing.
#include "core/document/Document.h"
#include "core/document/DocumentInputs.h"
#include "core/document/OwnFace.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/export/Export.h"
#include "core/gltf/AvatarWriter.h"
#include "core/mesh/VisemeSet.h"
#include "core/paint/SculptBrush.h"
#include "core/phonetics/PhonemeCounting.h"
#include "core/project/Project.h"
#include "core/reduce/Reduction.h"
#include "ui/session/BackgroundTask.h"
#include "ui/session/CommandHistory.h"
#include "ui/session/FaceSamples.h"
#include "ui/session/FileJobs.h"
#include "ui/session/ReductionService.h"
#include "ui/session/RefinementService.h"
#include "ui/session/SpeechService.h"

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl::ui {

struct StatusMessage {
    enum class Kind { Info, Error } kind = Kind::Info;
    std::string text;
    std::uint64_t serial = 0; // 1, 2, ... in the order the session posted them
};

class EditorSession {
  public:
    // The speech engines Say and the corpus count use (core/phonetics/SpeechEngines.h); the default
    // argument is evaluated where the session is made, so the session itself constructs none.
    explicit EditorSession(SpeechEngines engines = espeakSpeechEngines());
    ~EditorSession();

    // --- the document ----------------------------------------------------------------------------
    const Document& document() const { return history_.current(); }
    const VisemeSet* visemes() const { return document().visemes.get(); }
    std::size_t visemeCount() const { return document().visemeCount(); }
    const FaceModel& face() const { return document().face; }
    // The project file the document was opened from or last saved to; empty = untitled (new,
    // imported, or a bundled sample, which is never written).
    const std::filesystem::path& path() const { return path_; }

    // --- files -------------------------------------------------------------------------------
    void newProject();
    void openProject(const std::filesystem::path& file);
    // The same on a worker thread (the window stays responsive while large meshes load); the
    // result replaces the document in poll(), an error becomes a message and changes nothing.
    void startOpenProject(const std::filesystem::path& file);
    void startLoadVisemeFolder(const std::filesystem::path& folder);
    bool loading() const { return files_.loading(); }
    std::string loadingLabel() const { return files_.loadingLabel(); }
    // Saves to `file`, or to the document's own path when empty (throws InputError when it has none).
    void saveProject(const std::filesystem::path& file = {});
    // The same on a worker thread: the document is snapshotted now (later edits are not in the file).
    // poll() records the saved file and then runs `then` (the action the unsaved-changes prompt held
    // back) when nothing was edited meanwhile; a failed save is a message and changes nothing.
    void startSaveProject(const std::filesystem::path& file = {}, std::function<void()> then = {});
    bool saving() const { return files_.saving(); }
    std::string savingLabel() const { return files_.savingLabel(); }
    // A folder of meshes: the neutral by findNeutralMesh (core/io/VisemeSetFiles.h), the others are
    // visemes sorted by name; frequencies start uniform.
    void loadVisemeFolder(const std::filesystem::path& folder);
    // The bundled sample (assets/), whatever form the core ships it in.
    void loadSample();
    void startLoadSample(); // the same on a worker thread, like startOpenProject
    static std::filesystem::path assetsDirectory();
    // Adds one viseme mesh; throws the core's interpolability error and changes nothing on failure.
    void importViseme(const std::string& name, const std::filesystem::path& file);
    // Phonemes mapped to the viseme go to `phonemesGoTo`; without one such a removal is refused.
    void removeViseme(int index, const std::string& phonemesGoTo = {});
    bool modified() const { return history_.modified(); }
    // The project a save would write now: the document, the current reduction and selection.
    Project projectSnapshot() const;
    // Exports the reduced model of the document in memory (glb/runtime file, vrml/obj folder);
    // returns the files written.
    std::vector<std::filesystem::path> exportProject(ExportFormat format, const std::filesystem::path& out);
    // The same on a worker thread (it may run a fresh reduction) from a snapshot taken now; the
    // result or the error is a message in poll().
    void startExport(ExportFormat format, const std::filesystem::path& out);
    bool exporting() const { return files_.exporting(); }
    std::string exportingLabel() const { return files_.exportingLabel(); }
    // The morph targets of a glTF/GLB file become the viseme set (a new, untitled document, unsaved:
    // its geometry exists only in memory) with the frequencies the file carries (ModelFrequencies.h).
    void importGltf(const std::filesystem::path& file);

    // --- avatar (core/document/AvatarDocument.h) ------------------------------------------------
    // Opens an avatar (glTF, GLB, VRM) as a new untitled document: its visemes selected by `pattern`
    // (empty: the Oculus names) over every mesh carrying them; the others are shown greyed.
    void importAvatar(const std::filesystem::path& file, const std::string& pattern = {});
    void startImportAvatar(const std::filesystem::path& file, const std::string& pattern = {});
    // Another target pattern for the avatar's visemes (one undo step; refused when < 2 visemes).
    void setAvatarPattern(const std::string& pattern);
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
    // The last avatar export's keys: "key 2 (viseme_PP+viseme_FF): target 'viseme_PP' on ..." and the
    // visemes that rest (empty before any export).
    const std::vector<std::string>& lastAvatarExport() const { return lastAvatarExport_; }
    // The same on a worker thread from a snapshot taken now; the result is a message in poll().
    void startExportAvatar(const std::filesystem::path& out, const AvatarExport& options);

    // The memoized weights and frequencies of the current document (a slider drag evaluates none).
    const DocumentInputs& documentInputs() const { return inputs_; }

    // --- frequencies -------------------------------------------------------------------------
    // Normalised viseme frequencies from the current table (throws InputError when invalid).
    std::vector<double> visemeFrequencies() const { return inputs_.frequencies(); }
    void setVisemeFrequency(int viseme, double value);   // direct mode
    void setPhonemeFrequency(int phoneme, double value); // phoneme mode
    void setPhonemeViseme(int phoneme, const std::string& viseme);
    void loadFrequencies(const std::filesystem::path& file);
    // A phoneme table plus a map, e.g. the bundled en-us table and a bundled map (checked first).
    void setFrequencySource(FrequencySource source, const std::string& actionName);
    // The bundled American English table with the bundled map `mapId` ("oculus", "mpeg4", ...).
    void useBundledPhonemeMap(const std::string& mapId);
    // Counts the phonemes of a text file with espeak-ng on a worker thread; the counts replace the
    // phoneme table (the current map is kept, or the bundled Oculus map is used).
    void startPhonemeCount(const std::filesystem::path& corpus, const std::string& voice = "en-us");
    bool phonemeCountRunning() const { return countTask_.running(); }
    double phonemeCountProgress() const { return countTask_.progress(); }
    void saveFrequenciesCsv(const std::filesystem::path& file) const;

    // --- weights -----------------------------------------------------------------------------
    void setWeightMode(WeightMode mode);
    std::vector<double> weights() const { return inputs_.weights(); } // throws when invalid
    void setPaintedWeights(std::vector<double> painted, const std::string& actionName);

    // --- deformable face ---------------------------------------------------------------------
    // Loads the face of `individual` (fields, parameters) on a (u,v) mesh of the given resolution.
    void loadFace(face::Individual individual = face::Individual::Bundled,
                  int resolution = kEditorFaceResolution);
    void setParameter(int parameter, double value);
    void setParameters(std::vector<double> values, const std::string& actionName);
    // The parameter vector of a viseme of the face (its presets, by default oculusVisemes()).
    void applyVisemePreset(const std::string& viseme);
    // Replaces one analytic influence region of a stage (validated by the core first).
    void setInfluence(int stage, int influence, const InfluenceField& field);
    // Retargeting: the same fields on another individual's base geometry.
    void setIndividual(face::Individual individual);
    // The face's visemes generated on its (u,v) mesh become the viseme set (embedded meshes).
    void generateVisemesFromFace();
    // Per-vertex samples of the current cascade on its mesh (cached per cascade and mesh).
    const FaceSamples& faceSamples();
    // Whether faceSamples() has the current face's samples without evaluating the cascade (after a
    // refinement: the worker's own samples).
    bool faceSamplesReady() const;
    // The head's parts of the current face (eyeballs, teeth, tongue, mouth cavity; for a face built
    // from the user's mesh, the bundled parts carried to it) in morph form, shown beside the skin in
    // the face views. Made once per cascade: sliders move them through the morph weights, a field
    // edit, retargeting or another face makes them again; a refined skin keeps them. Null without a
    // face; empty (and said once in the status bar) when the face's landmarks carry no parts.
    std::shared_ptr<const HeadPartSamples> faceParts();
    // Own face (Deformation > Use my mesh...): the face built from the user's mesh and confirmed
    // landmarks becomes the document's face (one undo step); the status bar says what the build found.
    void useOwnFace(const OwnFaceCandidate& candidate);
    // The own-face step as document state (Document::ownFace), each change one undo step: open on a
    // mesh (its landmarks suggested), place a landmark at a (u,v) of the mesh (the calls of one
    // numeric drag merge into one step; endEdit() closes it), build from the step's landmarks
    // (useOwnFace above, closing the step) or cancel it.
    void openOwnFace(const std::filesystem::path& mesh);
    void placeOwnFaceLandmark(face::Landmark landmark, const Vec2& uv);
    void buildOwnFace();
    void cancelOwnFace();

    // --- adaptive refinement -----------------------------------------------------------------
    void setRefinementSettings(const CriterionSettings& settings); // validated, undoable
    // Runs on a worker thread; the refined (u,v) mesh becomes the face's display and viseme mesh.
    // Refused while a refinement runs.
    void startRefinement(RefineAction action) { refinement_.start(document(), action, false); }
    bool refinementRunning() const { return refinement_.running(); }
    const std::optional<RefinementReport>& lastRefinement() const { return refinement_.last(); }
    // Re-adapt in the background after every parameter, field or threshold change.
    bool autoRefine = false;

    // --- background jobs: one list for progress and Cancel --------------------------------------
    enum class Job { Loading, Refinement, Reduction, PhonemeCount };
    struct JobStatus {
        Job job;
        std::string label;
        std::optional<double> fraction;    // none: the job reports no progress
        std::optional<double> secondsLeft; // estimated from the progress so far
    };
    std::vector<JobStatus> runningJobs() const;
    // Stops `job` at once and leaves the document as it was. A reduction keeps its best groupings with
    // their proven gaps (stopReduction); the others' results are dropped.
    void cancelJob(Job job);

    // --- reduction ---------------------------------------------------------------------------
    void setTarget(int m);
    // Pins, apart and together pairs by viseme name (validated; saved in the project).
    void setConstraints(ConstraintNames constraints);
    // The reduction model and rest viseme (edit::setRest), one undo step.
    void setRest(RestChoice rest, const std::string& restViseme);
    // Starts the reduction of the current inputs on a worker thread (no-op when already current).
    void startReduction() { reduction_.start(document(), inputs_); }
    bool reductionRunning() const { return reduction_.running(); }
    // Drops a running reduction (the searches stop within one progress poll); "Run now" restarts it.
    void cancelReduction() { reduction_.cancel(); }
    // The panel's Cancel: a large set's branch and bound stops within one progress poll and its best
    // groupings are kept with their proven gaps; a small set's exact run is dropped.
    void stopReduction() { reduction_.stop(); }
    double reductionProgress() const { return reduction_.progress(); }
    std::optional<ReductionService::Bound> reductionBound() const { return reduction_.bound(); }
    // The curve if it is up to date with the inputs, else null.
    const ReductionResult* reductionCurve() const { return reduction_.curve(); }
    std::uint64_t reductionCurveRevision() const { return reduction_.curveRevision(); }
    // Grouping into the target number of groups from the current curve, or null.
    const Grouping* currentGrouping() const { return reduction_.grouping(document().target); }
    // The reduced model of currentGrouping() (merged keys, phoneme -> key; cached), or null without
    // a grouping. Throws InputError when it cannot be built (ReductionService::reducedModel).
    const ReducedModel* reducedModel() { return reduction_.reducedModel(document()); }
    bool autoReduce = true; // re-run in the background after every input change

    // --- viseme authoring and the phoneme map editor (core/document/VisemeCommands.h and
    // PhonemeMapCommands.h); each is one undo step, the selection follows the viseme it names.
    void renameViseme(int index, const std::string& name);
    void duplicateViseme(int index, const std::string& name);
    void moveViseme(int from, int to);
    void addRestViseme(const std::string& name);
    // A sculpt stroke's shape of viseme `index` (edit::setVisemeShape): the calls of one stroke merge
    // into one undo step named after the tool; endEdit() at the stroke's end closes it.
    void sculptViseme(int index, std::vector<Vec3> positions, SculptTool tool);
    // A new viseme mixed from others (edit::addBlendedViseme); it becomes the selection.
    void addBlendedViseme(const std::string& name, const std::vector<std::pair<int, double>>& mix);
    // An avatar's rest viseme (edit::addAvatarRestViseme, with the bundled Oculus table).
    // `name`: one of kRestVisemeNames; empty: the one the avatar's naming suggests.
    void addAvatarRestViseme(const std::string& name = {});
    // The sliders as a new viseme / into an existing one (preset, and mesh when the set is the face's).
    void storeSlidersAsNewViseme(const std::string& name);
    void storeSlidersInViseme(const std::string& name);
    void removePreset(const std::string& name);
    // True when the viseme set is the face's own (cached per set and cascade).
    bool visemeSetMadeByFace();
    // For such a set, each viseme's face parameter vector (edit::visemeFaceParameters; cached): the
    // viseme view poses the head's parts with it. Empty otherwise.
    const std::vector<std::vector<double>>& visemeFaceParameters();
    // The phoneme table a new map starts from: the current one, else the bundled en-us table.
    FrequencyTable startingPhonemeTable() const;
    void startPhonemeMap(FrequencyTable table, const PhonemeVisemeMap& start,
                         const std::vector<edit::MapAssignment>& assignment, const std::string& startName);
    void movePhonemes(const std::string& from, const std::string& to);
    void useDirectFrequencies();
    void savePhonemeMap(const std::filesystem::path& file) const;

    // --- speech (Say) ------------------------------------------------------------------------------
    // Text, voice and rate (validated; saved in the project). A rate change while dragging merges
    // into one undo step.
    void setSpeech(SpeechSettings speech);
    // Speaks the document's text on a worker thread; poll() makes the speech the current clip.
    void say() { speech_.say(document().speech); }
    bool speaking() const { return speech_.speaking(); }
    // A typed sequence of phonemes or viseme names, `secondsPerKey` each, becomes the current clip.
    void playSequence(const std::string& sequence, double secondsPerKey) {
        speech_.playSequence(document(), sequence, secondsPerKey);
    }
    const std::shared_ptr<const SpeechClip>& speechClip() const { return speech_.clip(); }
    // The current clip on the full set and the current reduction, with its utterance error.
    const SpeechPlayback* speechPlayback() {
        return speech_.playback(document(), reduction_.inputsRevision(), reduction_.curveRevision(),
                                currentGrouping());
    }

    // --- frame loop --------------------------------------------------------------------------
    // Starts a UI frame: documents replaced during the previous frame may be released now. Every
    // reference into document() taken during a frame stays valid until the next beginFrame(), even
    // when a widget commits an edit in between (panels read the document, then edit it).
    void beginFrame() { frameDocuments_.clear(); }
    // Collects finished background work and starts automatic re-runs; call once per frame.
    void poll();
    // Blocks until background work has finished and was collected (tests, screenshots).
    void finishBackgroundWork();

    // --- undo / redo -------------------------------------------------------------------------
    bool canUndo() const { return history_.canUndo(); }
    bool canRedo() const { return history_.canRedo(); }
    std::string undoName() const { return canUndo() ? history_.undoName() : std::string(); }
    std::string redoName() const { return canRedo() ? history_.redoName() : std::string(); }
    void undo();
    void redo();
    // Ends the current slider drag so the next change is a separate undo step.
    void endEdit() { history_.closeMerge(); }
    // Identifies the current document state: changes with every edit, undo and redo.
    std::uint64_t documentId() const { return history_.currentId(); }
    // Changes when the document is replaced (new, open, sample, folder, import) or its subject is
    // built anew (Generate viseme set from face, Use my mesh): the window then drops every view's
    // state of the old one (EditorUi::documentReplaced); the session drops its own here.
    std::uint64_t documentEpoch() const { return documentEpoch_; }

    // --- messages ----------------------------------------------------------------------------
    void info(std::string text);
    void error(std::string text);
    const std::deque<StatusMessage>& messages() const { return messages_; }
    // Runs `action`; an exception becomes an error message "<what>: <reason>" and returns false.
    bool attempt(std::string_view what, const std::function<void()>& action);

    // --- view state (not part of the document, not undoable) -----------------------------------
    int selectedViseme = -1;
    // Changes whenever the reduction inputs change (views re-derive what depends on them).
    std::uint64_t inputsGeneration() const { return reduction_.inputsRevision(); }
    // Increments whenever the mesh set changes (renderers re-upload when it differs).
    std::uint64_t geometryGeneration() const { return geometryGeneration_; }

    // (u,v) resolution of a face loaded in the editor (finer than a project's, for live sliders).
    static constexpr int kEditorFaceResolution = 48;

  private:
    using DocumentPtr = std::shared_ptr<const Document>;
    // Commits the command's result as an undo step; `mergeKey` collapses a slider drag into one step.
    void commit(std::string name, Document next, std::string mergeKey = {});
    // Replaces the current document without an undo step (derived data: a re-adapted mesh).
    void amend(Document next);
    void noteChange(const Document& before);
    // Replaces the document by a loaded one (a fresh history).
    using Loaded = LoadedDocument;
    void adopt(Loaded loaded);
    void startLoading(std::string label, std::function<Loaded()> load);
    static Loaded loadProjectFile(const std::filesystem::path& file);
    static Loaded loadFolder(const std::filesystem::path& folder);
    static Loaded loadSampleFiles();
    static Loaded loadAvatarFile(const std::filesystem::path& file, const std::string& pattern);
    // The message: one line saying what was written, then one line per key (and the resting visemes).
    static std::string writeAvatarExport(const Document& document, const Project& snapshot,
                                         const std::filesystem::path& out, const AvatarExport& options);
    void noteAvatarExport(const std::string& message); // status message + lastAvatarExport_
    // True when `file` lies inside the bundled assets folder (never written by the editor).
    static bool isBundled(const std::filesystem::path& file);
    // The target of a save request (throws InputError when there is none).
    std::filesystem::path saveTarget(const std::filesystem::path& file) const;
    // Records a finished save of the document `savedId` (see CommandHistory::currentId); false when
    // the document changed meanwhile (it stays unsaved).
    bool recordSaved(const std::filesystem::path& target, std::uint64_t savedId);
    static std::vector<std::filesystem::path> writeExport(const Document& document, const Project& snapshot,
                                                          ExportFormat format,
                                                          const std::filesystem::path& out);
    void collectRefinement();
    void adoptFaceSamples(std::shared_ptr<const DeformationCascade> cascade,
                          std::shared_ptr<const MeshData> domain, std::shared_ptr<const FaceSamples> samples);

    // The one place that says what a new document clears in the session (see documentEpoch()):
    // the speech clip and its synthesis, the last refinement's report, the last avatar export,
    // the selection. Called on every replacement, before the new document is current.
    void beginNewDocument();
    std::uint64_t documentEpoch_ = 1;

    // Keeps the current document alive until the next beginFrame() (call before replacing it).
    void retireCurrent();

    CommandHistory<Document> history_;
    // Weights and frequencies of the current document, re-evaluated only when an edit changed what
    // they depend on (a slider tick keeps them).
    DocumentInputs inputs_;
    std::filesystem::path path_;
    std::vector<DocumentPtr> frameDocuments_; // documents replaced this frame
    std::deque<StatusMessage> messages_;
    std::vector<std::string> lastAvatarExport_;
    std::uint64_t messageSerial_ = 0;
    std::uint64_t geometryGeneration_ = 1;
    ReductionService reduction_;
    RefinementService refinement_;
    SpeechEngines engines_;
    SpeechService speech_;
    BackgroundTask<PhonemeCountResult> countTask_;
    std::filesystem::path countCorpus_;
    FileJobs files_; // open, save and export on worker threads
    // faceSamples() cache: the display samples of (samplesCascade_, samplesDomain_), from the
    // refinement worker when it made that mesh, else computed on first use.
    std::shared_ptr<const DeformationCascade> samplesCascade_;
    std::shared_ptr<const MeshData> samplesDomain_;
    std::shared_ptr<const FaceSamples> samples_;
    // faceParts() cache: the parts of partsCascade_.
    std::shared_ptr<const DeformationCascade> partsCascade_;
    std::shared_ptr<const HeadPartSamples> parts_;
    // visemeSetMadeByFace() cache: the answer and the visemes' parameter vectors for the set, cascade
    // and presets it holds.
    struct MadeByFace {
        std::shared_ptr<const VisemeSet> set;
        std::shared_ptr<const DeformationCascade> cascade;
        std::vector<VisemeParameters> presets;
        bool value = false;
        std::vector<std::vector<double>> parameters;
    } madeByFace_;
    // Keeps the selection on viseme `name` after an edit moved it (or clears it when it is gone).
    void select(const std::string& name);
};

} // namespace vl::ui
