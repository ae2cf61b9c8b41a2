#pragma once
// The editor's document and every action on it, with no GL or ImGui: the panels call these
// methods, and so does the GUI smoke test, so both exercise the same code paths. Each edit builds
// a new state from the current one and commits it to the undo history only when the core accepted
// it, so bad input (a broken file, a non-interpolable mesh) changes nothing.
#include "core/adaptive/AdaptiveMesh.h"
#include "core/adaptive/Criteria.h"
#include "core/deform/BundledFace.h"
#include "core/deform/DeformationCascade.h"
#include "core/export/Export.h"
#include "core/phonetics/PhonemeCounting.h"
#include "core/project/Project.h"
#include "core/reduce/Reduction.h"
#include "core/reduce/VisemeSet.h"
#include "ui/session/BackgroundTask.h"
#include "ui/session/CommandHistory.h"

#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl::ui {

// The deformable face being edited: its cascade (fields and parameters), the parameter values
// shown, and the (u,v) mesh it is displayed on.
struct FaceModel {
    std::shared_ptr<const DeformationCascade> cascade; // null until a face is loaded
    face::Individual individual = face::Individual::Bundled;
    std::shared_ptr<const MeshData> domain; // (u,v) triangulation; positions unused
    std::vector<double> parameters;         // one value per cascade parameter
};

// One undoable state: the project plus the meshes it references, loaded and checked.
struct EditorState {
    Project project;
    std::shared_ptr<const VisemeSet> visemes; // null until a viseme set is loaded
    // Per-vertex preview colours (lips, eyes, brows) when the visemes come from the face model.
    std::shared_ptr<const std::vector<Vec3>> visemeColours;
    FaceModel face;
};

// A face cascade sampled on its display mesh: positions at q = 0 and at each unit vector e_k
// (the cascade is linear in q, so the shader reproduces any q as rest + sum q_k (target_k - rest)).
struct FaceSamples {
    std::vector<Vec3> rest;
    std::vector<std::vector<Vec3>> targets;
    std::vector<Vec3> colours;
};

struct StatusMessage {
    enum class Kind { Info, Error } kind = Kind::Info;
    std::string text;
};

// The reduction for every p = 1..n on the current inputs (n = number of visemes).
struct ReductionCurve {
    std::shared_ptr<const ReductionResult> result;
    std::uint64_t inputsGeneration = 0; // valid while it equals EditorSession::inputsGeneration()
};

// What the last adaptive refinement produced.
struct RefinementReport {
    std::string action;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    int maxLevel = 0;
    AdaptStats stats;
    double milliseconds = 0.0;
};

enum class RefineAction {
    Refine,     // split where the criterion asks, for the current parameters
    Simplify,   // weld where the criterion allows
    Adapt,      // re-adapt after a parameter or threshold change (resample, weld, split)
    AllVisemes, // one mesh refined for every viseme pose (for an interpolable viseme set)
};

struct AdaptiveWork; // the adaptive mesh, owned by the refinement worker between runs

class EditorSession {
  public:
    EditorSession();
    ~EditorSession();

    const EditorState& state() const { return history_.current(); }
    const Project& project() const { return state().project; }
    const VisemeSet* visemes() const { return state().visemes.get(); }
    std::size_t visemeCount() const { return visemes() ? visemes()->size() : 0; }

    // --- files -------------------------------------------------------------------------------
    void newProject();
    void openProject(const std::filesystem::path& file);
    // The same on a worker thread (the window stays responsive while large meshes load); the
    // result replaces the document in poll(), an error becomes a message and changes nothing.
    void startOpenProject(const std::filesystem::path& file);
    void startLoadVisemeFolder(const std::filesystem::path& folder);
    bool loading() const { return loadTask_.running(); }
    std::string loadingLabel() const { return loadTask_.label(); }
    // Saves to `file`, or to the project's own path when empty (throws InputError when it has none).
    void saveProject(const std::filesystem::path& file = {});
    // The same on a worker thread: the project is snapshotted now (later edits are not in the file).
    // poll() records the saved file (when nothing was edited meanwhile) and then runs `then` (the
    // action the unsaved-changes prompt held back); a failed save is a message and changes nothing.
    void startSaveProject(const std::filesystem::path& file = {}, std::function<void()> then = {});
    bool saving() const { return saveTask_.running(); }
    std::string savingLabel() const { return saveTask_.label(); }
    // A folder of meshes: the one whose name contains "neutral" is the neutral, the others are
    // visemes sorted by name; frequencies start uniform.
    void loadVisemeFolder(const std::filesystem::path& folder);
    // The bundled sample (assets/), whatever form the core ships it in.
    void loadSample();
    void startLoadSample(); // the same on a worker thread, like startOpenProject
    static std::filesystem::path assetsDirectory();
    // Adds one viseme mesh; throws the core's interpolability error and changes nothing on failure.
    void importViseme(const std::string& name, const std::filesystem::path& file);
    void removeViseme(int index);
    bool modified() const { return history_.modified(); }
    // The project as it would be saved: face model and the current reduction result included.
    Project projectSnapshot() const;
    // Exports the reduced model (glb/runtime file, vrml/obj folder); returns the files written.
    std::vector<std::filesystem::path> exportProject(ExportFormat format, const std::filesystem::path& out);
    // The same on a worker thread (it may run a fresh reduction) from a snapshot taken now; the
    // result or the error is a message in poll().
    void startExport(ExportFormat format, const std::filesystem::path& out);
    bool exporting() const { return exportTask_.running(); }
    std::string exportingLabel() const { return exportTask_.label(); }
    // The morph targets of a glTF/GLB file become the viseme set (a new project).
    void importGltf(const std::filesystem::path& file);

