#include "ui/EditorUi.h"

#include "core/adaptive/Criteria.h"
#include "core/common/Error.h"
#include "ui/KeyPresses.h"
#include "ui/UiScale.h"
#include "ui/widgets/Controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace vl::ui {
EditorUi::EditorUi(EditorSession& session, GLFWwindow* window) : session_(session), window_(window) {}

void EditorUi::selectPanel(Panel panel) {
    activePanel_ = panel;
    panelSelectPending_ = true;
}

void EditorUi::enableBrush(int operation) {
    weights_.painter().brush.enabled = true;
    weights_.painter().brush.mode = operation;
}

nlohmann::json EditorUi::probeSummary() {
    const Document& document = session_.document();
    nlohmann::json jobs = nlohmann::json::array(); // what the status bar shows with a Cancel
    for (const SessionJobs::JobStatus& job : session_.jobs().running()) jobs.push_back(job.label);
    nlohmann::json messages = nlohmann::json::array();
    for (const StatusMessage& message : session_.messages())
        messages.push_back({{"error", message.kind == StatusMessage::Kind::Error}, {"text", message.text}});
    const auto& painted = document.weights.paintedOrEmpty();
    double paintedSum = 0.0;
    for (double w : painted) paintedSum += w;
    nlohmann::json summary = {
        {"panel", panelName(activePanel_)},
        {"document_revision", session_.history().revision()},
        {"undo", session_.history().undoName()},
        {"redo", session_.history().redoName()},
        {"modified", session_.history().modified()},
        {"project_path", session_.files().path().string()},
        {"messages", std::move(messages)},
        {"busy", session_.files().loading() || session_.files().saving() || session_.files().exporting() ||
                     session_.face().refinementRunning() || session_.reduction().running() ||
                     session_.frequencies().countRunning() || session_.speech().speaking()},
        {"jobs", jobs},
        {"visemes", document.visemeCount()},
        {"selected_viseme", session_.selectedViseme()},
        {"target", document.target},
        {"constraints", document.constraints.pinned.size() + document.constraints.apart.size() +
                            document.constraints.together.size()},
        {"criterion", std::string(toString(document.refinement.kind))},
        {"file_dialog_open", files_.dialog().isOpen()},
        {"weight_mode", toString(document.weights.mode)},
        {"painted_mean", painted.empty() ? 0.0 : paintedSum / static_cast<double>(painted.size())},
        {"face_name", document.face.cascade ? document.face.cascade->name : std::string()}};
    views_.addProbe(summary);
    // Whether the font has the phoneme symbols the tables show (not '?'): IPA, Latin Extended-A, Greek.
    bool ipa = true;
    for (const ImWchar c : {0x014B, 0x03B8, 0x00F0, 0x0283, 0x0292, 0x0279})
        ipa = ipa && ImGui::GetFont()->FindGlyphNoFallback(c) != nullptr;
    summary["font_has_ipa"] = ipa;
    summary["font_size"] = ImGui::GetFontSize();
    summary["key_presses"] = keyPressCount();
    for (const SidePanel* panel : panels_) panel->addProbe(summary);
    avatar_.addProbe(summary);
    return summary;
}

// --- frame -----------------------------------------------------------------------------------

void EditorUi::frame() {
    session_.beginFrame();
    session_.poll();
    if (session_.history().documentEpoch() != documentEpoch_) documentReplaced();
    speech_.advance();
    views_.update(activePanel_);
    if (glfwWindowShouldClose(window_) && !files_.quitConfirmed()) {
        glfwSetWindowShouldClose(window_, GLFW_FALSE);
        files_.requestQuit();
    }
    shortcuts();

    const ImGuiIO& io = ImGui::GetIO();
    menuBar();
    const float menuHeight = ImGui::GetFrameHeight();
    const float statusHeight = statusBarHeight();
    const float sideWidth = std::clamp(io.DisplaySize.x * 0.36f, scaled(480.0f), scaled(640.0f));
    const float bodyHeight = std::max(1.0f, io.DisplaySize.y - menuHeight - statusHeight);
    sidePanel(menuHeight, sideWidth, bodyHeight);
    views_.draw(activePanel_, sideWidth, menuHeight, std::max(1.0f, io.DisplaySize.x - sideWidth),
                bodyHeight);
    statusBar(statusHeight);
    files_.draw();
}

void EditorUi::documentReplaced() {
    documentEpoch_ = session_.history().documentEpoch();
    speech_.reset();
    views_.documentReplaced();
    for (SidePanel* panel : panels_) panel->documentReplaced();
}

