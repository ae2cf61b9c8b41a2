#include "ui/widgets/CostPlot.h"

#include "core/inspect/DistanceUnits.h"
#include "ui/widgets/Controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vl::ui {
namespace {

const ImU32 kAxis = IM_COL32(150, 150, 160, 255);
const ImU32 kGrid = IM_COL32(70, 72, 80, 255);
const ImU32 kLine = IM_COL32(110, 180, 255, 255);
const ImU32 kMark = IM_COL32(255, 190, 60, 255);
const ImU32 kPlotText = IM_COL32(210, 210, 220, 255);

std::string tickLabel(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace

int costPlot(const char* id, std::span<const double> values, const CostPlotOptions& options, ImVec2 size) {
    if (values.empty()) return 0;
    if (size.x <= 0.0f) size.x = ImGui::GetContentRegionAvail().x;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const int n = static_cast<int>(values.size());
    const bool clicked = ctl::InvisibleButton(id, size);
    const bool hovered = ImGui::IsItemHovered();
    ImDrawList* draw = ImGui::GetWindowDrawList();

    // Value range: a logarithmic axis starts at the decade below the smallest positive value.
    // Values under 1e-5 of the largest are rounding left of a zero (p = n merges nothing): they sit
    // on the axis's floor instead of stretching it over decades nobody reads.
    double hi = 0.0, smallest = 0.0;
    for (const double v : values)
        if (std::isfinite(v)) hi = std::max(hi, v); // a p the constraints rule out has no point
    const double zero = 1e-5 * hi;
    for (const double v : values)
        if (std::isfinite(v) && v > zero) smallest = smallest > 0.0 ? std::min(smallest, v) : v;
    const bool logarithmic = options.logarithmic && smallest > 0.0 && hi > smallest;
    const double lo = logarithmic ? std::pow(10.0, std::floor(std::log10(smallest))) : 0.0;
    if (logarithmic)
        hi = std::pow(10.0, std::ceil(std::log10(hi)));
    else if (hi <= 0.0)
        hi = 1.0;
    auto axisValue = [&](double v) { return logarithmic ? std::log10(std::max(v, lo)) : v; };
    const double a0 = axisValue(lo), a1 = axisValue(hi) > a0 ? axisValue(hi) : a0 + 1.0;

    // Frame: a title row above (the value unit over the value labels, the p axis's name on the
    // right: never on the curve, which starts at the top left), room for the value labels on the
    // left and the p labels below.
    const float left = origin.x + ImGui::CalcTextSize("0.000e-00").x * 0.75f + 8.0f;
    const float right = origin.x + size.x - 8.0f;
    const float top = origin.y + ImGui::GetTextLineHeight() + 6.0f;
    const float bottom = origin.y + size.y - ImGui::GetTextLineHeight() - 6.0f;
    auto xOf = [&](int p) {
        return n > 1 ? left + (right - left) * static_cast<float>(p - 1) / static_cast<float>(n - 1)
                     : 0.5f * (left + right);
    };
    auto yOf = [&](double v) {
        return bottom - (bottom - top) * static_cast<float>((axisValue(v) - a0) / (a1 - a0));
    };
    draw->AddRectFilled(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(24, 26, 31, 255));

    double ticks[24];
    const int yTicks = axisTicks(lo, hi, 4, logarithmic, ticks, 24);
    for (int i = 0; i < yTicks; ++i) {
        const float y = yOf(ticks[i]);
        draw->AddLine(ImVec2(left, y), ImVec2(right, y), kGrid);
        const std::string label = tickLabel(ticks[i]);
        const ImVec2 textSize = ImGui::CalcTextSize(label.c_str());
        draw->AddText(ImVec2(left - 4.0f - textSize.x, y - 0.5f * textSize.y), kPlotText, label.c_str());
    }
    const int xStep = std::max(1, (n + 9) / 10);
    for (int p = 1; p <= n; p += (p == 1 && xStep > 1 ? xStep - 1 : xStep)) {
        const float x = xOf(p);
        draw->AddLine(ImVec2(x, bottom), ImVec2(x, bottom + 3.0f), kAxis);
        const std::string label = std::to_string(p);
        const float width = ImGui::CalcTextSize(label.c_str()).x;
        draw->AddText(ImVec2(std::clamp(x - 0.5f * width, left, right - width), bottom + 3.0f), kPlotText,
                      label.c_str());
    }
    draw->AddLine(ImVec2(left, top), ImVec2(left, bottom), kAxis);
    draw->AddLine(ImVec2(left, bottom), ImVec2(right, bottom), kAxis);
    if (options.unit[0])
        draw->AddText(ImVec2(std::max(origin.x, left - 4.0f - ImGui::CalcTextSize(options.unit).x), origin.y),
                      kPlotText, options.unit);
    draw->AddText(ImVec2(right - ImGui::CalcTextSize(options.axis).x, origin.y), kPlotText, options.axis);

    // Runs of finite values are drawn as lines; a p without a grouping leaves a gap.
    std::vector<ImVec2> points, run;
    auto flush = [&] {
        if (run.size() > 1) draw->AddPolyline(run.data(), static_cast<int>(run.size()), kLine, 0, 2.0f);
        run.clear();
    };
    for (int p = 1; p <= n; ++p) {
        const double value = values[static_cast<std::size_t>(p - 1)];
        points.push_back(ImVec2(xOf(p), std::isfinite(value) ? yOf(value) : bottom));
        if (!std::isfinite(value)) {
            flush();
            continue;
        }
        run.push_back(points.back());
        draw->AddCircleFilled(points.back(), 2.5f, kLine);
    }
    flush();
    if (options.marked >= 1 && options.marked <= n) {
        const ImVec2 point = points[static_cast<std::size_t>(options.marked - 1)];
        draw->AddLine(ImVec2(point.x, top), ImVec2(point.x, bottom), kMark, 1.5f);
        draw->AddCircleFilled(point, 4.5f, kMark);
    }

    // The point under the cursor (nearest p), with its value; a click picks it.
    int under = 0;
    if (hovered && n > 0) {
        const float mouse = ImGui::GetIO().MousePos.x;
        under = n > 1
                    ? std::clamp(static_cast<int>(std::lround((mouse - left) / (right - left) * (n - 1))) + 1,
                                 1, n)
                    : 1;
        const double value = values[static_cast<std::size_t>(under - 1)];
        draw->AddCircle(points[static_cast<std::size_t>(under - 1)], 6.0f, kPlotText);
        ImGui::BeginTooltip();
        if (!std::isfinite(value))
            ImGui::Text("p = %d: no grouping satisfies the constraints", under);
        else if (value <= zero)
            ImGui::Text("p = %d: 0 %s", under, options.unit);
        else
            ImGui::Text("p = %d: %.4g %s", under, value, options.unit);
        if (std::isfinite(value) && values[0] > 0.0)
            ImGui::TextDisabled("%.1f%% of p = 1", 100.0 * value / values[0]);
        ImGui::EndTooltip();
    }
    return clicked ? under : 0;
}

} // namespace vl::ui
