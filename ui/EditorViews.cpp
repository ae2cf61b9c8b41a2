// The editor's views: the main view (visemes; the face with its (u,v) inset; painting) and the
// Reduction panel's side-by-side comparison, the GPU copies of the session's meshes, the cameras,
// and the per-vertex scalars (weights, merge errors, field influence) shown through the colour map.
#include "ui/EditorViews.h"

#include "core/gltf/AvatarScan.h"
#include "core/inspect/VertexErrors.h"
#include "core/project/BuiltinGeometry.h"
#include "ui/UiScale.h"
#include "ui/probe/GuiProbe.h"
#include "ui/widgets/SurfaceToggle.h"

#include <imgui.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <span>

namespace vl::ui {
namespace {

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

// A view's title in its top left corner, wrapped onto more lines when wider than the view (a
// narrow comparison view at 1024 px cut it); recorded for the probe.
void drawViewLabel(const ImVec2& min, const ImVec2& max, const std::string& text) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float wrap = std::max(40.0f, max.x - min.x - 28.0f);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 box(min.x + 8, min.y + 8), boxMax(min.x + 16 + size.x, min.y + 12 + size.y);
    draw->AddRectFilled(box, boxMax, IM_COL32(20, 20, 24, 170), 4.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(min.x + 12, min.y + 10),
                  IM_COL32(235, 235, 240, 255), text.c_str(), nullptr, wrap);
    probe::recordRect(text.c_str(), "view-label", box, boxMax);
}

// The colour ramp of shaders/mesh.frag as a bar in the lower left corner of a view.
void colourLegend(const ImVec2& min, const ImVec2& max, const char* low, const char* high) {
    static const ImU32 stops[] = {IM_COL32(46, 61, 133, 255), IM_COL32(38, 133, 235, 255),
                                  IM_COL32(26, 217, 153, 255), IM_COL32(242, 217, 51, 255),
                                  IM_COL32(204, 31, 13, 255)};
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float highWidth = ImGui::CalcTextSize(high).x;
    const float lowWidth = ImGui::CalcTextSize(low).x;
    const float margin = scaled(16.0f), line = ImGui::GetTextLineHeight();
    const float width = std::max(scaled(60.0f), std::min(scaled(200.0f), max.x - min.x - 2.0f * margin));
    // In a narrow view (a comparison at 1024 px) the high label goes on a line of its own rather than
    // past the view's edge.
    const bool ownLine = margin + lowWidth + 12.0f + highWidth > max.x - min.x - 4.0f ||
                         std::max(width - highWidth, lowWidth + 12.0f) + highWidth > max.x - min.x - margin;
    const float height = scaled(12.0f);
    const ImVec2 origin(min.x + margin, max.y - scaled(36.0f) - (ownLine ? line : 0.0f));
    for (int i = 0; i < 4; ++i) {
        const float x0 = origin.x + width * static_cast<float>(i) / 4.0f;
        const float x1 = origin.x + width * static_cast<float>(i + 1) / 4.0f;
        draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), stops[i],
                                      stops[i + 1], stops[i + 1], stops[i]);
    }
    draw->AddRect(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(20, 20, 24, 255));
    draw->AddText(ImVec2(origin.x, origin.y + height + 2.0f), IM_COL32(220, 220, 230, 255), low);
    // Right-aligned under the bar's end, but never over the low label.
    const ImVec2 at = ownLine ? ImVec2(origin.x, origin.y + height + 2.0f + line)
                              : ImVec2(std::max(origin.x + width - highWidth, origin.x + lowWidth + 12.0f),
                                       origin.y + height + 2.0f);
    draw->AddText(at, IM_COL32(220, 220, 230, 255), high);
}

std::vector<float> normalised(const std::vector<double>& values, double scale) {
    std::vector<float> out(values.size(), 0.0f);
    if (scale <= 0.0) return out;
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<float>(values[i] / scale);
    return out;
}

double maxOf(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

} // namespace

nlohmann::json EditorViews::faceViewProbe() const {
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
    if (const auto& cascade = session_.document().face.cascade)
        for (std::size_t k = 0; k < std::min(cascade->parameters.size(), shownFace_.weights.size()); ++k)
            weights[cascade->parameters[k].name] = shownFace_.weights[k];
    return {{"panel", panelName(shownFace_.panel)},
            {"weights", std::move(weights)},
            {"renders", mainView_.renders()},
            {"skin_triangles", shownFace_.skinTriangles},
            {"part_triangles", shownFace_.partTriangles},
            {"parts", std::move(parts)}};
}

