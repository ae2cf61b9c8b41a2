#pragma once
// The editor window: the frame loop and its layout (menu bar, the side panel with one tab per task,
// the 3D views, the status bar) and the GPU copies of the session's meshes that the views draw.
// Each tab is a panel object (ui/panels) owning its view state; they share the session, the file
// actions and the speech player through a PanelContext. Everything the user does goes through
// EditorSession.
#include "ui/FileActions.h"
#include "ui/SpeechPlayer.h"
#include "ui/panels/AvatarPanel.h"
#include "ui/panels/DeformationPanel.h"
#include "ui/panels/ExportPanel.h"
#include "ui/panels/FrequenciesPanel.h"
#include "ui/panels/ReductionPanel.h"
#include "ui/panels/RefinementPanel.h"
#include "ui/panels/VisemesPanel.h"
#include "ui/panels/WeightsPanel.h"
#include "ui/render/GlShader.h"
#include "ui/render/GpuMesh.h"
#include "ui/render/Viewport.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/StatusLine.h"

#include <nlohmann/json.hpp>

#include <array>
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

class EditorUi {
  public:
    EditorUi(EditorSession& session, GLFWwindow* window);

    // Builds the whole interface for one frame (between ImGui::NewFrame and ImGui::Render).
    void frame();
    // What a GUI test checks after a click (see GuiProbe.h): panel, undo history, messages, tasks,
    // and each panel's part.
    nlohmann::json probeSummary();
    // True when the user asked to quit and either nothing is unsaved or they confirmed.
    bool quitConfirmed() const { return files_.quitConfirmed(); }

    // Start options (EditorApp).
    void selectPanel(Panel panel);
    void setWireframe(bool on) { wireframe_ = on; }
    // "errors", "skin" or "overlay" (--merged); throws InputError for another name.
    void setMergedDisplay(const std::string& name) { reduction_.setMergedDisplay(name); }
    // Turns painting on with this operation (0 add, 1 subtract, 2 smooth).
    void enableBrush(int operation);
    // Selects the first analytic region of the cascade stage with this name (Deformation panel).
    bool selectField(const std::string& stageName) { return deformation_.selectField(stageName); }
    // Starts the phoneme-sequence playback at `time` seconds.
    void startPlayback(double time, std::string sequence = {}) {
        speech_.playSequence(std::move(sequence), time);
    }
    // Says the document's speech text (Say button) and, once spoken, shows it at `time` seconds,
    // paused when `pause` (screenshots of a moment mid-sentence).
    void startSay(double time = 0.0, bool pause = false) { speech_.say(time, pause); }
    // Opens the map editor's assignment from a bundled map id ("oculus", ...) or "per-phoneme".
    void startMapFrom(const std::string& id) { frequencies_.startMapFrom(id); }

  private:
    // --- the frame (EditorUi.cpp) ---
    void menuBar();
    void shortcuts();
    void sidePanel(float top, float width, float height);
    // The status bar (StatusBar.cpp): its height this frame (a long message wraps onto more
    // lines), then the bar.
    float statusBarHeight();
    void statusBar(float height);

    // --- the views (EditorViews.cpp) ---
    void views(float left, float top, float width, float height);
    void mainView(ImVec2 size);
    void comparisonViews(ImVec2 size);
    void frameAll(); // every 3D view on its model (key F)
    void frameNewMeshes();
    void syncGpu();
    void syncContextMesh();
    void updateScalars();
    void drawContext(const glm::mat4& view, const glm::mat4& projection) const;
    std::vector<float> visemeWeights(int viseme) const;
    ColorMode surfaceColours() const; // face colours for visemes generated from the face model
    nlohmann::json faceViewProbe() const;

    EditorSession& session_;
    GLFWwindow* window_;
    GlShader shader_;
    GpuMesh visemeMesh_;  // neutral + one target per viseme
    GpuMesh mergedMesh_;  // neutral + one target per merged group
    GpuMesh faceMesh_;    // face cascade at q = 0 + one target per parameter
    GpuMesh partsMesh_;   // the head's parts (eyeballs, teeth, tongue, cavity) in the same form
    GpuMesh contextMesh_; // an avatar's meshes without visemes, drawn greyed
    Viewport mainView_, beforeView_, afterView_;
    std::uint64_t uploadedGeometry_ = 0;
    // Caches hold what they show (shared, immutable) or its revision, never a bare address that a
    // later allocation could reuse.
    std::shared_ptr<const DeformationCascade> uploadedCascade_;
    std::shared_ptr<const MeshData> uploadedDomain_;
    std::shared_ptr<const HeadPartSamples> uploadedParts_; // what partsMesh_ holds
    std::shared_ptr<const AvatarScan> uploadedContext_;    // the scan contextMesh_ shows
    std::uint64_t uploadedMergedCurve_ = 0;                // ReductionService::curveRevision()
    int uploadedMergedGroups_ = 0;
    // What each mesh's scalars currently show, to re-upload only on change.
    std::string weightsKey_, errorKey_, influenceKey_;
    double errorLegendMax_ = 0.0; // largest weighted distance of the error colours, model units
    // What the face view drew in its last frame (for the probe): the panel, the weights, and the
    // triangles of skin and parts.
    struct ShownFace {
        Panel panel = Panel::Count;
        std::vector<float> weights;
        std::size_t skinTriangles = 0, partTriangles = 0;
    } shownFace_;
    // The camera of each subject, kept across tabs; framed when its mesh first appears.
    OrbitCamera visemeCamera_, faceCamera_;
    bool frameVisemes_ = true, frameFace_ = true;
    ViewSubject subject_ = ViewSubject::Visemes;
    bool wireframe_ = true;

    Panel activePanel_ = Panel::Visemes;
    bool panelSelectPending_ = true;
    FileActions files_{session_};
    SpeechPlayer speech_{session_};
    PanelContext context_{session_, files_, speech_};
    AvatarPanel avatar_{context_}; // sections of the Visemes and Export panels, and the File menu's
    VisemesPanel visemes_{context_, avatar_};
    FrequenciesPanel frequencies_{context_};
    WeightsPanel weights_{context_, mainView_};
    DeformationPanel deformation_{context_};
    RefinementPanel refinement_{context_};
    ReductionPanel reduction_{context_};
    ExportPanel export_{context_, avatar_};
    // The tabs, in the order of Panel.
    const std::array<SidePanel*, static_cast<std::size_t>(Panel::Count)> panels_{
        &visemes_, &frequencies_, &weights_, &deformation_, &refinement_, &reduction_, &export_};

    // The status bar's message (expiring, wrapped to at most a few lines) as laid out this frame.
    StatusLine statusLine_;
    struct StatusLayout {
        std::string stats, message; // the message as shown: cut with "..." when it needs more lines
        const StatusMessage* shown = nullptr;
        float messageX = 0.0f, wrapWidth = 0.0f;
        int lines = 0;
    } status_;
    bool statusHovered_ = false;
};

} // namespace vl::ui
