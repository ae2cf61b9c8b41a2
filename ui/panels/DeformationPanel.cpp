// Deformation panel: one live slider per cascade parameter, viseme presets (stored from the sliders
// in StoreSlidersSection.cpp), the base geometry (retargeting) and editing of the analytic influence
// regions, drawn on the face and in (u,v).
#include "ui/panels/DeformationPanel.h"
#include "ui/UiScale.h"

#include "core/deform/Visemes.h"
#include "core/document/VisemeCommands.h"
#include "core/project/BuiltinGeometry.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/panels/ParameterSliders.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace vl::ui {
namespace {

constexpr Falloff kFalloffs[] = {Falloff::Linear, Falloff::Smoothstep, Falloff::Cosine, Falloff::Gaussian};

bool dragVec2(const char* label, Vec2& v, float speed, float lo, float hi) {
    float values[2] = {static_cast<float>(v[0]), static_cast<float>(v[1])};
    if (!ctl::DragFloat2(label, values, speed, lo, hi, "%.3f")) return false;
    v = Vec2(values[0], values[1]);
    return true;
}

} // namespace

void DeformationPanel::draw() {
    const FaceModel& model = session_.document().face;
    if (!model.cascade) {
        ImGui::TextWrapped(
            "The deformable face is a cascade of vector fields on the (u,v) square: a base geometry "
            "plus one field per muscle parameter.");
        if (ctl::Button("Load bundled face")) session_.attempt("Load face", [&] { session_.face().load(); });
        ImGui::SameLine();
        if (ctl::Button("Use my mesh...")) ownFace_.open();
        if (ownFace_.active()) ownFace_.draw();
        return;
    }
    if (ownFace_.active()) {
        ownFace_.draw();
        return;
    }
    const DeformationCascade& cascade = *model.cascade;

    sectionHeader("Base geometry (retargeting)");
    // A face built from the user's mesh carries the bundled fields rotated and scaled for it: going
    // back means loading the bundled face again, not retargeting these fields.
    if (ownFaceCascade_ != model.cascade) {
        ownFaceCascade_ = model.cascade;
        ownFaceLoaded_ = !builtinIndividualOf(cascade);
    }
    if (ownFaceLoaded_) {
        ImGui::TextWrapped("Your face: %s", cascade.name.c_str());
        if (ctl::Button("Back to the bundled face"))
            session_.attempt("Load face", [&] { session_.face().load(); });
    } else {
        int individual = static_cast<int>(model.individual);
        bool retargeted = ctl::RadioButton("bundled", &individual, 0);
        ImGui::SameLine();
        retargeted |= ctl::RadioButton("retarget (2nd individual)", &individual, 1);
        if (retargeted)
            session_.attempt("Retarget", [&] {
                session_.face().setIndividual(static_cast<face::Individual>(individual));
            });
    }
    ImGui::SameLine();
    if (ctl::Button("Use my mesh...")) ownFace_.open();

    sectionHeader("Parameters");
    parameterSliders(session_);
    storeSliders_.draw();

    sectionHeader("Fields");
    ctl::Checkbox("Show influence on the face", &showInfluence_);
    if (ImGui::BeginListBox("##stages", ImVec2(-1, 6.5f * ImGui::GetTextLineHeightWithSpacing()))) {
        for (std::size_t s = 0; s < cascade.stages.size(); ++s) {
            const DeformationStage& stage = cascade.stages[s];
            for (std::size_t r = 0; r < stage.field.influences.size(); ++r) {
                std::string label =
                    stage.name + (stage.field.influences.size() > 1 ? " #" + std::to_string(r + 1) : "");
                if (stage.kind == StageKind::AddVector)
                    label += "  <- " + cascade.parameters[stage.parameter].name;
                const bool selected =
                    selected_.stage == static_cast<int>(s) && selected_.influence == static_cast<int>(r);
                ImGui::PushID(static_cast<int>(s * 1000 + r));
                if (ctl::Selectable(label.c_str(), selected)) {
                    selected_.stage = static_cast<int>(s);
                    selected_.influence = static_cast<int>(r);
                }
                ImGui::PopID();
            }
        }
        ImGui::EndListBox();
    }
    if (selected_.stage < 0 || selected_.stage >= static_cast<int>(cascade.stages.size())) {
        ImGui::TextDisabled("Select an analytic field to edit it.");
    } else {
        const auto& influences = cascade.stages[static_cast<std::size_t>(selected_.stage)].field.influences;
        if (selected_.influence < static_cast<int>(influences.size())) {
            InfluenceField field = influences[static_cast<std::size_t>(selected_.influence)];
            bool changed = false;
            ImGui::PushItemWidth(scaled(-110.0f));
            changed |= dragVec2("centre (u,v)", field.centre, 0.002f, 0.0f, 1.0f);
            endEditOnRelease(session_);
            changed |= dragVec2("radii", field.radii, 0.002f, 0.005f, 1.0f);
            endEditOnRelease(session_);
            changed |= dragVec2("plateau", field.plateau, 0.002f, 0.0f, 1.0f);
            endEditOnRelease(session_);
            float degrees = static_cast<float>(field.rotation * 180.0 / M_PI);
            if (ctl::SliderFloat("rotation", &degrees, -180.0f, 180.0f, "%.0f deg")) {
                field.rotation = degrees * M_PI / 180.0;
                changed = true;
            }
            endEditOnRelease(session_);
            float direction[3] = {static_cast<float>(field.direction[0]),
                                  static_cast<float>(field.direction[1]),
                                  static_cast<float>(field.direction[2])};
            if (ImGui::DragFloat3("direction", direction, 0.01f, -1.0f, 1.0f, "%.2f")) {
                field.direction = Vec3(direction[0], direction[1], direction[2]);
                changed = true;
            }
            endEditOnRelease(session_);
            float magnitude = static_cast<float>(field.magnitude);
            if (ctl::DragFloat("magnitude", &magnitude, 0.01f, -10.0f, 10.0f, "%.3f")) {
                field.magnitude = magnitude;
                changed = true;
            }
            endEditOnRelease(session_);
            int falloff = static_cast<int>(field.falloff);
            const std::string current(toString(field.falloff));
            if (ctl::BeginCombo("falloff", current.c_str())) {
                for (Falloff kind : kFalloffs)
                    if (ctl::Selectable(std::string(toString(kind)).c_str(),
                                        static_cast<int>(kind) == falloff)) {
                        field.falloff = kind;
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            ImGui::PopItemWidth();
            if (changed)
                session_.attempt("Field", [&] {
                    session_.face().setInfluence(selected_.stage, selected_.influence, field);
                });
            ImGui::TextDisabled("The region is drawn on the face and in the (u,v) inset of the view.");
        }
    }

    sectionHeader("Visemes");
    ImGui::TextWrapped("Generate the face's viseme set (one mesh per viseme preset) to reduce it.");
    if (ctl::Button("Generate viseme set from face"))
        files_.guarded(
            [this] { session_.attempt("Generate visemes", [&] { session_.face().generateVisemes(); }); });
}

DeformationPanel::InsetPlace DeformationPanel::insetPlace(ImVec2 viewMin, ImVec2 viewMax) const {
    InsetPlace place;
    const float margin = 16.0f;
    place.titleHeight = ImGui::GetTextLineHeight() + 6.0f;
    place.side = std::max(40.0f, std::min(300.0f, 0.35f * (viewMax.y - viewMin.y)));
    const ImVec2 extent(place.side, place.side + place.titleHeight);
    // The default place is the lower right corner; the user's offset moves it, within the view.
    const ImVec2 home(viewMax.x - margin - extent.x, viewMax.y - margin - extent.y);
    place.offsetMin = ImVec2(viewMin.x - home.x, viewMin.y - home.y);
    place.offsetMax = ImVec2(std::max(place.offsetMin.x, viewMax.x - extent.x - home.x),
                             std::max(place.offsetMin.y, viewMax.y - extent.y - home.y));
    place.min = ImVec2(home.x + std::clamp(insetOffset_.x, place.offsetMin.x, place.offsetMax.x),
                       home.y + std::clamp(insetOffset_.y, place.offsetMin.y, place.offsetMax.y));
    place.max = ImVec2(place.min.x + extent.x, place.min.y + extent.y);
    return place;
}

void DeformationPanel::inset(const InsetPlace& place) {
    ImGui::SetCursorScreenPos(place.min);
    ctl::InvisibleButton("##uv-title", ImVec2(place.side, place.titleHeight));
    const bool moving = ImGui::IsItemActive();
    if (moving) {
        // Kept inside the view as it moves, so a drag past the edge does not have to be undone.
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        insetOffset_ = ImVec2(std::clamp(insetOffset_.x + delta.x, place.offsetMin.x, place.offsetMax.x),
                              std::clamp(insetOffset_.y + delta.y, place.offsetMin.y, place.offsetMax.y));
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(place.min, ImVec2(place.max.x, place.min.y + place.titleHeight),
                        ImGui::IsItemHovered() || moving ? IM_COL32(70, 76, 92, 255)
                                                         : IM_COL32(52, 56, 68, 255));
    draw->PushClipRect(place.min, ImVec2(place.max.x, place.min.y + place.titleHeight), true);
    draw->AddText(ImVec2(place.min.x + 6, place.min.y + 3), IM_COL32(220, 220, 230, 255),
                  "(u,v)   drag this bar to move it");
    draw->PopClipRect();
    ImGui::SetCursorScreenPos(ImVec2(place.min.x, place.min.y + place.titleHeight));
    uvView(place.side);
}

void DeformationPanel::uvView(float side) {
    const int stage = selected_.stage, influence = selected_.influence;
    const FaceModel& model = session_.document().face;
    const InfluenceField& field = model.cascade->stages[static_cast<std::size_t>(stage)]
                                      .field.influences[static_cast<std::size_t>(influence)];
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ctl::InvisibleButton("##uv", ImVec2(side, side));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRect(ImVec2(origin.x - 1, origin.y - 1), ImVec2(origin.x + side + 1, origin.y + side + 1),
                  IM_COL32(120, 125, 140, 255));
    // v grows upwards in the view, as on the face.
    auto toScreen = [&](double u, double v) {
        return ImVec2(origin.x + static_cast<float>(u) * side, origin.y + static_cast<float>(1.0 - v) * side);
    };
    draw->AddRectFilled(origin, ImVec2(origin.x + side, origin.y + side), IM_COL32(30, 32, 38, 255));
    // Everything of the domain stays inside its frame: an ellipse reaching past u or v = 0..1 is cut
    // at the frame, not drawn over the face.
    draw->PushClipRect(origin, ImVec2(origin.x + side, origin.y + side), true);
    const auto& uvs = model.domain->uvs;
    for (const Triangle& t : model.domain->triangles)
        for (int a = 0; a < 3; ++a) {
            const Vec2& p = uvs[t[static_cast<std::size_t>(a)]];
            const Vec2& q = uvs[t[static_cast<std::size_t>((a + 1) % 3)]];
            if (t[static_cast<std::size_t>(a)] < t[static_cast<std::size_t>((a + 1) % 3)])
                draw->AddLine(toScreen(p[0], p[1]), toScreen(q[0], q[1]), IM_COL32(80, 84, 96, 255));
        }
    auto ellipse = [&](const Vec2& radii, ImU32 colour) {
        constexpr int kSegments = 64;
        ImVec2 points[kSegments];
        const double c = std::cos(field.rotation), s = std::sin(field.rotation);
        for (int i = 0; i < kSegments; ++i) {
            const double a = 2.0 * M_PI * i / kSegments;
            const double x = radii[0] * std::cos(a), y = radii[1] * std::sin(a);
            points[i] = toScreen(field.centre[0] + c * x - s * y, field.centre[1] + s * x + c * y);
        }
        draw->AddPolyline(points, kSegments, colour, ImDrawFlags_Closed, 2.0f);
    };
    ellipse(field.radii, IM_COL32(255, 190, 60, 255));
    if (field.plateau[0] > 0.0) ellipse(field.plateau, IM_COL32(255, 120, 60, 200));
    const ImVec2 centre = toScreen(field.centre[0], field.centre[1]);
    draw->AddCircleFilled(centre, 5.0f, IM_COL32(255, 220, 120, 255));
    draw->PopClipRect();
    // Dragging in the view moves the centre.
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        InfluenceField moved = field;
        moved.centre = Vec2(std::clamp((mouse.x - origin.x) / side, 0.0f, 1.0f),
                            std::clamp(1.0f - (mouse.y - origin.y) / side, 0.0f, 1.0f));
        session_.attempt("Field", [&] { session_.face().setInfluence(stage, influence, moved); });
    }
    if (ImGui::IsItemDeactivated()) session_.history().endEdit();
}

bool DeformationPanel::selectField(const std::string& stageName) {
    const auto& cascade = session_.document().face.cascade;
    if (!cascade) return false;
    for (std::size_t s = 0; s < cascade->stages.size(); ++s)
        if (cascade->stages[s].name == stageName && !cascade->stages[s].field.influences.empty()) {
            selected_.stage = static_cast<int>(s);
            selected_.influence = 0;
            return true;
        }
    return false;
}

void DeformationPanel::addProbe(nlohmann::json& summary) const {
    summary["own_face_step"] = ownFace_.probe();
    summary["landmark_handles"] = handles_.probe();
    summary["uv_inset_offset"] = {insetOffset_.x, insetOffset_.y};
}

} // namespace vl::ui