void EditorUi::shortcuts() {
    // Every press since the last frame, even one released before this frame began (KeyPresses.h).
    const std::vector<KeyPress> presses = takeKeyPresses();
    if (files_.dialog().isOpen()) return;
    // Ctrl+Q quits from anywhere, a text field too (through the unsaved-changes prompt).
    for (const KeyPress& press : presses)
        if (press.ctrl() && press.key == GLFW_KEY_Q && !press.repeat) files_.requestQuit();
    if (ImGui::GetIO().WantTextInput) return;
    for (const KeyPress& press : presses) {
        if (press.ctrl() && !press.repeat) {
            switch (press.key) {
            case GLFW_KEY_O:
                files_.openProject();
                break;
            case GLFW_KEY_S:
                files_.saveProject(press.shift());
                break;
            case GLFW_KEY_Z:
                press.shift() ? session_.history().redo() : session_.history().undo();
                break;
            case GLFW_KEY_Y:
                session_.history().redo();
                break;
            case GLFW_KEY_L:
                files_.loadSample();
                break;
            default:
                break;
            }
        }
        // Blender's numpad: 1 front, 3 right, 7 top; with Ctrl the opposite side; 5 orthographic.
        const bool opposite = press.ctrl();
        switch (press.key) {
        case GLFW_KEY_KP_1:
            views_.setView(opposite ? StandardView::Back : StandardView::Front);
            break;
        case GLFW_KEY_KP_3:
            views_.setView(opposite ? StandardView::Left : StandardView::Right);
            break;
        case GLFW_KEY_KP_7:
            views_.setView(opposite ? StandardView::Bottom : StandardView::Top);
            break;
        case GLFW_KEY_KP_5:
            if (!press.repeat) views_.toggleOrthographic();
            break;
        case GLFW_KEY_HOME:
            views_.frameAll();
            break;
        case GLFW_KEY_KP_ADD:
        case GLFW_KEY_EQUAL:
            views_.zoom(0.9f);
            break;
        case GLFW_KEY_KP_SUBTRACT:
        case GLFW_KEY_MINUS:
            views_.zoom(1.0f / 0.9f);
            break;
        default:
            break;
        }
        if (press.ctrl()) continue;
        if (press.key == GLFW_KEY_F && !press.repeat) views_.frameAll();
        if (press.key == GLFW_KEY_W && !press.repeat) views_.wireframe = !views_.wireframe;
        if (press.key == GLFW_KEY_M && !press.repeat && views_.hasMaterials())
            views_.setSurface(views_.surface == SurfaceShading::Materials ? SurfaceShading::ErrorColours
                                                                          : SurfaceShading::Materials);
        // Brush size by keyboard, as in painting programs (held: keeps changing).
        if (activePanel_ == Panel::Weights &&
            (press.key == GLFW_KEY_LEFT_BRACKET || press.key == GLFW_KEY_RIGHT_BRACKET))
            weights_.painter().resizeBrush(press.key == GLFW_KEY_RIGHT_BRACKET);
    }
}

void EditorUi::setSurface(const std::string& name) {
    if (name != "materials" && name != "errors")
        throwInputError("--surface", "expected materials or errors, got '" + name + "'");
    views_.setSurface(name == "materials" ? SurfaceShading::Materials : SurfaceShading::ErrorColours);
}

