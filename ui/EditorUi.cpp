#include "ui/EditorUi.h"

#include "core/common/Error.h"
#include "core/gltf/AvatarScan.h"
#include "core/inspect/DistanceUnits.h"
#include "core/project/BuiltinGeometry.h"
#include "ui/widgets/Controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace vl::ui {
namespace {

// Tab labels are short so all seven fit; the full names are used by --panel and the View menu.
constexpr const char* kPanelLabels[] = {"Visemes", "Freq.",  "Weights", "Deform",
                                        "Refine",  "Reduce", "Export"};
constexpr const char* kPanelNames[] = {"Visemes",    "Frequencies", "Weights", "Deformation",
                                       "Refinement", "Reduction",   "Export"};

glm::vec3 toGlm(const Vec3& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// A centred hint drawn over an empty view.
void emptyViewHint(const ImVec2& min, const ImVec2& max, const char* text) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    ImGui::GetWindowDrawList()->AddText(
        ImVec2(0.5f * (min.x + max.x - size.x), 0.5f * (min.y + max.y - size.y)),
        IM_COL32(200, 200, 210, 255), text);
}

void viewLabel(const ImVec2& min, const std::string& text) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    draw->AddRectFilled(ImVec2(min.x + 8, min.y + 8), ImVec2(min.x + 16 + size.x, min.y + 12 + size.y),
                        IM_COL32(20, 20, 24, 170), 4.0f);
    draw->AddText(ImVec2(min.x + 12, min.y + 10), IM_COL32(235, 235, 240, 255), text.c_str());
}

// The colour ramp of shaders/mesh.frag as a bar in the lower left corner of a view.
void colourLegend(const ImVec2& min, const ImVec2& max, const char* low, const char* high) {
    static const ImU32 stops[] = {IM_COL32(46, 61, 133, 255), IM_COL32(38, 133, 235, 255),
                                  IM_COL32(26, 217, 153, 255), IM_COL32(242, 217, 51, 255),
                                  IM_COL32(204, 31, 13, 255)};
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float width = 200.0f, height = 12.0f;
    const ImVec2 origin(min.x + 16.0f, max.y - 36.0f);
    for (int i = 0; i < 4; ++i) {
        const float x0 = origin.x + width * static_cast<float>(i) / 4.0f;
        const float x1 = origin.x + width * static_cast<float>(i + 1) / 4.0f;
        draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), stops[i],
                                      stops[i + 1], stops[i + 1], stops[i]);
    }
    draw->AddRect(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(20, 20, 24, 255));
    draw->AddText(ImVec2(origin.x, origin.y + height + 2.0f), IM_COL32(220, 220, 230, 255), low);
    // Right-aligned under the bar's end, but never over the low label.
    const float highWidth = ImGui::CalcTextSize(high).x;
    const float lowWidth = ImGui::CalcTextSize(low).x;
    draw->AddText(
        ImVec2(std::max(origin.x + width - highWidth, origin.x + lowWidth + 12.0f), origin.y + height + 2.0f),
        IM_COL32(220, 220, 230, 255), high);
}

} // namespace

const char* panelName(Panel panel) {
    return kPanelNames[static_cast<int>(panel)];
}

std::optional<Panel> panelFromName(std::string_view name) {
    for (int i = 0; i < static_cast<int>(Panel::Count); ++i) {
        const std::string_view candidate = kPanelNames[i];
        if (candidate.size() == name.size() &&
            std::equal(candidate.begin(), candidate.end(), name.begin(), [](char a, char b) {
                return std::tolower(static_cast<unsigned char>(a)) ==
                       std::tolower(static_cast<unsigned char>(b));
            }))
            return static_cast<Panel>(i);
    }
    return std::nullopt;
}

EditorUi::EditorUi(EditorSession& editorSession, GLFWwindow* window)
    : session(editorSession), window_(window), shader_(shaderDirectory(), "mesh") {
    afterView_.background = beforeView_.background = mainView_.background;
}

