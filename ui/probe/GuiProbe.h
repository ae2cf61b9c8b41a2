#pragma once
// GUI probe: what a test that drives the real window with real input events needs to find the
// controls and to see what a click did. When enabled (editor option --probe FILE), every control
// drawn through the wrappers in Controls.h is recorded with its label and window rectangle, and at
// the end of each frame the list and a summary of the document are written to FILE (replaced by
// rename, so a reader never sees half a file). Disabled, recording is one branch per control.
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace vl::ui::probe {

void enable(const std::filesystem::path& file);
bool enabled();

// Where a control is about to be submitted: its window and ID, taken before the ImGui call because
// some controls change both (a selected tab pushes its own ID scope, an open combo begins a popup).
struct Before {
    const void* window = nullptr;
    ImGuiID id = 0;
};
Before before(const char* label);
// Records the control ImGui submitted last (call right after the widget). `kind` names the widget
// ("button", "slider", ...). While a combo or menu is open ImGui's last item is its popup, not the
// control: the control then keeps the rectangle of the frame before.
void recordItem(const Before& before, const char* label, const char* kind);
// Records the last item whatever its ID (images and other items without one, e.g. a 3D view).
void recordArea(const char* label, const char* kind);
// Records a rectangle drawn without an item of its own (a chart's label, say), in screen pixels.
void recordRect(const char* label, const char* kind, ImVec2 min, ImVec2 max);
// Every record says whether the whole item, label included, reaches past its window's clip
// rectangle sideways ("cut": a label the user cannot read in full).

// A test asks for a picture of the window by writing its path into FILE.screenshot; the editor
// takes the request (the file is removed) and saves the frame there (EditorApp).
std::optional<std::filesystem::path> takeScreenshotRequest();

// Writes the frame's controls and `document` (a summary the caller chooses) and starts a new list.
void endFrame(const nlohmann::json& document);

} // namespace vl::ui::probe