void EditorViews::syncGpu() {
    if (refreshViewMaterials(materials_, session_.document(), session_)) {
        // Another source of materials: every mesh that shows them is uploaded again.
        uploadedGeometry_ = 0;
        uploadedMergedCurve_ = 0;
        uploadedContext_ = nullptr;
    }
    if (uploadedGeometry_ != session_.history().geometryRevision()) {
        uploadedGeometry_ = session_.history().geometryRevision();
        if (const VisemeSet* set = session_.visemes()) {
            session_.attempt("Display visemes", [&] {
                visemeMesh_.setGeometry(set->neutral.positions, set->neutral.triangles,
                                        positionSpans(set->visemes, &Viseme::positions));
                if (const auto& colours = session_.document().visemeColours) visemeMesh_.setColors(*colours);
            });
            session_.attempt("Display materials",
                             [&] { visemeMesh_.setSurface(materials_.visemes, materials_.materials); });
        } else {
            visemeMesh_.setGeometry({}, {}, {});
        }
        uploadedMergedCurve_ = 0;
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear(), mainErrorKey_.clear();
        // Another set is framed once; an edit of a viseme (a sculpt stroke, an undo) keeps the camera.
        const VisemeSet* set = session_.visemes();
        std::vector<Vec3> neutral = set ? set->neutral.positions : std::vector<Vec3>();
        if (neutral != framedNeutral_) {
            framedNeutral_ = std::move(neutral);
            frameVisemes_ = true;
        }
    }
    const FaceModel& model = session_.document().face;
    if (uploadedFace_ != session_.face().samplesRevision()) {
        const bool first = !uploadedFaceShown_;
        uploadedFace_ = session_.face().samplesRevision();
        uploadedFaceShown_ = model.cascade != nullptr;
        if (model.cascade) {
            const FaceSamples& samples = session_.face().samples();
            faceMesh_.setGeometry(samples.rest, model.domain->triangles, positionSpans(samples.targets));
            faceMesh_.setColors(samples.colours);
        } else {
            faceMesh_.setGeometry({}, {}, {});
        }
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear();
        if (first) frameFace_ = true;
    }
    // The parts are made once per cascade (a refined skin keeps them); the sliders move them as
    // morph weights, like the skin.
    if (std::shared_ptr<const HeadPartSamples> parts = session_.face().parts(); parts != uploadedParts_) {
        uploadedParts_ = std::move(parts);
        const bool shown =
            uploadedParts_ && !uploadedParts_->rest.empty() && session_.attempt("Head parts", [&] {
                partsMesh_.setGeometry(uploadedParts_->rest, uploadedParts_->triangles,
                                       positionSpans(uploadedParts_->targets));
                partsMesh_.setColors(uploadedParts_->colours);
            });
        if (!shown) partsMesh_.setGeometry({}, {}, {});
    }
    const ReductionResult* curve = session_.reduction().curve();
    const int groups = session_.document().target;
    if (curve &&
        (uploadedMergedCurve_ != session_.reduction().curveRevision() || uploadedMergedGroups_ != groups)) {
        const VisemeSet* set = session_.visemes();
        const bool shown = session_.attempt("Merged visemes", [&] {
            std::vector<PositionSpan> targets;
            if (const ReducedModel* merged = session_.reduction().reducedModel())
                targets = positionSpans(merged->keys, &KeyMesh::positions);
            mergedMesh_.setGeometry(set->neutral.positions, set->neutral.triangles, targets);
            if (const auto& colours = session_.document().visemeColours) mergedMesh_.setColors(*colours);
        });
        if (!shown) mergedMesh_.setGeometry({}, {}, {});
        // The viseme mesh's materials: a layout that does not fit was reported for it already.
        if (shown && visemeMesh_.hasSurface()) {
            try {
                mergedMesh_.setSurface(materials_.visemes, materials_.materials);
            } catch (const std::exception&) {
            }
        }
        uploadedMergedCurve_ = session_.reduction().curveRevision();
        uploadedMergedGroups_ = groups;
        weightsKey_.clear(), errorKey_.clear(), influenceKey_.clear();
    }
    syncContextMesh();
    // The own-face step's mesh; the face camera frames it when it appears and the face when it goes.
    const auto& step = session_.document().ownFace;
    if (std::shared_ptr<const face::UvMesh> mesh = step ? step->mesh : nullptr; mesh != uploadedOwnFace_) {
        uploadedOwnFace_ = std::move(mesh);
        const bool shown = uploadedOwnFace_ && session_.attempt("Display your mesh", [&] {
            ownFaceMesh_.setGeometry(uploadedOwnFace_->positions, uploadedOwnFace_->triangles, {});
        });
        if (!shown) ownFaceMesh_.setGeometry({}, {}, {});
        frameFace_ = true;
    }
    updateScalars();
}