void EditorUi::selectPanel(Panel panel) {
    activePanel_ = panel;
    panelSelectPending_ = true;
}

bool EditorUi::selectField(const std::string& stageName) {
    const auto& cascade = session.face().cascade;
    if (!cascade) return false;
    for (std::size_t s = 0; s < cascade->stages.size(); ++s)
        if (cascade->stages[s].name == stageName && !cascade->stages[s].field.influences.empty()) {
            selectedStage_ = static_cast<int>(s);
            selectedInfluence_ = 0;
            return true;
        }
    return false;
}

void EditorUi::startPlayback(double time, std::string sequence) {
    speech_.playSequence(std::move(sequence), time);
}

void EditorUi::startSay(double time, bool pause) {
    speech_.say(time, pause);
}

nlohmann::json EditorUi::probeSummary() {
    static const char* const kCriteria[] = {"depth", "normals", "contour"};
    const Document& document = session.document();
    nlohmann::json messages = nlohmann::json::array();
    for (const StatusMessage& message : session.messages())
        messages.push_back({{"error", message.kind == StatusMessage::Kind::Error}, {"text", message.text}});
    const auto& painted = document.weights.paintedOrEmpty();
    double paintedSum = 0.0;
    for (double w : painted) paintedSum += w;
    nlohmann::json summary = {
        {"panel", panelName(activePanel_)},
        {"document_id", session.documentId()},
        {"undo", session.undoName()},
        {"redo", session.redoName()},
        {"modified", session.modified()},
        {"project_path", session.path().string()},
        {"messages", std::move(messages)},
        {"busy", session.loading() || session.saving() || session.exporting() ||
                     session.refinementRunning() || session.reductionRunning() ||
                     session.phonemeCountRunning() || session.speaking()},
        {"visemes", document.visemeCount()},
        {"selected_viseme", session.selectedViseme},
        {"target", document.target},
        {"constraints", document.constraints.pinned.size() + document.constraints.apart.size() +
                            document.constraints.together.size()},
        {"criterion", kCriteria[static_cast<int>(document.refinement.kind)]},
        {"file_dialog_open", files_.dialog().isOpen()},
        {"brush", brush_.enabled},
        {"weight_mode", toString(document.weights.mode)},
        {"painted_mean", painted.empty() ? 0.0 : paintedSum / static_cast<double>(painted.size())},
        {"wireframe", wireframe_},
        {"face_name", document.face.cascade ? document.face.cascade->name : std::string()},
        {"own_face_step", ownFaceProbe()},
        {"face_view", faceViewProbe()}};
    summary.update(polishSummary());
    avatar_.addProbe(summary);
    visemes_.addProbe(summary);
    frequencies_.addProbe(summary);
    reduction_.addProbe(summary);
    return summary;
}

nlohmann::json EditorUi::faceViewProbe() const {
    if (shownFace_.panel == Panel::Count) return nullptr;
    // Each part's centre where the view drew it: the morph of the uploaded parts at the drawn weights.
    nlohmann::json parts = nlohmann::json::array();
    if (shownFace_.partTriangles > 0 && uploadedParts_) {
        const std::vector<Vec3> positions = partsMesh_.blendedPositions(shownFace_.weights);
        for (const HeadPartSamples::Part& part : uploadedParts_->parts) {
            Vec3 centre(0, 0, 0);
            for (std::size_t i = part.first; i < part.first + part.count; ++i) centre += positions[i];
            if (part.count > 0) centre /= static_cast<double>(part.count);
            parts.push_back({{"name", part.name},
                             {"vertices", part.count},
                             {"centre", {centre[0], centre[1], centre[2]}}});
        }
    }
    nlohmann::json weights = nlohmann::json::object();
    if (const auto& cascade = session.face().cascade)
        for (std::size_t k = 0; k < std::min(cascade->parameters.size(), shownFace_.weights.size()); ++k)
            weights[cascade->parameters[k].name] = shownFace_.weights[k];
    return {{"panel", panelName(shownFace_.panel)},
            {"weights", std::move(weights)},
            {"renders", mainView_.renders()},
            {"skin_triangles", shownFace_.skinTriangles},
            {"part_triangles", shownFace_.partTriangles},
            {"parts", std::move(parts)}};
}

