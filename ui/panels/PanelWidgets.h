#pragma once
// Small ImGui helpers shared by the panels.
#include "ui/probe/GuiProbe.h"
#include "ui/session/EditorSession.h"

#include <imgui.h>

namespace vl::ui {

// Call after a slider/drag: releasing it ends the undo step the drag was merging into.
inline void endEditOnRelease(EditorSession& session) {
    if (ImGui::IsItemDeactivated()) session.history().endEdit();
}

inline void sectionHeader(const char* text) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", text);
    ImGui::Separator();
}

// Grey explanatory text (beside a control after SameLine, or on its own line), wrapped at the
// panel's edge so it is never cut; recorded for the GUI tests' "nothing cut" check.
inline void noteText(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
    probe::recordArea(text, "text");
}

inline void helpMarker(const char* text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    probe::recordArea("(?)", "help"); // so the GUI tests see a marker pushed past the panel's side
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

} // namespace vl::ui