namespace {
bool frameOn(OrbitCamera& camera, std::span<const Vec3> positions) {
    Vec3 lo, hi;
    if (!bounds(positions, lo, hi)) return false;
    camera.frame(toGlm(lo), toGlm(hi));
    return true;
}
} // namespace

void EditorViews::frameNewMeshes() {
    // Each subject keeps its camera across tabs; a new mesh (another document) is framed once.
    if (frameVisemes_) {
        const VisemeSet* set = session_.visemes();
        if (!set || frameOn(visemeCamera_, set->neutral.positions)) frameVisemes_ = false;
    }
    if (frameFace_) {
        if (uploadedOwnFace_)
            frameFace_ = !frameOn(faceCamera_, uploadedOwnFace_->positions);
        else if (!session_.document().face.cascade || frameOn(faceCamera_, session_.face().samples().rest))
            frameFace_ = false;
    }
}

void EditorViews::frameAll() {
    if (subject_ == ViewSubject::Face) {
        if (uploadedOwnFace_)
            frameOn(faceCamera_, uploadedOwnFace_->positions);
        else if (session_.document().face.cascade)
            frameOn(faceCamera_, session_.face().samples().rest);
    } else if (const VisemeSet* set = session_.visemes()) {
        frameOn(visemeCamera_, set->neutral.positions);
    }
}

void EditorViews::viewLabel(const ViewportEvents& view, const std::string& text) {
    drawViewLabel(view.imageMin, view.imageMax, text);
    shownLabels_.push_back(text);
}

void EditorViews::setView(StandardView view) {
    shownCamera().setView(view);
}

void EditorViews::setStartView(StandardView view, bool orthographic) {
    for (OrbitCamera* camera : {&visemeCamera_, &faceCamera_}) {
        camera->setView(view);
        camera->orthographic = orthographic;
    }
}

void EditorViews::resetView() {
    OrbitCamera& camera = shownCamera();
    camera.setView(StandardView::Front);
    camera.orthographic = false;
    frameAll();
}

void EditorViews::toggleOrthographic() {
    shownCamera().orthographic = !shownCamera().orthographic;
}

