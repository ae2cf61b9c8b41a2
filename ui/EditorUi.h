#pragma once
// The editor window's contents: menu bar, fixed side panel with one tab per task, the 3D views and
// the status bar. Everything the user does goes through EditorSession; this class only draws and
// keeps GPU copies of the session's meshes up to date.
#include "core/paint/BrushRadius.h"
#include "core/paint/PaintSurface.h"
#include "core/paint/RayPick.h"
#include "ui/FileActions.h"
#include "ui/SpeechPlayer.h"
#include "ui/panels/AvatarPanel.h"
#include "ui/panels/ExportPanel.h"
#include "ui/panels/FrequenciesPanel.h"
#include "ui/panels/ReductionPanel.h"
#include "ui/panels/RefinementPanel.h"
#include "ui/panels/VisemesPanel.h"
#include "ui/render/GlShader.h"
#include "ui/render/GpuMesh.h"
#include "ui/render/Viewport.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/StatusLine.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct GLFWwindow;

namespace vl::ui {

enum class Panel { Visemes, Frequencies, Weights, Deformation, Refinement, Reduction, Export, Count };

const char* panelName(Panel panel);
std::optional<Panel> panelFromName(std::string_view name); // case-insensitive

// What the main view shows.
enum class ViewSubject { Visemes, Face };

struct BrushSettings {
    BrushRadius radius;    // screen pixels or % of the head size
    float strength = 0.5f; // per dab
    int falloff = 1;       // index into the core's falloff kinds
    int mode = 0;          // 0 add, 1 subtract, 2 smooth
    bool symmetric = true;
    bool frontFacesOnly = true; // no paint through to the back of the head (WeightBrush::eye)
    bool enabled = false;
};

// What a left drag on the mesh does while painting is on (Weights panel).
enum class PaintTool { Brush, FillRegion, SelectBox };

class EditorUi {
  public:
    EditorUi(EditorSession& session, GLFWwindow* window);

    // Builds the whole interface for one frame (between ImGui::NewFrame and ImGui::Render).
    void frame();
    void selectPanel(Panel panel);
    void setWireframe(bool on) { wireframe_ = on; }
    // "errors", "skin" or "overlay" (--merged); throws InputError for another name.
    void setMergedDisplay(const std::string& name) { reduction_.setMergedDisplay(name); }
    // Turns painting on with this operation (0 add, 1 subtract, 2 smooth).
    void enableBrush(int operation) {
        brush_.enabled = true;
        brush_.mode = operation;
    }
    // Selects the first analytic region of the cascade stage with this name (Deformation panel).
    bool selectField(const std::string& stageName);
    // Starts the phoneme-sequence playback at `time` seconds.
    void startPlayback(double time, std::string sequence = {});
    // Says the document's speech text (Say button) and, once spoken, shows it at `time` seconds,
    // paused when `pause` (screenshots of a moment mid-sentence).
    void startSay(double time = 0.0, bool pause = false);
    // True when the user asked to quit and either nothing is unsaved or they confirmed.
    bool quitConfirmed() const { return files_.quitConfirmed(); }
    // Opens the map editor's assignment from a bundled map id ("oculus", ...) or "per-phoneme".
    void startMapFrom(const std::string& id) { frequencies_.startMapFrom(id); }
    // What a GUI test checks after a click (see GuiProbe.h): panel, undo history, messages, tasks.
    nlohmann::json probeSummary();

    EditorSession& session;

  private:
    // Frames every 3D view on its model (key F).
    void frameAll();
    void menuBar();
    // The status bar: its height this frame (a long message wraps onto more lines), then the bar.
    float statusBarHeight();
    void statusBar(float height);
    void sidePanel(float top, float width, float height);
    void views(float left, float top, float width, float height);
    void shortcuts();
    void syncGpu();
    void frameNewMeshes();

