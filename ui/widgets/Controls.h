#pragma once
// The ImGui controls the editor uses, recorded for GUI tests (GuiProbe.h): each wrapper calls the
// ImGui function of the same name with the same arguments and returns its result unchanged.
#include "ui/probe/GuiProbe.h"

#include <imgui.h>
#include <imgui_stdlib.h> // std::string overloads of InputText

#include <utility>

namespace vl::ui::ctl {

#define VL_PROBED_CONTROL(name, kind)                                                                        \
    template <class... Args> bool name(const char* label, Args&&... args) {                                  \
        const probe::Before before = probe::before(label);                                                   \
        const bool result = ImGui::name(label, std::forward<Args>(args)...);                                 \
        probe::recordItem(before, label, kind);                                                              \
        return result;                                                                                       \
    }

VL_PROBED_CONTROL(Button, "button")
VL_PROBED_CONTROL(SmallButton, "button")
VL_PROBED_CONTROL(InvisibleButton, "button")
VL_PROBED_CONTROL(Checkbox, "checkbox")
VL_PROBED_CONTROL(RadioButton, "radio")
VL_PROBED_CONTROL(SliderFloat, "slider")
VL_PROBED_CONTROL(SliderInt, "slider")
VL_PROBED_CONTROL(DragFloat, "drag")
VL_PROBED_CONTROL(DragFloat2, "drag")
VL_PROBED_CONTROL(DragInt, "drag")
VL_PROBED_CONTROL(InputText, "text")
VL_PROBED_CONTROL(InputTextWithHint, "text")
VL_PROBED_CONTROL(InputTextMultiline, "text")
VL_PROBED_CONTROL(InputInt, "text")
VL_PROBED_CONTROL(InputDouble, "text")
VL_PROBED_CONTROL(Selectable, "selectable")
VL_PROBED_CONTROL(MenuItem, "menuitem")
VL_PROBED_CONTROL(BeginTabItem, "tab")
VL_PROBED_CONTROL(Combo, "combo")
VL_PROBED_CONTROL(BeginCombo, "combo")
VL_PROBED_CONTROL(BeginMenu, "menu")
VL_PROBED_CONTROL(TreeNode, "tree")

#undef VL_PROBED_CONTROL

} // namespace vl::ui::ctl