void EditorViews::draw(Panel active, float left, float top, float width, float height) {
    active_ = active;
    const ViewSubject subject = active_ == Panel::Deformation || active_ == Panel::Refinement
                                    ? ViewSubject::Face
                                    : ViewSubject::Visemes;
    subject_ = subject;
    shownFace_ = {}; // the face view says what it draws
    shownVisemeParts_ = {};
    shownLabels_.clear();
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
    if (active_ == Panel::Reduction) {
        beforeView_.camera = afterView_.camera = camera;
        comparisonViews(size);
        camera = beforeView_.camera; // the two are synchronised by now
    } else {
        mainView_.camera = camera;
        drawMainView(size);
        camera = mainView_.camera;
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

ColorMode EditorViews::surfaceColours() const {
    return session_.document().visemeColours ? ColorMode::VertexColor : ColorMode::Surface;
}

ColorMode EditorViews::skinColours(const GpuMesh& mesh) const {
    return drawnSurface_ == SurfaceShading::Materials && mesh.hasSurface() ? ColorMode::Material
                                                                           : surfaceColours();
}

void EditorViews::setSurface(SurfaceShading shading) {
    surface = shading;
    using Display = ReductionPanel::MergedDisplay;
    if (shading == SurfaceShading::ErrorColours)
        panels_.reduction.setMergedDisplay(Display::ErrorColours);
    else if (panels_.reduction.mergedDisplay() == Display::ErrorColours)
        panels_.reduction.setMergedDisplay(Display::Skin);
}

void EditorViews::excludeSurfaceSwitch(Viewport& view, ImVec2 viewMin, ImVec2 size) const {
    if (!hasMaterials()) return;
    ImVec2 min, max;
    surfaceToggleRect(ImVec2(viewMin.x + size.x, viewMin.y), min, max);
    view.excludeFromDrags(min, max);
}

void EditorViews::surfaceSwitch(const ViewportEvents& view) {
    if (!hasMaterials()) return;
    SurfaceShading shading = drawnSurface_;
    if (surfaceToggle(ImVec2(view.imageMax.x, view.imageMin.y), shading)) setSurface(shading);
}

std::vector<float> EditorViews::visemeWeights(int viseme) const {
    std::vector<float> w(session_.visemeCount(), 0.0f);
    if (viseme >= 0 && viseme < static_cast<int>(w.size())) w[static_cast<std::size_t>(viseme)] = 1.0f;
    return w;
}

std::vector<float> EditorViews::visemePartWeights(std::span<const float> weights) {
    const std::vector<std::vector<double>>& parameters = session_.authoring().visemeFaceParameters();
    const auto& cascade = session_.document().face.cascade;
    if (parameters.empty() || !cascade || parameters.size() != weights.size()) return {};
    const std::vector<double> rest = cascade->defaults();
    std::vector<double> q = rest;
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (weights[i] != 0.0f)
            for (std::size_t k = 0; k < q.size() && k < parameters[i].size(); ++k)
                q[k] += static_cast<double>(weights[i]) * (parameters[i][k] - rest[k]);
    return std::vector<float>(q.begin(), q.end());
}

std::size_t EditorViews::drawHeadParts(std::span<const float> q, const glm::mat4& view,
                                       const glm::mat4& projection, const DrawStyle& skinStyle) const {
    if (partsMesh_.empty()) return 0;
    DrawStyle partsStyle = skinStyle;
    partsStyle.color = ColorMode::VertexColor;
    partsMesh_.draw(shader_, q, view, projection, partsStyle);
    return partsMesh_.triangleCount();
}

void EditorViews::drawMainView(ImVec2 size) {
    const DeformationPanel::Field selected = panels_.deformation.selectedField();
    drawnSurface_ = shownSurface();
    DrawStyle style;
    style.wireframe = wireframe;
    const bool painting = (active_ == Panel::Weights && panels_.weights.painter().brush.enabled) ||
                          (active_ == Panel::Visemes && panels_.visemes.sculptor().active());
    const bool orbit = !painting || ImGui::GetIO().KeyAlt;
    std::string label;
    ViewportEvents events;
    if (subject_ == ViewSubject::Face && active_ == Panel::Deformation && uploadedOwnFace_) {
        events = drawOwnFaceStep(size, style, label);
    } else if (subject_ == ViewSubject::Face) {
        std::vector<float> q;
        for (double v : session_.document().face.parameters) q.push_back(static_cast<float>(v));
        style.color = panels_.deformation.showInfluence() && selected.stage >= 0 ? ColorMode::Scalar
                                                                                 : ColorMode::VertexColor;
        const auto& cascade = session_.document().face.cascade;
        const bool inset =
            active_ == Panel::Deformation && cascade && selected.stage >= 0 &&
            selected.stage < static_cast<int>(cascade->stages.size()) &&
            selected.influence <
                static_cast<int>(
                    cascade->stages[static_cast<std::size_t>(selected.stage)].field.influences.size());
        // The (u,v) inset (drawn after the view) takes its own mouse drags; where it sits is known
        // before the view is drawn: the view fills the space from the cursor.
        const ImVec2 viewMin = ImGui::GetCursorScreenPos();
        const DeformationPanel::InsetPlace place =
            panels_.deformation.insetPlace(viewMin, ImVec2(viewMin.x + size.x, viewMin.y + size.y));
        if (inset) mainView_.excludeFromDrags(place.min, place.max);
        // The skin (its influence colours when a field is selected) and the head's parts inside it,
        // in their own colours, at the same weights.
        shownFace_ = {active_, q, faceMesh_.triangleCount(), 0};
        events = mainView_.show("main", size, [&](const glm::mat4& view, const glm::mat4& projection) {
            faceMesh_.draw(shader_, q, view, projection, style);
            if (!faceMesh_.empty()) shownFace_.partTriangles = drawHeadParts(q, view, projection, style);
        });
        if (inset) panels_.deformation.inset(place);
        if (faceMesh_.empty())
            emptyViewHint(events.imageMin, events.imageMax,
                          "No face loaded: use \"Load bundled face\" in the panel");
        else // a face built from the user's mesh is named by its mesh, not as the bundled one
            label =
                "Deformable face (" +
                (builtinIndividualOf(*cascade) ? std::string(toString(session_.document().face.individual))
                                               : cascade->name) +
                ")";
    } else {
        std::vector<float> weights =
            speech_.shown() ? speech_.weights(false) : visemeWeights(session_.selectedViseme());
        if (weights.size() != session_.visemeCount()) weights = visemeWeights(-1);
        // Weight colours while painting; with materials switched to error colours, the merge error of
        // the selected viseme once the reduction has one.
        const bool errorMap = active_ == Panel::Visemes && !mainErrorKey_.empty();
        style.color = (active_ == Panel::Weights && panels_.weights.showColours()) || errorMap
                          ? ColorMode::Scalar
                          : skinColours(visemeMesh_);
        if (active_ == Panel::Weights) weights.assign(weights.size(), 0.0f); // paint on the neutral
        // A set the face made shows the head's teeth, tongue and cavity in the mouth, as the face view
        // does (not while painting weights, which apply to the skin alone).
        std::vector<float> partsQ;
        if (active_ != Panel::Weights) partsQ = visemePartWeights(weights);
        shownVisemeParts_ = {0, partsQ};
        shownMainColour_ = style.color;
        excludeSurfaceSwitch(mainView_, ImGui::GetCursorScreenPos(), size);
        events = mainView_.show(
            "main", size,
            [&](const glm::mat4& view, const glm::mat4& projection) {
                visemeMesh_.draw(shader_, weights, view, projection, style);
                if (!partsQ.empty() && !visemeMesh_.empty())
                    shownVisemeParts_.triangles = drawHeadParts(partsQ, view, projection, style);
                drawContext(view, projection);
            },
            orbit);
        if (visemeMesh_.empty()) {
            emptyViewHint(
                events.imageMin, events.imageMax,
                "No viseme set: File > Load sample face (Ctrl+L), or open a project or a viseme folder");
        } else if (active_ == Panel::Weights) {
            label = std::string("Weights: ") + toString(session_.document().weights.mode);
            if (panels_.weights.showColours())
                colourLegend(events.imageMin, events.imageMax, "0", "largest weight");
        } else if (speech_.shown()) {
            label = session_.speech().clip()->label + " (full set)";
        } else {
            const int s = session_.selectedViseme();
            label = s >= 0 ? "Viseme " + session_.visemes()->visemes[static_cast<std::size_t>(s)].name
                           : "Neutral";
            if (errorMap) {
                label += " (merge error)";
                errorLegend(events);
            }
        }
        if (!visemeMesh_.empty()) surfaceSwitch(events);
        if (active_ == Panel::Weights)
            panels_.weights.painter().paint(events); // readout always, tools while painting
        if (active_ == Panel::Visemes && !speech_.shown()) panels_.visemes.sculptor().sculpt(events);
    }
    if (!label.empty()) viewLabel(events, label);
}

ViewportEvents EditorViews::drawOwnFaceStep(ImVec2 size, const DrawStyle& style, std::string& label) {
    LandmarkHandles& handles = panels_.deformation.landmarkHandles();
    const bool orbit = !handles.wantsMouse(mainView_.camera, ImGui::GetCursorScreenPos(), size);
    const ViewportEvents events = mainView_.show(
        "main", size,
        [&](const glm::mat4& view, const glm::mat4& projection) {
            ownFaceMesh_.draw(shader_, {}, view, projection, style);
        },
        orbit);
    handles.handle(mainView_.camera, events);
    // The panel may have closed the step this frame (Cancel, Build): the mesh is shown once more.
    if (const auto& step = session_.document().ownFace)
        label = "Your mesh " + step->name + ": drag a landmark's dot to move it";
    return events;
}

void EditorViews::comparisonViews(ImVec2 size) {
    // With a clip shown, the timeline takes the bottom of the views.
    const bool speech = speech_.shown();
    const float timelineHeight = speech ? std::min(scaled(230.0f), 0.32f * size.y) : 0.0f;
    const ImVec2 half(std::floor(size.x * 0.5f) - 1.0f, size.y - timelineHeight);
    const int selected = std::max(session_.selectedViseme(), 0);
    const Grouping* grouping = session_.reduction().grouping();
    const SpeechPlayback* playback = speech ? session_.speech().playback() : nullptr;
    std::vector<float> before = speech ? speech_.weights(false) : visemeWeights(selected);
    if (before.size() != session_.visemeCount()) before = visemeWeights(-1); // no track: the neutral
    std::vector<float> after;
    std::string afterLabel = "Reduced set: waiting for the reduction";
    std::string beforeLabel =
        session_.visemes() && !speech
            ? "Original " + session_.visemes()->visemes[static_cast<std::size_t>(selected)].name
            : "";
    if (speech) {
        beforeLabel = "Full set (" + std::to_string(session_.visemeCount()) +
                      " visemes)"; // the Say section names the clip
        if (playback && !playback->problem.empty()) beforeLabel = "Cannot play: " + playback->problem;
    }
    if (grouping && session_.visemes()) {
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
                afterLabel = std::string("Rests: the neutral") +
                             kShown[static_cast<int>(panels_.reduction.mergedDisplay())];
            } else {
                after[static_cast<std::size_t>(group)] = 1.0f;
                afterLabel = "Merged group " + std::to_string(group + 1) +
                             kShown[static_cast<int>(panels_.reduction.mergedDisplay())];
            }
        }
    }
    // The comparison follows the panel's choice for the right view: its error colours are the
    // analysis colours on both sides, skin and overlay show the materials.
    drawnSurface_ =
        hasMaterials() && panels_.reduction.mergedDisplay() != ReductionPanel::MergedDisplay::ErrorColours
            ? SurfaceShading::Materials
            : SurfaceShading::ErrorColours;
    DrawStyle plain;
    plain.wireframe = wireframe;
    plain.color = skinColours(visemeMesh_);
    DrawStyle errors = plain;
    const bool errorColours =
        !speech && panels_.reduction.mergedDisplay() == ReductionPanel::MergedDisplay::ErrorColours;
    if (errorColours) errors.color = ColorMode::Scalar;
    DrawStyle ghost = plain;
    ghost.ghost = true;
    const bool overlay =
        !speech && panels_.reduction.mergedDisplay() == ReductionPanel::MergedDisplay::Overlay;
    const ViewportEvents left =
        beforeView_.show("before", half, [&](const glm::mat4& view, const glm::mat4& projection) {
            visemeMesh_.draw(shader_, before, view, projection, plain);
            drawContext(view, projection);
        });
    if (session_.visemes())
        viewLabel(left, beforeLabel);
    else
        emptyViewHint(left.imageMin, left.imageMax, "No viseme set loaded");
    ImGui::SameLine(0.0f, 2.0f);
    excludeSurfaceSwitch(afterView_, ImGui::GetCursorScreenPos(), half);
    const ViewportEvents right =
        afterView_.show("after", half, [&](const glm::mat4& view, const glm::mat4& projection) {
            drawContext(view, projection); // the avatar's meshes without visemes, greyed
            if (!grouping) return;
            mergedMesh_.draw(shader_, after, view, projection, errors);
            if (overlay) visemeMesh_.draw(shader_, before, view, projection, ghost);
        });
    if (session_.visemes()) viewLabel(right, afterLabel);
    if (grouping && errorColours) errorLegend(right);
    if (session_.visemes()) surfaceSwitch(right);
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

void EditorViews::errorLegend(const ViewportEvents& view) const {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g mm (largest, all visemes)",
                  errorLegendMax_ * panels_.reduction.millimetresPerModelUnit());
    colourLegend(view.imageMin, view.imageMax, "0 mm", text);
}