    void weightsPanel();
    void deformationPanel();
    // The (u,v) inset over the face view: a title bar that moves it and the square (u,v) domain,
    // whose drawing is clipped to its frame. Where it sits is view state (uvInsetOffset_).
    struct UvInsetPlace {
        ImVec2 min, max; // the whole inset, title bar included
        float side = 0.0f, titleHeight = 0.0f;
        ImVec2 offsetMin, offsetMax; // the offsets that keep it inside the view
    };
    UvInsetPlace uvInsetPlace(ImVec2 viewMin, ImVec2 viewMax) const;
    void uvInset(const UvInsetPlace& place, int stage, int influence);
    void uvView(int stage, int influence, float side);

    void mainView(ImVec2 size);
    void comparisonViews(ImVec2 size);
    std::vector<float> visemeWeights(int viseme) const;
    ColorMode surfaceColours() const; // face colours for visemes generated from the face model
    void paint(const ViewportEvents& events);
    void updateScalars();

    GLFWwindow* window_;
    GlShader shader_;
    GpuMesh visemeMesh_; // neutral + one target per viseme
    GpuMesh mergedMesh_; // neutral + one target per merged group
    GpuMesh faceMesh_;   // face cascade at q = 0 + one target per parameter
    GpuMesh partsMesh_;  // the head's parts (eyeballs, teeth, tongue, cavity) in the same form
    Viewport mainView_, beforeView_, afterView_;
    std::uint64_t uploadedGeometry_ = 0;
    // Caches hold what they show (shared, immutable) or its revision, never a bare address that a
    // later allocation could reuse.
    std::shared_ptr<const DeformationCascade> uploadedCascade_;
    std::shared_ptr<const MeshData> uploadedDomain_;
    std::shared_ptr<const HeadPartSamples> uploadedParts_; // what partsMesh_ holds
    // What the face view drew in its last frame (for the probe): the panel, the weights, and the
    // triangles of skin and parts.
    struct ShownFace {
        Panel panel = Panel::Count;
        std::vector<float> weights;
        std::size_t skinTriangles = 0, partTriangles = 0;
    } shownFace_;
    nlohmann::json faceViewProbe() const;
    std::uint64_t uploadedMergedCurve_ = 0; // ReductionService::curveRevision()
    int uploadedMergedGroups_ = 0;
    // What each mesh's scalars currently show, to re-upload only on change.
    std::string weightsKey_, errorKey_, influenceKey_;

    Panel activePanel_ = Panel::Visemes;
    bool panelSelectPending_ = true;
    ViewSubject subject_ = ViewSubject::Visemes;
    bool wireframe_ = true;
    bool showWeightsColours_ = true;
    bool showFieldInfluence_ = true;
    int selectedStage_ = -1, selectedInfluence_ = 0;
    BrushSettings brush_;
    bool strokeActive_ = false;
    std::vector<double> strokeStart_;
    std::vector<double> strokeWeights_;
    std::optional<Vec3> lastDab_;
    FileActions files_{session};
    SpeechPlayer speech_{session};
    PanelContext context_{session, files_, speech_};
    AvatarPanel avatar_{context_};
    FrequenciesPanel frequencies_{context_};
    RefinementPanel refinement_{context_};
    VisemesPanel visemes_{context_, avatar_};
    ReductionPanel reduction_{context_};
    ExportPanel export_{context_, avatar_};

    // --- own face (issue 15): Deformation > Use my mesh... and its landmark step (OwnFaceStep.cpp) ---
    void openOwnFaceMesh();
    void ownFaceStep();
    nlohmann::json ownFaceProbe() const;
    std::optional<OwnFaceCandidate> ownFace_;                  // the mesh whose landmarks await confirmation
    std::shared_ptr<const DeformationCascade> ownFaceCascade_; // the cascade ownFaceLoaded_ was found for
    bool ownFaceLoaded_ = false;                               // the face is built from a user's mesh
    double errorLegendMax_ = 0.0; // largest weighted distance of the error colours, model units
    // --- Say (issue 11): speech played on the full and the reduced faces. The text, voice and rate
    // are document state (session.setSpeech); what is below is view state.