nlohmann::json EditorUi::polishSummary() const {
    const OrbitCamera& camera = subject_ == ViewSubject::Face ? faceCamera_ : visemeCamera_;
    nlohmann::json refine;
    if (const auto& report = session.lastRefinement())
        refine = {{"vertices_before", report->verticesBefore},
                  {"vertices_at_start", report->verticesAtStart},
                  {"from_base_mesh", report->fromBaseMesh},
                  {"vertices_after", report->vertices},
                  {"added", report->stats.splits},
                  {"removed", report->stats.welds}};
    return {{"paint", paintSummary()},
            {"refine", refine},
            {"uv_inset_offset", {uvInsetOffset_.x, uvInsetOffset_.y}},
            {"camera", {{"yaw", camera.yaw}, {"pitch", camera.pitch}, {"distance", camera.distance}}}};
}

// --- GPU copies of the session's meshes ------------------------------------------------------

void EditorUi::syncGpu() {
    if (uploadedGeometry_ != session.geometryGeneration()) {
        uploadedGeometry_ = session.geometryGeneration();
        if (const VisemeSet* set = session.visemes()) {
            std::vector<std::vector<Vec3>> targets;
            for (const auto& v : set->visemes) targets.push_back(v.positions);
            session.attempt("Display visemes", [&] {
                visemeMesh_.setGeometry(set->neutral.positions, set->neutral.triangles, targets);
                if (const auto& colours = session.document().visemeColours) visemeMesh_.setColors(*colours);
            });
        } else {
            visemeMesh_.setGeometry({}, {}, {});
        }
        uploadedMergedCurve_ = 0;
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear();
        frameVisemes_ = true;
    }
    const FaceModel& model = session.face();
    if (uploadedCascade_ != model.cascade || uploadedDomain_ != model.domain) {
        const bool first = uploadedCascade_ == nullptr;
        uploadedCascade_ = model.cascade;
        uploadedDomain_ = model.domain;
        if (model.cascade) {
            const FaceSamples& samples = session.faceSamples();
            faceMesh_.setGeometry(samples.rest, model.domain->triangles, samples.targets);
            faceMesh_.setColors(samples.colours);
        } else {
            faceMesh_.setGeometry({}, {}, {});
        }
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear();
        if (first) frameFace_ = true;
    }
    // The parts are made once per cascade (a refined skin keeps them); the sliders move them as
    // morph weights, like the skin.
    if (std::shared_ptr<const HeadPartSamples> parts = session.faceParts(); parts != uploadedParts_) {
        uploadedParts_ = std::move(parts);
        const bool shown =
            uploadedParts_ && !uploadedParts_->rest.empty() && session.attempt("Head parts", [&] {
                partsMesh_.setGeometry(uploadedParts_->rest, uploadedParts_->triangles,
                                       uploadedParts_->targets);
                partsMesh_.setColors(uploadedParts_->colours);
            });
        if (!shown) partsMesh_.setGeometry({}, {}, {});
    }
    const ReductionResult* curve = session.reductionCurve();
    const int groups = session.document().target;
    if (curve &&
        (uploadedMergedCurve_ != session.reductionCurveRevision() || uploadedMergedGroups_ != groups)) {
        const VisemeSet* set = session.visemes();
        const bool shown = session.attempt("Merged visemes", [&] {
            std::vector<std::vector<Vec3>> targets;
            if (const ReducedModel* merged = session.reducedModel())
                for (const KeyMesh& key : merged->keys) targets.push_back(key.positions);
            mergedMesh_.setGeometry(set->neutral.positions, set->neutral.triangles, targets);
            if (const auto& colours = session.document().visemeColours) mergedMesh_.setColors(*colours);
        });
        if (!shown) mergedMesh_.setGeometry({}, {}, {});
        uploadedMergedCurve_ = session.reductionCurveRevision();
        uploadedMergedGroups_ = groups;
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear();
    }
    syncContextMesh();
    updateScalars();
}