    // --- frequencies -------------------------------------------------------------------------
    // Normalised viseme frequencies from the current table (throws InputError when invalid).
    std::vector<double> visemeFrequencies() const;
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
    std::vector<double> weights() const; // the metric's per-vertex weights (throws when invalid)
    void setPaintedWeights(std::vector<double> painted, const std::string& actionName);

    // --- deformable face ---------------------------------------------------------------------
    // Loads the bundled face (fields, parameters) on a (u,v) mesh of the given resolution.
    void loadFace(face::Individual individual = face::Individual::Bundled, int resolution = 48);
    const FaceModel& face() const { return state().face; }
    void setParameter(int parameter, double value);
    void setParameters(std::vector<double> values, const std::string& actionName);
    // The parameter vector of a viseme of the face (oculusVisemes()).
    void applyVisemePreset(const std::string& viseme);
    // Replaces one analytic influence region of a stage (validated by the core first).
    void setInfluence(int stage, int influence, const InfluenceField& field);
    // Retargeting: the same fields on another individual's base geometry.
    void setIndividual(face::Individual individual);
    // The face's visemes generated on its (u,v) mesh become the viseme set (embedded meshes).
    void generateVisemesFromFace();
    // Per-vertex samples of the current cascade on its mesh (cached by cascade and mesh).
    const FaceSamples& faceSamples();

    // --- adaptive refinement -----------------------------------------------------------------
    void setRefinementSettings(const CriterionSettings& settings); // validated, undoable
    // Runs on a worker thread; the refined (u,v) mesh becomes the face's display and viseme mesh.
    // Refused while a refinement runs.
    void startRefinement(RefineAction action);
    bool refinementRunning() const { return refinementTask_.running(); }
    const std::optional<RefinementReport>& lastRefinement() const { return lastRefinement_; }
    // Re-adapt in the background after every parameter, field or threshold change.
    bool autoRefine = false;

    // --- reduction ---------------------------------------------------------------------------
    void setTarget(int m);
    // Starts the reduction of the current inputs on a worker thread (no-op when already current).
    void startReduction();
    bool reductionRunning() const { return reductionTask_.running(); }
    double reductionProgress() const { return reductionTask_.progress(); }
    // The curve if it is up to date with the inputs, else null.
    const ReductionResult* reductionCurve() const;
    // Grouping into the target number of groups from the current curve, or null.
    const Grouping* currentGrouping() const;
    // Merged shape of each group of currentGrouping() (frequency-weighted means; cached).
    const std::vector<std::vector<Vec3>>& mergedShapes();
    bool autoReduce = true; // re-run in the background after every input change

    // --- frame loop --------------------------------------------------------------------------
    // Starts a UI frame: states replaced during the previous frame may be released now. Every
    // reference into state() taken during a frame stays valid until the next beginFrame(), even
    // when a widget commits an edit in between (panels read the document, then edit it).
    void beginFrame() { frameStates_.clear(); }
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

    // --- messages ----------------------------------------------------------------------------
    void info(std::string text);
    void error(std::string text);
    const std::deque<StatusMessage>& messages() const { return messages_; }
    // Runs `action`; an exception becomes an error message "<what>: <reason>" and returns false.
    bool attempt(std::string_view what, const std::function<void()>& action);

