// Weights panel: the metric's per-vertex weights (uniform, area, painted) and the painting brush.
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void EditorUi::weightsPanel() {
    const VisemeSet* set = session.visemes();
    if (!set) {
        ImGui::TextWrapped("Load a viseme set first.");
        return;
    }
    sectionHeader("Weight mode");
    int mode = static_cast<int>(session.document().weights.mode);
    bool changed = ctl::RadioButton("uniform (rho1)", &mode, 0);
    ImGui::SameLine();
    changed |= ctl::RadioButton("area (rho2)", &mode, 1);
    ImGui::SameLine();
    changed |= ctl::RadioButton("painted", &mode, 2);
    if (changed)
        session.attempt("Weight mode", [&] { session.setWeightMode(static_cast<WeightMode>(mode)); });
    ctl::Checkbox("Show weights as colours", &showWeightsColours_);
    ImGui::TextDisabled("Blue: low weight, red: the largest weight.");

    sectionHeader("Brush");
    ctl::Checkbox("Paint (left drag on the mesh; Alt + drag orbits)", &brush_.enabled);
    Vec3 lo, hi;
    bounds(set->neutral.positions, lo, hi);
    const float size = static_cast<float>((hi - lo).norm());
    if (brush_.radius <= 0.0f || brush_.radius > size) brush_.radius = 0.08f * size;
    ImGui::PushItemWidth(-110);
    ctl::SliderFloat("radius", &brush_.radius, 0.005f * size, 0.5f * size, "%.3f");
    ctl::SliderFloat("strength", &brush_.strength, 0.01f, 1.0f, "%.2f");
    const char* falloffs[] = {"linear", "smoothstep", "cosine", "gaussian"};
    ctl::Combo("falloff", &brush_.falloff, falloffs, 4);
    const char* modes[] = {"add", "subtract", "smooth"};
    ctl::Combo("operation", &brush_.mode, modes, 3);
    ImGui::PopItemWidth();
    ctl::Checkbox("Symmetric left/right", &brush_.symmetric);
    if (ctl::Button("Fill with 1"))
        session.attempt("Fill weights", [&] {
            session.setPaintedWeights(std::vector<double>(set->vertexCount(), 1.0), "Fill weights");
        });
    ImGui::SameLine();
    if (ctl::Button("Fill with 0.1"))
        session.attempt("Fill weights", [&] {
            session.setPaintedWeights(std::vector<double>(set->vertexCount(), 0.1), "Fill weights");
        });
    ImGui::TextDisabled("Each stroke is one undo step (Ctrl+Z).");
}

} // namespace vl::ui