void EditorViews::syncContextMesh() {
    const DocumentAvatar& avatar = session_.document().avatar;
    if (avatar.scan == uploadedContext_) return;
    uploadedContext_ = avatar.scan;
    if (!avatar.isSet() || avatar.scan->context.positions.empty()) {
        contextMesh_.setGeometry({}, {}, {});
        return;
    }
    const MeshData& context = avatar.scan->context;
    if (session_.attempt("Display the avatar",
                         [&] { contextMesh_.setGeometry(context.positions, context.triangles, {}); }))
        session_.attempt("Display materials",
                         [&] { contextMesh_.setSurface(materials_.context, materials_.materials); });
}

void EditorViews::drawContext(const glm::mat4& view, const glm::mat4& projection) const {
    if (contextMesh_.empty()) return;
    // The meshes the reduction does not touch (body, hair, outfit), for orientation only: in their
    // materials, or greyed.
    DrawStyle grey;
    grey.wireframe = false;
    grey.color = skinColours(contextMesh_) == ColorMode::Material ? ColorMode::Material : ColorMode::Surface;
    grey.surfaceColor = glm::vec3(0.36f, 0.37f, 0.40f);
    contextMesh_.draw(shader_, {}, view, projection, grey);
}

bool EditorViews::mergeErrors(int selected, std::vector<float>& values) {
    const VisemeSet* set = session_.visemes();
    const Grouping* grouping = session_.reduction().grouping();
    bool done = false;
    session_.attempt("Error map", [&] {
        const ReducedModel* merged = session_.reduction().reducedModel();
        if (!set || !grouping || !merged) return;
        const std::vector<double> w = session_.weights().values();
        double scale = 0.0;
        std::vector<double> shown;
        const auto measure = [&](int member, const std::vector<Vec3>& shape) {
            auto errors = vertexErrors(set->visemes[static_cast<std::size_t>(member)].positions, shape, w);
            scale = std::max(scale, maxOf(errors));
            if (member == selected) shown = std::move(errors);
        };
        for (std::size_t g = 0; g < grouping->groups.size(); ++g)
            for (int member : grouping->groups[g]) measure(member, merged->keys[g].positions);
        // A resting viseme is shown as the neutral: its error is its distance from it.
        for (int member : grouping->rest) measure(member, set->neutral.positions);
        // Square root: distances read better than squared distances on a colour ramp. The
        // legend reads in distance for a vertex of the largest weight (sqrt(w) d / sqrt(w_max)).
        for (double& e : shown) e = std::sqrt(e);
        values = normalised(shown, std::sqrt(scale));
        const double maxWeight = maxOf(w);
        errorLegendMax_ = maxWeight > 0.0 ? std::sqrt(scale / maxWeight) : 0.0;
        done = true;
    });
    return done;
}