    // --- avatars (File > Import avatar..., panels/AvatarPanel.cpp) ---------------------------------
    GpuMesh contextMesh_;                               // the avatar's meshes without visemes, drawn greyed
    std::shared_ptr<const AvatarScan> uploadedContext_; // the scan contextMesh_ shows
    void syncContextMesh();
    void drawContext(const glm::mat4& view, const glm::mat4& projection) const;

    // --- issue 14 polish (view state): paint tools, one camera per subject ----------------------
    struct PaintToolState {
        PaintTool tool = PaintTool::Brush;
        float fillValue = 1.0f;
        float fillTolerance = 0.05f;          // region fill: largest difference to the seed's weight
        std::vector<std::uint32_t> selection; // selected vertices, increasing
        std::optional<ImVec2> boxStart;       // screen corner of the box being dragged
        std::optional<double> readout;        // weight under the cursor (last frame)
        std::uint32_t readoutVertex = 0;      // the vertex nearest to the cursor's hit
        double modelRadius = 0.0;             // the brush radius at the cursor, model units
        double unitsPerPixel = 0.0;           // model units per screen pixel at the cursor
        std::optional<Vec3> boxEye;           // the camera position of the last box selection
    } paintTool_;
    // For the probe: how many selected vertices the eye of the last box does not see, found by ray
    // picking (recomputed when the selection changes).
    struct HiddenCount {
        std::vector<std::uint32_t> selection;
        Vec3 eye;
        std::size_t hidden = 0;
    };
    mutable std::optional<HiddenCount> selectionHidden_;
    std::size_t selectedHidden() const;
    std::vector<double> shownWeights_; // the metric's weights as the colours show them
    std::shared_ptr<const VisemeSet> paintSurfaceSet_;
    PaintSurface paintSurface_;
    const PaintSurface& paintSurface(); // of the viseme set's neutral, rebuilt when the set changes
    std::vector<double> paintStartWeights() const;
    void paintBrush(const ViewportEvents& events, const std::optional<RayHit>& hit);
    void paintBoxSelection(const ViewportEvents& events);
    void drawSelection(const ViewportEvents& events);
    void fillVertices(const std::vector<std::uint32_t>& vertices, const char* action);
    nlohmann::json paintSummary() const;
    nlohmann::json polishSummary() const; // what the polish tests assert, merged into probeSummary()
    // The status bar's message (expiring, wrapped to at most kStatusLines lines) as laid out this frame.
    StatusLine statusLine_;
    struct StatusLayout {
        std::string stats, message; // the message as shown: cut with "..." when it needs more lines
        const StatusMessage* shown = nullptr;
        float messageX = 0.0f, wrapWidth = 0.0f;
        int lines = 0;
    } status_;
    bool statusHovered_ = false;
    // The camera of each subject, kept across tabs; framed when its mesh first appears.
    OrbitCamera visemeCamera_, faceCamera_;
    bool frameVisemes_ = true, frameFace_ = true;
    // The (u,v) inset's top-left corner relative to the view's lower-right default place (moved by
    // dragging its title bar; kept inside the view).
    ImVec2 uvInsetOffset_{0.0f, 0.0f};

    // --- viseme authoring and the phoneme map editor (ui/panels/VisemeAuthoring.cpp,
    // StoreSlidersSection.cpp, PhonemeMapEditor.cpp); view state only, the edits are the session's.
    void storeSlidersSection(); // Deformation panel: the sliders as a new or existing viseme, presets
    struct AuthoringView {
        std::string newViseme; // Deformation: name of a new viseme from the sliders
        std::string storeInto; // Deformation: the existing preset or viseme to store into
    } authoring_;
};

} // namespace vl::ui