void EditorUi::menuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ctl::BeginMenu("File")) {
        if (ctl::MenuItem("New project")) files_.guarded([this] { session_.files().newProject(); });
        if (ctl::MenuItem("Open project...", "Ctrl+O")) files_.openProject();
        if (ctl::MenuItem("Save project", "Ctrl+S", false, !session_.files().path().empty()))
            files_.saveProject(false);
        if (ctl::MenuItem("Save project as...", "Ctrl+Shift+S")) files_.saveProject(true);
        ImGui::Separator();
        if (ctl::MenuItem("Load sample face", "Ctrl+L")) files_.loadSample();
        if (ctl::MenuItem("Open viseme folder...")) files_.openVisemeFolder();
        ImGui::Separator();
        if (ctl::MenuItem("Import avatar...")) avatar_.openImport();
        if (ctl::MenuItem("Export avatar...", nullptr, false, session_.document().avatar.isSet()))
            avatar_.openExport();
        ImGui::Separator();
        if (ctl::MenuItem("Quit", "Ctrl+Q")) files_.requestQuit();
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("Edit")) {
        const std::string undo = "Undo " + session_.history().undoName();
        const std::string redo = "Redo " + session_.history().redoName();
        if (ctl::MenuItem(undo.c_str(), "Ctrl+Z", false, session_.history().canUndo()))
            session_.history().undo();
        if (ctl::MenuItem(redo.c_str(), "Ctrl+Y", false, session_.history().canRedo()))
            session_.history().redo();
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("View")) {
        if (ctl::MenuItem("Frame model", "F, Home")) views_.frameAll();
        static const std::pair<StandardView, const char*> kViews[] = {
            {StandardView::Front, "Numpad 1"},     {StandardView::Right, "Numpad 3"},
            {StandardView::Top, "Numpad 7"},       {StandardView::Back, "Ctrl+Numpad 1"},
            {StandardView::Left, "Ctrl+Numpad 3"}, {StandardView::Bottom, "Ctrl+Numpad 7"}};
        for (const auto& [view, keys] : kViews)
            if (ctl::MenuItem(standardViewName(view), keys)) views_.setView(view);
        if (ctl::MenuItem("Reset view")) views_.resetView();
        bool orthographic = views_.orthographic();
        if (ctl::MenuItem("Orthographic", "Numpad 5", &orthographic)) views_.toggleOrthographic();
        ImGui::Separator();
        ctl::MenuItem("Wireframe overlay", "W", &views_.wireframe);
        ImGui::Separator();
        // The document's materials or the analysis colours (also the switch in the views' corner).
        const bool materials = views_.hasMaterials();
        if (ctl::MenuItem("Materials", "M", views_.surface == SurfaceShading::Materials, materials))
            views_.setSurface(SurfaceShading::Materials);
        if (ctl::MenuItem("Error colours", "M", views_.surface == SurfaceShading::ErrorColours, materials))
            views_.setSurface(SurfaceShading::ErrorColours);
        ImGui::Separator();
        for (int i = 0; i < static_cast<int>(Panel::Count); ++i)
            if (ctl::MenuItem(panelName(static_cast<Panel>(i)), nullptr,
                              activePanel_ == static_cast<Panel>(i)))
                selectPanel(static_cast<Panel>(i));
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("Help")) {
        ImGui::TextUnformatted("VisemeLab editor");
        ImGui::Separator();
        ImGui::TextUnformatted("Left drag: orbit    Right/middle drag: pan    Wheel: zoom");
        ImGui::TextUnformatted(
            "Arrows: orbit    +/-: zoom    F or Home: frame    W: wireframe    M: materials");
        ImGui::TextUnformatted("Numpad 1/3/7: front/right/top, Ctrl for back/left/bottom, 5: orthographic");
        ImGui::TextUnformatted("Ctrl+O open, Ctrl+S save, Ctrl+Shift+S save as, Ctrl+L sample, Ctrl+Q quit");
        ImGui::TextUnformatted("Ctrl+Z undo, Ctrl+Y redo");
        ImGui::TextUnformatted("Weights panel, brush on: left drag paints, Alt+left drag orbits");
        ImGui::TextUnformatted("Guide: docs/user-guide.md");
        ImGui::EndMenu();
    }
    if (session_.history().modified()) {
        ImGui::SameLine(ImGui::GetWindowWidth() - scaled(140.0f));
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "unsaved changes");
    }
    ImGui::EndMainMenuBar();
}

void EditorUi::sidePanel(float top, float width, float height) {
    constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                        ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::SetNextWindowPos(ImVec2(0, top));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("##side", nullptr, kFixed);
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(scaled(4), scaled(4)));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemInnerSpacing, ImVec2(scaled(2), scaled(4)));
    const bool tabs = ImGui::BeginTabBar("##panels", ImGuiTabBarFlags_FittingPolicyResizeDown);
    ImGui::PopStyleVar(2);
    if (tabs) {
        for (int i = 0; i < static_cast<int>(Panel::Count); ++i) {
            const auto panel = static_cast<Panel>(i);
            const ImGuiTabItemFlags flags =
                panelSelectPending_ && activePanel_ == panel ? ImGuiTabItemFlags_SetSelected : 0;
            if (ctl::BeginTabItem(panelLabel(panel), nullptr, flags)) {
                if (!panelSelectPending_) activePanel_ = panel;
                ImGui::BeginChild("##panel-body");
                panels_[static_cast<std::size_t>(i)]->draw();
                ImGui::EndChild();
                ImGui::EndTabItem();
            }
        }
        panelSelectPending_ = false;
        ImGui::EndTabBar();
    }
    ImGui::End();
}

} // namespace vl::ui
