// Weights panel: the metric's per-vertex weights (uniform, area, painted) and the paint tools: a
// brush (radius in screen pixels or % of the head, front faces only), a region fill and a box
// selection filled with a value. The weight under the cursor shows beside it in the view.
#include "ui/panels/WeightsPanel.h"
#include "ui/UiScale.h"

#include "core/paint/PaintRegions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <numeric>

namespace vl::ui {

void WeightsPanel::draw() {
    const VisemeSet* set = session_.visemes();
    if (!set) {
        ImGui::TextWrapped("Load a viseme set first.");
        return;
    }
    sectionHeader("Weight mode");
    int mode = static_cast<int>(session_.document().weights.mode);
    bool changed = ctl::RadioButton("uniform (rho1)", &mode, 0);
    ImGui::SameLine();
    changed |= ctl::RadioButton("area (rho2)", &mode, 1);
    ImGui::SameLine();
    changed |= ctl::RadioButton("painted", &mode, 2);
    if (changed)
        session_.attempt("Weight mode", [&] { session_.weights().setMode(static_cast<WeightMode>(mode)); });
    ctl::Checkbox("Show weights as colours", &showColours_);
    ImGui::TextDisabled("Blue: low weight, red: the largest weight.");
    if (painter_.tools.readout)
        ImGui::Text("Under the cursor: %.3g (vertex %u)", *painter_.tools.readout,
                    painter_.tools.readoutVertex);
    else
        ImGui::TextDisabled("Under the cursor: point at the mesh to read its weight.");

    sectionHeader("Paint");
    ctl::Checkbox("Paint (left drag on the mesh; Alt + drag orbits)", &painter_.brush.enabled);
    int tool = static_cast<int>(painter_.tools.tool);
    bool toolChanged = ctl::RadioButton("brush", &tool, 0);
    ImGui::SameLine();
    toolChanged |= ctl::RadioButton("fill region", &tool, 1);
    ImGui::SameLine();
    toolChanged |= ctl::RadioButton("select box", &tool, 2);
    if (toolChanged) {
        painter_.tools.tool = static_cast<PaintTool>(tool);
        painter_.brush.enabled = true; // choosing a tool means using it
    }
    ctl::Checkbox("Front faces only (nothing through to the back)", &painter_.brush.frontFacesOnly);
    helpMarker("The brush and the box reach only the surface you see: a big brush on the face leaves "
               "the back of the head, the inside of the mouth and the other lip alone, and a box selects "
               "no vertex hidden behind another part (the far lip, an ear behind the head).");

    ImGui::PushItemWidth(scaled(-130.0f));
    sectionHeader("Brush");
    const bool pixels = painter_.brush.radius.unit == RadiusUnit::ScreenPixels;
    float radius = static_cast<float>(painter_.brush.radius.value);
    if (ctl::SliderFloat("radius", &radius, pixels ? 2.0f : 0.5f, pixels ? 300.0f : 50.0f,
                         pixels ? "%.0f px" : "%.1f %% of head", ImGuiSliderFlags_Logarithmic))
        painter_.brush.radius.value = radius;
    int unit = static_cast<int>(painter_.brush.radius.unit);
    ImGui::TextUnformatted("radius in");
    ImGui::SameLine();
    bool unitChanged = ctl::RadioButton("screen pixels", &unit, 0);
    ImGui::SameLine();
    unitChanged |= ctl::RadioButton("% of head size", &unit, 1);
    if (unitChanged && unit != static_cast<int>(painter_.brush.radius.unit)) {
        // Keep the size the brush has on the face now (known once the cursor was over the mesh).
        const double headSize = painter_.surface().size();
        const double model = painter_.tools.modelRadius, perPixel = painter_.tools.unitsPerPixel;
        if (model > 0.0 && perPixel > 0.0 && headSize > 0.0)
            painter_.brush.radius.value = unit == 1 ? std::clamp(100.0 * model / headSize, 0.5, 50.0)
                                                    : std::clamp(model / perPixel, 2.0, 300.0);
        else
            painter_.brush.radius.value = unit == 1 ? 8.0 : 40.0;
        painter_.brush.radius.unit = static_cast<RadiusUnit>(unit);
    }
    // Weights are in [0, 1]: strength is the weight a dab adds at its centre (smooth: the share of the
    // way to the neighbours' mean), the fill value a weight, the tolerance a weight difference.
    ctl::SliderFloat("strength", &painter_.brush.strength, 0.01f, 1.0f, "%.2f weight per dab");
    const char* falloffs[] = {"linear", "smoothstep", "cosine", "gaussian"};
    ctl::Combo("falloff", &painter_.brush.falloff, falloffs, 4);
    const char* modes[] = {"add", "subtract", "smooth"};
    ctl::Combo("operation", &painter_.brush.mode, modes, 3);
    ctl::Checkbox("Symmetric left/right", &painter_.brush.symmetric);
    ImGui::TextDisabled("[ and ] shrink and grow the brush. Each stroke is one undo step.");

    sectionHeader("Fill");
    ctl::SliderFloat("fill value", &painter_.tools.fillValue, 0.0f, 1.0f, "weight %.2f");
    ctl::SliderFloat("region tolerance", &painter_.tools.fillTolerance, 0.0f, 1.0f, "+- %.2f weight");
    ImGui::PopItemWidth();
    if (ctl::Button("Fill all")) {
        std::vector<std::uint32_t> all(set->vertexCount());
        std::iota(all.begin(), all.end(), 0u);
        painter_.fill(all, "Fill all");
    }
    helpMarker("Fill region: a click on the mesh sets the connected vertices whose weight is within the "
               "tolerance of the clicked one (tolerance 1: the whole connected part).");

    sectionHeader("Selection");
    const std::size_t selected = painter_.tools.selection.size();
    ImGui::Text("%zu of %zu vertices selected", selected, set->vertexCount());
    helpMarker("Select box: drag a box on the mesh; Shift adds to the selection, Ctrl removes from it.");
    if (selected == 0) ImGui::BeginDisabled();
    if (ctl::Button("Fill selection")) painter_.fill(painter_.tools.selection, "Fill selection");
    if (selected == 0) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ctl::Button("Select all")) {
        painter_.tools.selection.resize(painter_.surface().vertexCount());
        std::iota(painter_.tools.selection.begin(), painter_.tools.selection.end(), 0u);
    }
    ImGui::SameLine();
    if (ctl::Button("Invert")) {
        std::vector<std::uint32_t> inverted;
        std::size_t next = 0;
        for (std::uint32_t v = 0; v < painter_.surface().vertexCount(); ++v) {
            if (next < painter_.tools.selection.size() && painter_.tools.selection[next] == v)
                ++next;
            else
                inverted.push_back(v);
        }
        painter_.tools.selection = std::move(inverted);
    }
    ImGui::SameLine();
    if (ctl::Button("Clear")) painter_.tools.selection.clear();
}

void WeightsPanel::addProbe(nlohmann::json& summary) const {
    summary["brush"] = painter_.brush.enabled;
    summary["paint"] = painter_.probe();
}

} // namespace vl::ui
