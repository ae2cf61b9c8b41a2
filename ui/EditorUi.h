#pragma once
// The editor window: the frame loop and its layout: menu bar and shortcuts, the side panel with one
// tab per task, the 3D views (EditorViews), the status bar. Each tab is a panel object (ui/panels)
// owning its view state; they share the session, the file actions and the speech player through a
// PanelContext. Everything the user does goes through EditorSession.
#include "ui/EditorViews.h"
#include "ui/panels/AvatarPanel.h"
#include "ui/panels/DeformationPanel.h"
#include "ui/panels/ExportPanel.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/FrequenciesPanel.h"
#include "ui/panels/Panel.h"
#include "ui/panels/ReductionPanel.h"
#include "ui/panels/RefinementPanel.h"
#include "ui/panels/SpeechPlayer.h"
#include "ui/panels/VisemesPanel.h"
#include "ui/panels/WeightsPanel.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/StatusLine.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>

struct GLFWwindow;

namespace vl::ui {

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

    // Start options (EditorApp). They set up the window for the document they open: once applied,
    // that document's state is the window's (startOptionsApplied), not reset on the first frame.
    void startOptionsApplied() { documentEpoch_ = session_.history().documentEpoch(); }
    void selectPanel(Panel panel);
    void setWireframe(bool on) { views_.wireframe = on; }
    void setStartView(StandardView view, bool orthographic) { views_.setStartView(view, orthographic); }
    // "materials" or "errors" (--surface); throws InputError for another name.
    void setSurface(const std::string& name);
    // "errors", "skin" or "overlay" (--merged); throws InputError for another name.
    void setMergedDisplay(const std::string& name) { reduction_.setMergedDisplay(name); }
    // Turns painting on with this operation (0 add, 1 subtract, 2 smooth).
    void enableBrush(int operation);
    // Turns sculpting on with this tool (Visemes panel).
    void enableSculpt(SculptTool tool) {
        visemes_.sculptor().settings.enabled = true;
        visemes_.sculptor().settings.tool = tool;
    }
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
    // The one place that says what the window drops when the document is replaced (open, import,
    // new, sample, build face: SessionCore::documentEpoch, whose beginNewDocument clears the
    // session's part): the speech player (timeline, playhead, shown clip), the views' framing, and
    // each panel's state of the old document (selected field, import error ...).
    void documentReplaced();
    void sidePanel(float top, float width, float height);
    // The status bar (StatusBar.cpp): its height this frame (a long message wraps onto more
    // lines), then the bar.
    float statusBarHeight();
    void statusBar(float height);

    EditorSession& session_;
    GLFWwindow* window_;
    Panel activePanel_ = Panel::Visemes;
    bool panelSelectPending_ = true;
    std::uint64_t documentEpoch_ = 0; // of the document the window's state belongs to
    FileActions files_{session_};
    SpeechPlayer speech_{session_};
    PanelContext context_{session_, files_, speech_};
    AvatarPanel avatar_{context_}; // sections of the Visemes and Export panels, and the File menu's
    FrequenciesPanel frequencies_{context_};
    // The views show what the panels below hold (bound now, used from the first frame on).
    EditorViews views_{session_, speech_, {visemes_, weights_, deformation_, reduction_}};
    VisemesPanel visemes_{context_, avatar_, views_.mainView()};
    WeightsPanel weights_{context_, views_.mainView()};
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
