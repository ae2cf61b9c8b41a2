#include "ui/widgets/SurfaceToggle.h"

#include "ui/UiScale.h"
#include "ui/widgets/Controls.h"

namespace vl::ui {
namespace {

constexpr const char* kLabels[] = {"Materials", "Error colours"};

float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

} // namespace

void surfaceToggleRect(ImVec2 topRight, ImVec2& min, ImVec2& max) {
    const float width = buttonWidth(kLabels[0]) + buttonWidth(kLabels[1]);
    const float margin = scaled(8.0f);
    min = ImVec2(topRight.x - width - margin, topRight.y + margin);
    max = ImVec2(topRight.x - margin, min.y + ImGui::GetFrameHeight());
}

bool surfaceToggle(ImVec2 topRight, SurfaceShading& shading) {
    ImVec2 min, max;
    surfaceToggleRect(topRight, min, max);
    ImGui::SetCursorScreenPos(min);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, 0.0f);
    bool changed = false;
    for (int i = 0; i < 2; ++i) {
        const bool current = static_cast<int>(shading) == i;
        // The current choice in the active button colour, the other one dimmed: a segmented switch.
        ImGui::PushStyleColor(ImGuiCol_Button, current ? ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive)
                                                       : ImVec4(0.12f, 0.12f, 0.14f, 0.85f));
        if (i > 0) ImGui::SameLine();
        if (ctl::Button(kLabels[i]) && !current) {
            shading = static_cast<SurfaceShading>(i);
            changed = true;
        }
        ImGui::PopStyleColor();
    }
    ImGui::PopStyleVar(2);
    return changed;
}

} // namespace vl::ui
