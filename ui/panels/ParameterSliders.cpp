// The face's parameter sliders, shown by the Deformation and the Refinement panels.
#include "ui/panels/ParameterSliders.h"
#include "ui/UiScale.h"

#include "core/document/VisemeCommands.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void parameterSliders(EditorSession& session) {
    const FaceModel& model = session.document().face;
    const DeformationCascade& cascade = *model.cascade;
    if (ctl::BeginCombo("preset", "apply a viseme...", ImGuiComboFlags_HeightLargest)) {
        for (const VisemeParameters& preset : edit::facePresets(model))
            if (ctl::Selectable(preset.name.c_str()))
                session.attempt("Preset", [&] { session.face().applyVisemePreset(preset.name); });
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ctl::Button("Defaults"))
        session.attempt("Defaults",
                        [&] { session.face().setParameters(cascade.defaults(), "Reset parameters"); });
    for (std::size_t k = 0; k < cascade.parameters.size(); ++k) {
        const DeformParameter& p = cascade.parameters[k];
        float value = static_cast<float>(model.parameters[k]);
        ImGui::PushID(static_cast<int>(k));
        ImGui::SetNextItemWidth(scaled(-130.0f));
        if (ctl::SliderFloat(p.name.c_str(), &value, static_cast<float>(p.min), static_cast<float>(p.max),
                             "%.2f"))
            session.attempt("Parameter", [&] { session.face().setParameter(static_cast<int>(k), value); });
        endEditOnRelease(session);
        ImGui::PopID();
    }
}

} // namespace vl::ui
