#pragma once
// The "Materials | Error colours" switch drawn in a view's top right corner: two buttons side by
// side, the current one highlighted (probed as buttons "Materials" and "Error colours").
#include "ui/session/ViewMaterials.h"

#include <imgui.h>

namespace vl::ui {

// The rectangle the switch takes in a view whose top right corner is `topRight` (the view keeps
// clicks there from its camera: Viewport::excludeFromDrags).
void surfaceToggleRect(ImVec2 topRight, ImVec2& min, ImVec2& max);
// Draws it; true when a click changed `shading`.
bool surfaceToggle(ImVec2 topRight, SurfaceShading& shading);

} // namespace vl::ui