void EditorViews::updateScalars() {
    const VisemeSet* set = session_.visemes();
    // Metric weights on the viseme mesh (the Weights panel).
    if (set && active_ == Panel::Weights) {
        WeightPainter& painter = panels_.weights.painter();
        const std::vector<double>* stroke = painter.strokeWeights();
        const std::string key =
            "w" + std::to_string(session_.documentInputs().reductionRevision()) + (stroke ? "s" : "");
        if (key != weightsKey_ || stroke) {
            std::vector<double> w;
            if (stroke) {
                w = *stroke;
            } else {
                session_.attempt("Weights", [&] { w = session_.weights().values(); });
                painter.setShownWeights(w);
            }
            visemeMesh_.setScalars(normalised(w, maxOf(w)));
            weightsKey_ = key;
            mainErrorKey_.clear(); // the merge errors are no longer there
        }
    }
    // Merge error of the selected viseme on the reduced view.
    const Grouping* grouping = session_.reduction().grouping();
    if (set && grouping && active_ == Panel::Reduction) {
        const int selected = std::max(session_.selectedViseme(), 0);
        const std::string key = std::to_string(selected) + ":" +
                                std::to_string(session_.documentInputs().reductionRevision()) + ":" +
                                std::to_string(grouping->groups.size());
        if (key != errorKey_) {
            std::vector<float> values;
            if (mergeErrors(selected, values)) mergedMesh_.setScalars(values);
            errorKey_ = key;
        }
    }
    // The same on the viseme itself in the Visemes panel, when materials are switched to error colours.
    const bool mainErrors = set && grouping && active_ == Panel::Visemes && hasMaterials() &&
                            surface == SurfaceShading::ErrorColours && session_.selectedViseme() >= 0 &&
                            !speech_.shown();
    if (!mainErrors) {
        mainErrorKey_.clear();
    } else {
        const std::string key = std::to_string(session_.selectedViseme()) + ":" +
                                std::to_string(session_.documentInputs().reductionRevision()) + ":" +
                                std::to_string(grouping->groups.size());
        std::vector<float> values;
        if (key != mainErrorKey_ && mergeErrors(session_.selectedViseme(), values)) {
            visemeMesh_.setScalars(values);
            mainErrorKey_ = key;
            weightsKey_.clear(); // the weights are no longer there
        }
    }
    // Influence of the selected analytic field on the face.
    const FaceModel& model = session_.document().face;
    const DeformationPanel::Field selected = panels_.deformation.selectedField();
    if (model.cascade && selected.stage >= 0 &&
        selected.stage < static_cast<int>(model.cascade->stages.size())) {
        const auto& influences =
            model.cascade->stages[static_cast<std::size_t>(selected.stage)].field.influences;
        const std::string key = std::to_string(reinterpret_cast<std::uintptr_t>(model.cascade.get())) + ":" +
                                std::to_string(selected.stage) + ":" + std::to_string(selected.influence);
        if (key != influenceKey_ && selected.influence < static_cast<int>(influences.size())) {
            const InfluenceField& field = influences[static_cast<std::size_t>(selected.influence)];
            std::vector<float> values;
            values.reserve(model.domain->uvs.size());
            for (const Vec2& uv : model.domain->uvs)
                values.push_back(0.1f + 0.9f * static_cast<float>(field.weight(uv[0], uv[1])));
            faceMesh_.setScalars(values);
            influenceKey_ = key;
        }
    }
}

