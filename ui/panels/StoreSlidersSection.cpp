// Deformation panel, under the sliders: the sliders stored as a new viseme or into an existing one
// (the preset, and the mesh when the viseme set is the face's own), and the face's presets: apply
// one to the sliders, remove one. Apply, adjust, store: a preset is edited with the sliders.
#include "ui/panels/StoreSlidersSection.h"
#include "ui/UiScale.h"

#include "core/document/VisemeCommands.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace vl::ui {
namespace {

// "jaw_open 0.65, lip_pucker 0.55" (the values that differ from the defaults).
std::string presetSummary(const VisemeParameters& preset) {
    if (preset.values.empty()) return "(all defaults: the rest pose)";
    std::string text;
    for (const auto& [name, value] : preset.values) {
        char number[32];
        std::snprintf(number, sizeof number, " %.2f", value);
        text += (text.empty() ? "" : ", ") + name + number;
    }
    return text;
}

} // namespace

void StoreSlidersSection::draw() {
    const FaceModel& model = session_.document().face;
    const std::vector<VisemeParameters> presets = edit::facePresets(model);
    const bool madeByFace = session_.authoring().visemeSetMadeByFace();

    sectionHeader("Store the sliders as a viseme");
    if (madeByFace)
        ImGui::TextWrapped("The viseme set is this face's: storing also generates the viseme's mesh.");
    else
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.35f, 1.0f), "%s",
                           session_.visemes()
                               ? "The viseme set is not this face's: only the preset is stored."
                               : "No viseme set yet: the preset is stored (generate the set below).");
    ImGui::SetNextItemWidth(std::min(220.0f, ImGui::GetContentRegionAvail().x * 0.5f));
    const bool entered = ctl::InputTextWithHint("##new-viseme-name", "new viseme name", &newViseme_,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ctl::Button("Store as new viseme") || entered) {
        if (session_.attempt("Store sliders",
                             [&] { session_.authoring().storeSlidersAsNewViseme(newViseme_); })) {
            storeInto_ = newViseme_;
            newViseme_.clear();
        }
    }
    // Every preset, and the set's visemes when the face made them (their preset is created).
    std::vector<std::string> targets;
    for (const VisemeParameters& preset : presets) targets.push_back(preset.name);
    if (madeByFace)
        for (const Viseme& viseme : session_.visemes()->visemes)
            if (std::find(targets.begin(), targets.end(), viseme.name) == targets.end())
                targets.push_back(viseme.name);
    if (std::find(targets.begin(), targets.end(), storeInto_) == targets.end())
        storeInto_ = targets.empty() ? std::string() : targets.front();
    ImGui::SetNextItemWidth(std::min(220.0f, ImGui::GetContentRegionAvail().x * 0.5f));
    if (ctl::BeginCombo("##store-into", storeInto_.c_str(), ImGuiComboFlags_HeightLargest)) {
        for (const std::string& name : targets)
            if (ctl::Selectable(name.c_str(), name == storeInto_)) storeInto_ = name;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ctl::Button("Store into viseme"))
        session_.attempt("Store sliders", [&] { session_.authoring().storeSlidersInViseme(storeInto_); });
    helpMarker("Apply a preset below, adjust the sliders, then store them into it: its parameters (and its "
               "mesh, when the set is the face's) are replaced. One undo step each.");

    sectionHeader("Viseme presets");
    if (ImGui::BeginTable("##presets", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("Preset", ImGuiTableColumnFlags_WidthFixed, scaled(90.0f));
        ImGui::TableSetupColumn("Parameters (others at their default)", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("##remove", ImGuiTableColumnFlags_WidthFixed, scaled(20.0f));
        ImGui::TableHeadersRow();
        for (const VisemeParameters& preset : presets) {
            ImGui::PushID(preset.name.c_str());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const std::string apply = preset.name + "##apply-" + preset.name;
            if (ctl::Button(apply.c_str(), ImVec2(-1, 0)))
                if (session_.attempt("Preset", [&] { session_.face().applyVisemePreset(preset.name); }))
                    storeInto_ = preset.name;
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextWrapped("%s", presetSummary(preset).c_str());
            ImGui::TableNextColumn();
            const std::string remove = "x##remove-" + preset.name;
            if (ctl::SmallButton(remove.c_str()))
                session_.attempt("Remove preset", [&] { session_.authoring().removePreset(preset.name); });
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
}

} // namespace vl::ui