    // --- view state (not part of the document, not undoable) -----------------------------------
    int selectedViseme = -1;
    std::uint64_t inputsGeneration() const { return inputsGeneration_; }
    // Increments whenever the mesh set changes (renderers re-upload when it differs).
    std::uint64_t geometryGeneration() const { return geometryGeneration_; }

  private:
    // Commits `next` as an undo step; `mergeKey` collapses a slider drag into one step.
    void commit(std::string name, EditorState next, std::string mergeKey = {});
    void noteChange(const EditorState& before, const EditorState& after);
    void resetTo(EditorState state);
    // The document a project file or a mesh folder describes, loaded and checked (any thread).
    static EditorState projectState(const std::filesystem::path& file);
    static EditorState folderState(const std::filesystem::path& folder);
    // Replaces the document by a loaded one (a fresh history).
    void adopt(EditorState next, const std::string& message);
    void startLoading(std::string label, std::function<EditorState()> load,
                      std::function<std::string(const EditorState&)> describe);
    static EditorState sampleState();
    // True when `file` lies inside the bundled assets folder (never written by the editor).
    static bool isBundled(const std::filesystem::path& file);
    static void untitle(Project& project);
    static std::string describeSample(const EditorState& sample);
    // The target of a save request (throws InputError when there is none).
    std::filesystem::path saveTarget(const std::filesystem::path& file) const;
    // Writes a snapshot (any thread); returns it rebased on `target`, as the document records it.
    static Project writeProject(const std::filesystem::path& target, const Project& snapshot);
    // Records a finished save of the state `savedId` (see CommandHistory::currentId); false when the
    // document changed meanwhile (it stays unsaved).
    bool recordSaved(const std::filesystem::path& target, Project saved, std::uint64_t savedId);
    static std::vector<std::filesystem::path> writeExport(const Project& snapshot, ExportFormat format,
                                                          const std::filesystem::path& out);
    static FaceModel makeFaceModel(face::Individual individual, int resolution);
    // Generates the face's visemes into `next` as a fresh project (embedded meshes).
    static void setVisemesFromFace(EditorState& next);
    static constexpr int kSampleResolution = 40;

    // Keeps the current state alive until the next beginFrame() and returns it (call before any
    // change of the current state).
    std::shared_ptr<const EditorState> retireCurrent();

    CommandHistory<EditorState> history_;
    std::vector<std::shared_ptr<const EditorState>> frameStates_; // states replaced this frame
    std::deque<StatusMessage> messages_;
    std::uint64_t inputsGeneration_ = 1;
    std::uint64_t geometryGeneration_ = 1;
    ReductionCurve curve_;
    std::uint64_t runningGeneration_ = 0;
    BackgroundTask<std::shared_ptr<const ReductionResult>> reductionTask_;
    // mergedShapes() cache, keyed by the curve and the number of groups.
    const ReductionResult* mergedFor_ = nullptr;
    int mergedGroups_ = 0;
    std::vector<std::vector<Vec3>> merged_;
    struct RefineOutcome {
        std::shared_ptr<const MeshData> domain;
        RefinementReport report;
        bool automatic = false;
    };
    BackgroundTask<RefineOutcome> refinementTask_;
    BackgroundTask<PhonemeCountResult> countTask_;
    BackgroundTask<EditorState> loadTask_;
    std::function<std::string(const EditorState&)> describeLoad_;
    struct SaveOutcome {
        std::filesystem::path target;
        Project saved;
    };
    BackgroundTask<SaveOutcome> saveTask_;
    std::uint64_t saveRequestId_ = 0;
    std::function<void()> afterSave_;
    BackgroundTask<std::vector<std::filesystem::path>> exportTask_;
    ExportFormat exportFormat_ = ExportFormat::Glb;
    std::filesystem::path exportOut_;
    std::filesystem::path countCorpus_;
    std::shared_ptr<AdaptiveWork> adaptive_;
    std::optional<RefinementReport> lastRefinement_;
    // Inputs of the last automatic re-adaptation (held, so a freed cascade's address is never reused
    // for a match).
    std::shared_ptr<const DeformationCascade> autoCascade_;
    std::vector<double> autoParameters_;
    CriterionSettings autoSettings_;
    // Whether the current state has the inputs of the last automatic re-adaptation.
    bool autoInputsCurrent() const;
    void startRefinementTask(RefineAction action, bool automatic);
    // faceSamples() cache.
    const DeformationCascade* samplesCascade_ = nullptr;
    const MeshData* samplesDomain_ = nullptr;
    FaceSamples samples_;
};

} // namespace vl::ui
