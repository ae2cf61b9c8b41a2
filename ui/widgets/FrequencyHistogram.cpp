#include "ui/widgets/FrequencyHistogram.h"

#include "ui/probe/GuiProbe.h"
#include "ui/widgets/Controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

namespace vl::ui {

int labelRows(std::span<const float> labelWidths, float barWidth, float gap) {
    const int n = static_cast<int>(labelWidths.size());
    for (int rows = 1; rows < n; ++rows) {
        // On one row, names i and i + rows are rows bars apart (centre to centre).
        bool fits = true;
        for (int i = 0; i + rows < n && fits; ++i)
            fits = 0.5f * (labelWidths[static_cast<std::size_t>(i)] +
                           labelWidths[static_cast<std::size_t>(i + rows)]) +
                       gap <=
                   static_cast<float>(rows) * barWidth;
        if (fits) return rows;
    }
    return std::max(1, n);
}

void frequencyHistogram(const char* id, std::span<const double> values, std::span<const std::string> names,
                        float height) {
    const std::size_t n = std::min(values.size(), names.size());
    if (n == 0) return;
    const double sum = std::accumulate(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n), 0.0);
    const double largest = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n));
    const double top = sum > 0.0 ? 100.0 * largest / sum : 1.0; // the axis' top, in %

    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float lineHeight = ImGui::GetTextLineHeight();
    char text[64];
    std::snprintf(text, sizeof text, "%.1f %%", top);
    const float axisWidth = ImGui::CalcTextSize(text).x + 6.0f;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = std::max(60.0f, ImGui::GetContentRegionAvail().x);
    const float plotLeft = origin.x + axisWidth, plotRight = origin.x + width;
    const float barWidth = (plotRight - plotLeft) / static_cast<float>(n);
    std::vector<float> labelWidths(n);
    for (std::size_t i = 0; i < n; ++i) labelWidths[i] = ImGui::CalcTextSize(names[i].c_str()).x;
    const int rows = labelRows(labelWidths, barWidth, 6.0f);
    const float tick = rows > 1 ? 4.0f : 2.0f;
    const float total = height + tick + static_cast<float>(rows) * lineHeight + 2.0f;

    // One item for the whole chart (hover readout); the names are recorded for the GUI tests.
    ctl::InvisibleButton(id, ImVec2(width, total));
    const bool hovered = ImGui::IsItemHovered();
    const float bottom = origin.y + height;
    const ImU32 axis = IM_COL32(130, 135, 150, 255), label = ImGui::GetColorU32(ImGuiCol_Text);
    draw->AddLine(ImVec2(plotLeft, origin.y), ImVec2(plotLeft, bottom), axis);
    draw->AddLine(ImVec2(plotLeft, bottom), ImVec2(plotRight, bottom), axis);
    draw->AddText(ImVec2(origin.x, origin.y), label, text);
    draw->AddText(ImVec2(origin.x + axisWidth - ImGui::CalcTextSize("0").x - 6.0f, bottom - lineHeight),
                  label, "0");
    const int hoveredBar =
        hovered ? static_cast<int>(std::floor((ImGui::GetIO().MousePos.x - plotLeft) / barWidth)) : -1;
    for (std::size_t i = 0; i < n; ++i) {
        const float x0 = plotLeft + barWidth * static_cast<float>(i);
        const float centre = x0 + 0.5f * barWidth;
        const float share = sum > 0.0 ? static_cast<float>(100.0 * values[i] / sum / top) : 0.0f;
        const bool lit = static_cast<int>(i) == hoveredBar;
        draw->AddRectFilled(ImVec2(x0 + 1.0f, bottom - share * height), ImVec2(x0 + barWidth - 1.0f, bottom),
                            lit ? IM_COL32(250, 190, 90, 255) : IM_COL32(110, 160, 230, 255));
        const int row = static_cast<int>(i) % rows;
        const float y = bottom + tick + static_cast<float>(row) * lineHeight;
        if (rows > 1) draw->AddLine(ImVec2(centre, bottom), ImVec2(centre, y), axis);
        const ImVec2 at(
            std::max(origin.x, std::min(centre - 0.5f * labelWidths[i], plotRight - labelWidths[i])), y);
        draw->AddText(at, lit ? IM_COL32(250, 190, 90, 255) : label, names[i].c_str());
        probe::recordRect(names[i].c_str(), "histogram-label", at,
                          ImVec2(at.x + labelWidths[i], at.y + lineHeight));
    }
    if (hoveredBar >= 0 && hoveredBar < static_cast<int>(n)) {
        const auto i = static_cast<std::size_t>(hoveredBar);
        ImGui::SetTooltip("%s: %.2f %% of the speech (frequency %.4g)", names[i].c_str(),
                          sum > 0.0 ? 100.0 * values[i] / sum : 0.0, values[i]);
    }
}

} // namespace vl::ui
