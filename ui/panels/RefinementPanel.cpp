// Refinement panel: adaptive (RBMT) refinement of the deformable face.
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"

#include <imgui.h>

namespace vl::ui {

void EditorUi::refinementPanel() {
    sectionHeader("Adaptive refinement");
    ImGui::TextWrapped("Waiting for the core's adaptive mesh module (core/adaptive).");
}

} // namespace vl::ui