// --- frame -----------------------------------------------------------------------------------

void EditorUi::frame() {
    session.beginFrame();
    session.poll();
    speech_.advance();
    syncGpu();
    frameNewMeshes();
    if (glfwWindowShouldClose(window_) && !files_.quitConfirmed()) {
        glfwSetWindowShouldClose(window_, GLFW_FALSE);
        files_.requestQuit();
    }
    shortcuts();

    const ImGuiIO& io = ImGui::GetIO();
    menuBar();
    const float menuHeight = ImGui::GetFrameHeight();
    const float statusHeight = statusBarHeight();
    const float sideWidth = std::clamp(io.DisplaySize.x * 0.36f, 480.0f, 640.0f);
    const float bodyHeight = std::max(1.0f, io.DisplaySize.y - menuHeight - statusHeight);
    sidePanel(menuHeight, sideWidth, bodyHeight);
    views(sideWidth, menuHeight, std::max(1.0f, io.DisplaySize.x - sideWidth), bodyHeight);
    statusBar(statusHeight);
    files_.draw();
}

namespace {
bool frameOn(OrbitCamera& camera, std::span<const Vec3> positions) {
    Vec3 lo, hi;
    if (!bounds(positions, lo, hi)) return false;
    camera.frame(toGlm(lo), toGlm(hi));
    return true;
}
} // namespace

void EditorUi::frameNewMeshes() {
    // Each subject keeps its camera across tabs; a new mesh (another document) is framed once.
    if (frameVisemes_) {
        const VisemeSet* set = session.visemes();
        if (!set || frameOn(visemeCamera_, set->neutral.positions)) frameVisemes_ = false;
    }
    if (frameFace_) {
        if (!session.face().cascade || frameOn(faceCamera_, session.faceSamples().rest)) frameFace_ = false;
    }
}

void EditorUi::frameAll() {
    if (subject_ == ViewSubject::Face) {
        if (session.face().cascade) frameOn(faceCamera_, session.faceSamples().rest);
    } else if (const VisemeSet* set = session.visemes()) {
        frameOn(visemeCamera_, set->neutral.positions);
    }
}

void EditorUi::shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || files_.dialog().isOpen()) return;
    if (io.KeyCtrl) {
        if (ImGui::IsKeyPressed(GLFW_KEY_O, false)) files_.openProject();
        if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) files_.saveProject(io.KeyShift);
        if (ImGui::IsKeyPressed(GLFW_KEY_Z, false)) io.KeyShift ? session.redo() : session.undo();
        if (ImGui::IsKeyPressed(GLFW_KEY_Y, false)) session.redo();
        if (ImGui::IsKeyPressed(GLFW_KEY_L, false)) files_.loadSample();
    } else if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) {
        frameAll();
    } else if (ImGui::IsKeyPressed(GLFW_KEY_W, false)) {
        wireframe_ = !wireframe_;
    } else if (activePanel_ == Panel::Weights &&
               (ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET) || ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET))) {
        // Brush size by keyboard, as in painting programs, within the radius slider's range.
        const bool pixels = brush_.radius.unit == RadiusUnit::ScreenPixels;
        const double factor = ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET) ? 1.15 : 1.0 / 1.15;
        brush_.radius.value =
            std::clamp(brush_.radius.value * factor, pixels ? 2.0 : 0.5, pixels ? 300.0 : 50.0);
    }
}

