// Reduction panel: target m, the optimal cost for every p with m marked, the groups, and playback
// of a phoneme sequence with the full and the reduced set (the views show both side by side).
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace vl::ui {

void EditorUi::reductionPanel() {
    const VisemeSet* set = session.visemes();
    if (!set) {
        ImGui::TextWrapped("Load a viseme set first (Visemes panel or File > Load sample face).");
        return;
    }
    const int n = static_cast<int>(set->size());
    int m = session.project().reduction.target;
    sectionHeader("Target");
    ImGui::SetNextItemWidth(-90);
    if (ctl::SliderInt("groups m", &m, 1, n)) session.attempt("Target", [&] { session.setTarget(m); });
    endEditOnRelease(session);
    ctl::Checkbox("Re-run automatically", &session.autoReduce);
    ImGui::SameLine();
    if (ctl::Button("Run now")) session.attempt("Reduction", [&] { session.startReduction(); });
    if (session.reductionRunning())
        ImGui::ProgressBar(static_cast<float>(session.reductionProgress()), ImVec2(-1, 0), "reducing...");

    const ReductionResult* curve = session.reductionCurve();
    const Grouping* grouping = session.currentGrouping();
    if (!curve) {
        ImGui::TextDisabled(n > kMaxExactVisemes ? "Exact reduction handles at most 20 visemes."
                                                 : "No result for the current inputs yet.");
        return;
    }

    sectionHeader("Optimal cost for p = 1..n");
    std::vector<float> costs;
    for (const Grouping& g : curve->curve) costs.push_back(static_cast<float>(g.cost));
    const float top = *std::max_element(costs.begin(), costs.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "m = %d: cost %.4g", m, grouping ? grouping->cost : 0.0);
    ImGui::PlotLines("##cost", costs.data(), static_cast<int>(costs.size()), 0, overlay, 0.0f, top * 1.05f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 120)); // 1.86 PlotLines takes no negative width
    {
        // Mark the chosen m on the curve (PlotLines spreads the points over the inner frame).
        const ImVec2 lo = ImGui::GetItemRectMin();
        const ImVec2 hi = ImGui::GetItemRectMax();
        const ImVec2 pad = ImGui::GetStyle().FramePadding;
        const float x0 = lo.x + pad.x, x1 = hi.x - pad.x;
        const float t =
            costs.size() > 1 ? static_cast<float>(m - 1) / static_cast<float>(costs.size() - 1) : 0.0f;
        const float x = x0 + t * (x1 - x0);
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddLine(ImVec2(x, lo.y + pad.y), ImVec2(x, hi.y - pad.y), IM_COL32(255, 190, 60, 220), 2.0f);
        const float y =
            hi.y - pad.y - (hi.y - lo.y - 2 * pad.y) * costs[static_cast<std::size_t>(m - 1)] / (top * 1.05f);
        draw->AddCircleFilled(ImVec2(x, y), 4.0f, IM_COL32(255, 190, 60, 255));
    }
    ImGui::TextDisabled("p = 1 (left) .. %d (right); cost 0 at p = n", n);

    if (!grouping) return;
    sectionHeader("Groups");
    std::vector<double> frequencies;
    session.attempt("Frequencies", [&] { frequencies = session.visemeFrequencies(); });
    if (ImGui::BeginTable("##groups", 3,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                              ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, 24.0f);
        ImGui::TableSetupColumn("Members (click to compare)", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("Freq.", ImGuiTableColumnFlags_WidthFixed, 52.0f);
        ImGui::TableHeadersRow();
        for (std::size_t g = 0; g < grouping->groups.size(); ++g) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%zu", g + 1);
            ImGui::TableNextColumn();
            double total = 0.0;
            bool first = true;
            for (int member : grouping->groups[g]) {
                const std::string& name = set->visemes[static_cast<std::size_t>(member)].name;
                // Wrap the member buttons at the column's edge.
                const float width =
                    ImGui::CalcTextSize(name.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x;
                if (!first && ImGui::GetItemRectMax().x + 6.0f + width <
                                  ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x -
                                      ImGui::GetStyle().ItemSpacing.x)
                    ImGui::SameLine(0.0f, 6.0f);
                first = false;
                ImGui::PushID(member);
                if (ctl::SmallButton(name.c_str())) session.selectedViseme = member;
                ImGui::PopID();
                if (static_cast<std::size_t>(member) < frequencies.size())
                    total += frequencies[static_cast<std::size_t>(member)];
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.1f%%", 100.0 * total);
        }
        ImGui::EndTable();
    }

    sectionHeader("Compare");
    const int selected = std::max(session.selectedViseme, 0);
    if (ctl::BeginCombo("viseme", set->visemes[static_cast<std::size_t>(selected)].name.c_str())) {
        for (int i = 0; i < n; ++i)
            if (ctl::Selectable(set->visemes[static_cast<std::size_t>(i)].name.c_str(), i == selected))
                session.selectedViseme = i;
        ImGui::EndCombo();
    }
    ImGui::TextDisabled("Right view: colour = weighted distance to the merged shape");

    sectionHeader("Playback");
    ImGui::SetNextItemWidth(-1);
    ctl::InputTextWithHint("##sequence", "phonemes or visemes, e.g. PP aa E RR (empty: all visemes)",
                           &playback_.sequence);
    float speed = static_cast<float>(playback_.secondsPerKey);
    ImGui::SetNextItemWidth(160);
    if (ctl::SliderFloat("s per key", &speed, 0.05f, 1.0f, "%.2f")) playback_.secondsPerKey = speed;
    ImGui::SameLine();
    if (ctl::Button(playback_.playing ? "Stop" : "Play", ImVec2(70, 0))) {
        playback_.playing = !playback_.playing;
        playback_.time = 0.0;
    }
}

} // namespace vl::ui