EditorViews::EditorViews(EditorSession& session, SpeechPlayer& speech, Panels panels)
    : session_(session), speech_(speech), panels_(panels), shader_(shaderDirectory(), "mesh") {
    afterView_.background = beforeView_.background = mainView_.background;
}

void EditorViews::update(Panel active) {
    active_ = active;
    syncGpu();
    frameNewMeshes();
}

std::string EditorViews::statistics() const {
    if (subject_ == ViewSubject::Face && session_.document().face.cascade)
        return "Face: " + std::to_string(faceMesh_.vertexCount()) + " vertices, " +
               std::to_string(faceMesh_.triangleCount()) + " triangles, " +
               std::to_string(session_.document().face.parameters.size()) + " parameters";
    if (const VisemeSet* set = session_.visemes())
        return std::to_string(set->size()) + " visemes, " + std::to_string(set->vertexCount()) +
               " vertices, " + std::to_string(set->neutral.triangles.size()) + " triangles";
    return "No mesh";
}

void EditorViews::addProbe(nlohmann::json& summary) const {
    summary["face_view"] = faceViewProbe();
    summary["viseme_view_parts"] = {{"triangles", shownVisemeParts_.triangles}, {"q", shownVisemeParts_.q}};
    summary["wireframe"] = wireframe;
    // The surface switch and what the main view drew last frame with it.
    static const char* const kColourModes[] = {"surface", "scalar", "vertex colour", "material"};
    summary["surface"] = {{"choice", surface == SurfaceShading::Materials ? "materials" : "error colours"},
                          {"has_materials", hasMaterials()},
                          {"main_colours", kColourModes[static_cast<int>(shownMainColour_)]},
                          {"materials", materials_.summary()},
                          {"textures", materials_.materials.images.size()},
                          {"viseme_ranges", materials_.visemes.ranges.size()},
                          {"context_ranges", materials_.context.ranges.size()},
                          {"warnings", materials_.materials.warnings}};
    summary["view_labels"] = shownLabels_;
    // The shown camera and the matrices the views draw with (the tests compare them with
    // reference matrices), column-major like glm.
    const OrbitCamera& camera = shownCamera();
    const auto flat = [](const glm::mat4& m) {
        nlohmann::json values = nlohmann::json::array();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) values.push_back(m[c][r]);
        return values;
    };
    const Viewport& shown = active_ == Panel::Reduction ? beforeView_ : mainView_;
    summary["camera"] = {{"yaw", camera.yaw},
                         {"pitch", camera.pitch},
                         {"distance", camera.distance},
                         {"target", {camera.target.x, camera.target.y, camera.target.z}},
                         {"orthographic", camera.orthographic},
                         {"view", flat(camera.view())}};
    // What the views drew last frame; the comparison's two views with one camera.
    summary["drawn_camera"] = {
        {"view", flat(shown.camera.view())},
        {"projection", flat(shown.drawnProjection())},
        {"linked", beforeView_.camera.view() == afterView_.camera.view() &&
                       beforeView_.camera.orthographic == afterView_.camera.orthographic}};
}

} // namespace vl::ui