void EditorUi::menuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ctl::BeginMenu("File")) {
        if (ctl::MenuItem("New project")) files_.guarded([this] { session.newProject(); });
        if (ctl::MenuItem("Open project...", "Ctrl+O")) files_.openProject();
        if (ctl::MenuItem("Save project", "Ctrl+S", false, !session.path().empty()))
            files_.saveProject(false);
        if (ctl::MenuItem("Save project as...", "Ctrl+Shift+S")) files_.saveProject(true);
        ImGui::Separator();
        if (ctl::MenuItem("Load sample face", "Ctrl+L")) files_.loadSample();
        if (ctl::MenuItem("Open viseme folder...")) files_.openVisemeFolder();
        ImGui::Separator();
        if (ctl::MenuItem("Import avatar...")) avatar_.openImport();
        if (ctl::MenuItem("Export avatar...", nullptr, false, session.document().avatar.isSet()))
            avatar_.openExport();
        ImGui::Separator();
        if (ctl::MenuItem("Quit")) files_.requestQuit();
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("Edit")) {
        const std::string undo = "Undo " + session.undoName();
        const std::string redo = "Redo " + session.redoName();
        if (ctl::MenuItem(undo.c_str(), "Ctrl+Z", false, session.canUndo())) session.undo();
        if (ctl::MenuItem(redo.c_str(), "Ctrl+Y", false, session.canRedo())) session.redo();
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("View")) {
        if (ctl::MenuItem("Frame model", "F")) frameAll();
        ctl::MenuItem("Wireframe overlay", "W", &wireframe_);
        ImGui::Separator();
        for (int i = 0; i < static_cast<int>(Panel::Count); ++i)
            if (ctl::MenuItem(kPanelNames[i], nullptr, activePanel_ == static_cast<Panel>(i)))
                selectPanel(static_cast<Panel>(i));
        ImGui::EndMenu();
    }
    if (ctl::BeginMenu("Help")) {
        ImGui::TextUnformatted("VisemeLab editor");
        ImGui::Separator();
        ImGui::TextUnformatted("Left drag: orbit    Right/middle drag: pan    Wheel: zoom");
        ImGui::TextUnformatted("Arrows: orbit    +/-: zoom    F: frame    W: wireframe");
        ImGui::TextUnformatted("Ctrl+O open, Ctrl+S save, Ctrl+Shift+S save as, Ctrl+L sample");
        ImGui::TextUnformatted("Ctrl+Z undo, Ctrl+Y redo");
        ImGui::TextUnformatted("Weights panel, brush on: left drag paints, Alt+left drag orbits");
        ImGui::TextUnformatted("Guide: docs/user-guide.md");
        ImGui::EndMenu();
    }
    if (session.modified()) {
        ImGui::SameLine(ImGui::GetWindowWidth() - 140.0f);
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
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(4, 4));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemInnerSpacing, ImVec2(2, 4));
    const bool tabs = ImGui::BeginTabBar("##panels", ImGuiTabBarFlags_FittingPolicyResizeDown);
    ImGui::PopStyleVar(2);
    if (tabs) {
        for (int i = 0; i < static_cast<int>(Panel::Count); ++i) {
            const auto panel = static_cast<Panel>(i);
            const ImGuiTabItemFlags flags =
                panelSelectPending_ && activePanel_ == panel ? ImGuiTabItemFlags_SetSelected : 0;
            if (ctl::BeginTabItem(kPanelLabels[i], nullptr, flags)) {
                if (!panelSelectPending_) activePanel_ = panel;
                ImGui::BeginChild("##panel-body");
                switch (panel) {
                case Panel::Visemes:
                    visemes_.draw();
                    break;
                case Panel::Frequencies:
                    frequencies_.draw();
                    break;
                case Panel::Weights:
                    weightsPanel();
                    break;
                case Panel::Deformation:
                    deformationPanel();
                    break;
                case Panel::Refinement:
                    refinement_.draw();
                    break;
                case Panel::Reduction:
                    reduction_.draw();
                    break;
                case Panel::Export:
                    export_.draw();
                    break;
                case Panel::Count:
                    break;
                }
                ImGui::EndChild();
                ImGui::EndTabItem();
            }
        }
        panelSelectPending_ = false;
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void EditorUi::views(float left, float top, float width, float height) {
    const ViewSubject subject = activePanel_ == Panel::Deformation || activePanel_ == Panel::Refinement
                                    ? ViewSubject::Face
                                    : ViewSubject::Visemes;
    subject_ = subject;
    shownFace_ = {}; // the face view says what it draws
    ImGui::SetNextWindowPos(ImVec2(left, top));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin("##views", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
    const ImVec2 size(width, height);
    // The views show the subject's kept camera and hand back what the user did with it.
    OrbitCamera& camera = subject == ViewSubject::Face ? faceCamera_ : visemeCamera_;
    if (activePanel_ == Panel::Reduction) {
        beforeView_.camera = afterView_.camera = camera;
        comparisonViews(size);
        camera = beforeView_.camera; // the two are synchronised by now
    } else {
        mainView_.camera = camera;
        mainView(size);
        camera = mainView_.camera;
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

// --- views -----------------------------------------------------------------------------------

ColorMode EditorUi::surfaceColours() const {
    return session.document().visemeColours ? ColorMode::VertexColor : ColorMode::Surface;
}

std::vector<float> EditorUi::visemeWeights(int viseme) const {
    std::vector<float> w(session.visemeCount(), 0.0f);
    if (viseme >= 0 && viseme < static_cast<int>(w.size())) w[static_cast<std::size_t>(viseme)] = 1.0f;
    return w;
}

void EditorUi::mainView(ImVec2 size) {
    DrawStyle style;
    style.wireframe = wireframe_;
    const bool painting = activePanel_ == Panel::Weights && brush_.enabled;
    const bool orbit = !painting || ImGui::GetIO().KeyAlt;
    std::string label;
    ViewportEvents events;
    if (subject_ == ViewSubject::Face) {
        std::vector<float> q;
        for (double v : session.face().parameters) q.push_back(static_cast<float>(v));
        style.color = showFieldInfluence_ && selectedStage_ >= 0 ? ColorMode::Scalar : ColorMode::VertexColor;
        const auto& cascade = session.face().cascade;
        const bool inset =
            activePanel_ == Panel::Deformation && cascade && selectedStage_ >= 0 &&
            selectedStage_ < static_cast<int>(cascade->stages.size()) &&
            selectedInfluence_ <
                static_cast<int>(
                    cascade->stages[static_cast<std::size_t>(selectedStage_)].field.influences.size());
        // The (u,v) inset (drawn after the view) takes its own mouse drags; where it sits is known
        // before the view is drawn: the view fills the space from the cursor.
        const ImVec2 viewMin = ImGui::GetCursorScreenPos();
        const UvInsetPlace place = uvInsetPlace(viewMin, ImVec2(viewMin.x + size.x, viewMin.y + size.y));
        if (inset) mainView_.excludeFromDrags(place.min, place.max);
        // The skin (its influence colours when a field is selected) and the head's parts inside it,
        // in their own colours, at the same weights.
        DrawStyle partsStyle = style;
        partsStyle.color = ColorMode::VertexColor;
        shownFace_ = {activePanel_, q, faceMesh_.triangleCount(), 0};
        events = mainView_.show("main", size, [&](const glm::mat4& view, const glm::mat4& projection) {
            faceMesh_.draw(shader_, q, view, projection, style);
            if (faceMesh_.empty() || partsMesh_.empty()) return;
            partsMesh_.draw(shader_, q, view, projection, partsStyle);
            shownFace_.partTriangles = partsMesh_.triangleCount();
        });
        if (inset) uvInset(place, selectedStage_, selectedInfluence_);
        if (faceMesh_.empty())
            emptyViewHint(events.imageMin, events.imageMax,
                          "No face loaded: use \"Load bundled face\" in the panel");
        else // a face built from the user's mesh is named by its mesh, not as the bundled one
            label =
                "Deformable face (" +
                (builtinIndividualOf(*cascade) ? std::string(face::individualName(session.face().individual))
                                               : cascade->name) +
                ")";
    } else {
        std::vector<float> weights =
            speech_.shown() ? speech_.weights(false) : visemeWeights(session.selectedViseme);
        if (weights.size() != session.visemeCount()) weights = visemeWeights(-1);
        style.color =
            activePanel_ == Panel::Weights && showWeightsColours_ ? ColorMode::Scalar : surfaceColours();
        if (activePanel_ == Panel::Weights) weights.assign(weights.size(), 0.0f); // paint on the neutral
        events = mainView_.show(
            "main", size,
            [&](const glm::mat4& view, const glm::mat4& projection) {
                visemeMesh_.draw(shader_, weights, view, projection, style);
                drawContext(view, projection);
            },
            orbit);
        if (visemeMesh_.empty()) {
            emptyViewHint(
                events.imageMin, events.imageMax,
                "No viseme set: File > Load sample face (Ctrl+L), or open a project or a viseme folder");
        } else if (activePanel_ == Panel::Weights) {
            label = std::string("Weights: ") + toString(session.document().weights.mode);
            if (showWeightsColours_) colourLegend(events.imageMin, events.imageMax, "0", "largest weight");
        } else if (speech_.shown()) {
            label = session.speechClip()->label + " (full set)";
        } else {
            const int s = session.selectedViseme;
            label =
                s >= 0 ? "Viseme " + session.visemes()->visemes[static_cast<std::size_t>(s)].name : "Neutral";
        }
        if (activePanel_ == Panel::Weights) paint(events); // readout always, tools while painting
    }
    if (!label.empty()) viewLabel(events.imageMin, label);
}

void EditorUi::comparisonViews(ImVec2 size) {
    // With a clip shown, the timeline takes the bottom of the views.
    const bool speech = speech_.shown();
    const float timelineHeight = speech ? std::min(230.0f, 0.32f * size.y) : 0.0f;
    const ImVec2 half(std::floor(size.x * 0.5f) - 1.0f, size.y - timelineHeight);
    const int selected = std::max(session.selectedViseme, 0);
    const Grouping* grouping = session.currentGrouping();
    const SpeechPlayback* playback = speech ? session.speechPlayback() : nullptr;
    std::vector<float> before = speech ? speech_.weights(false) : visemeWeights(selected);
    if (before.size() != session.visemeCount()) before = visemeWeights(-1); // no track: the neutral
    std::vector<float> after;
    std::string afterLabel = "Reduced set: waiting for the reduction";
    std::string beforeLabel =
        session.visemes() && !speech
            ? "Original " + session.visemes()->visemes[static_cast<std::size_t>(selected)].name
            : "";
    if (speech) {
        beforeLabel = "Full set (" + std::to_string(session.visemeCount()) +
                      " visemes)"; // the Say section names the clip
        if (playback && !playback->problem.empty()) beforeLabel = "Cannot play: " + playback->problem;
    }
    if (grouping && session.visemes()) {
        if (speech) {
            after = speech_.weights(true);
            if (after.size() != grouping->groups.size()) after.assign(grouping->groups.size(), 0.0f);
            afterLabel = "Reduced set (m = " + std::to_string(grouping->groups.size()) + ")";
            if (playback && playback->error) {
                const auto& frames = playback->error->frames;
                const auto frame =
                    static_cast<std::size_t>(std::lround(speech_.time() * playback->error->fps));
                char text[96];
                std::snprintf(text, sizeof text, ", error now %.3g (mean %.3g)",
                              frames.empty() ? 0.0 : frames[std::min(frame, frames.size() - 1)],
                              playback->error->mean);
                afterLabel += text;
            }
        } else {
            const int group = grouping->groupOf()[static_cast<std::size_t>(selected)];
            after.assign(grouping->groups.size(), 0.0f);
            static const char* const kShown[] = {" (error colours)", " (skin)", " on the original (cyan)"};
            if (group == kRestGroup) { // no key: every weight 0 shows the neutral
                afterLabel =
                    std::string("Rests: the neutral") + kShown[static_cast<int>(reduction_.mergedDisplay())];
            } else {
                after[static_cast<std::size_t>(group)] = 1.0f;
                afterLabel = "Merged group " + std::to_string(group + 1) +
                             kShown[static_cast<int>(reduction_.mergedDisplay())];
            }
        }
    }
    DrawStyle plain;
    plain.wireframe = wireframe_;
    plain.color = surfaceColours();
    DrawStyle errors = plain;
    const bool errorColours =
        !speech && reduction_.mergedDisplay() == ReductionPanel::MergedDisplay::ErrorColours;
    if (errorColours) errors.color = ColorMode::Scalar;
    DrawStyle ghost = plain;
    ghost.ghost = true;
    const bool overlay = !speech && reduction_.mergedDisplay() == ReductionPanel::MergedDisplay::Overlay;
    const ViewportEvents left =
        beforeView_.show("before", half, [&](const glm::mat4& view, const glm::mat4& projection) {
            visemeMesh_.draw(shader_, before, view, projection, plain);
            drawContext(view, projection);
        });
    if (session.visemes())
        viewLabel(left.imageMin, beforeLabel);
    else
        emptyViewHint(left.imageMin, left.imageMax, "No viseme set loaded");
    ImGui::SameLine(0.0f, 2.0f);
    const ViewportEvents right =
        afterView_.show("after", half, [&](const glm::mat4& view, const glm::mat4& projection) {
            drawContext(view, projection); // the avatar's meshes without visemes, greyed
            if (!grouping) return;
            mergedMesh_.draw(shader_, after, view, projection, errors);
            if (overlay) visemeMesh_.draw(shader_, before, view, projection, ghost);
        });
    if (session.visemes()) viewLabel(right.imageMin, afterLabel);
    if (grouping && errorColours)
        colourLegend(right.imageMin, right.imageMax, "0 mm",
                     [&] {
                         char text[64];
                         std::snprintf(text, sizeof text, "%.3g mm (largest, all visemes)",
                                       errorLegendMax_ * reduction_.millimetresPerModelUnit());
                         return std::string(text);
                     }()
                         .c_str());
    // One camera for both views: the one the user is moving wins.
    if (right.hovered || right.leftDown)
        beforeView_.camera = afterView_.camera;
    else
        afterView_.camera = beforeView_.camera;
    if (speech) {
        ImGui::SetCursorScreenPos(ImVec2(left.imageMin.x, left.imageMax.y + 2.0f));
        speech_.timeline(ImVec2(size.x, timelineHeight - 2.0f));
    }
}

void EditorUi::syncContextMesh() {
    const DocumentAvatar& avatar = session.document().avatar;
    if (avatar.scan == uploadedContext_) return;
    uploadedContext_ = avatar.scan;
    if (!avatar.isSet() || avatar.scan->context.positions.empty()) {
        contextMesh_.setGeometry({}, {}, {});
        return;
    }
    const MeshData& context = avatar.scan->context;
    session.attempt("Display the avatar",
                    [&] { contextMesh_.setGeometry(context.positions, context.triangles, {}); });
}

void EditorUi::drawContext(const glm::mat4& view, const glm::mat4& projection) const {
    if (contextMesh_.empty()) return;
    // Greyed: the meshes the reduction does not touch (body, hair, outfit), for orientation only.
    DrawStyle grey;
    grey.wireframe = false;
    grey.color = ColorMode::Surface;
    grey.surfaceColor = glm::vec3(0.36f, 0.37f, 0.40f);
    contextMesh_.draw(shader_, {}, view, projection, grey);
}

} // namespace vl::ui
