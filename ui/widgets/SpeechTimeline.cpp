#include "ui/widgets/SpeechTimeline.h"

#include "ui/widgets/Controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace vl::ui {

namespace {

constexpr float kLabelWidth = 92.0f; // row names on the left
constexpr float kAxisHeight = 18.0f;
constexpr float kRowHeight = 22.0f;
constexpr ImU32 kTimelineText = IM_COL32(225, 225, 232, 255);
constexpr ImU32 kDim = IM_COL32(150, 150, 160, 255);

// The same value gets the same colour in every row (a viseme in the full row and its merged key
// look alike); rest and silence are grey.
ImU32 colourOf(const std::string& value) {
    if (value == kRestCue || value == kSilencePhoneme) return IM_COL32(70, 70, 78, 255);
    const std::size_t hash = std::hash<std::string>{}(value);
    const float hue = static_cast<float>(hash % 360) / 360.0f;
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(hue, 0.45f, 0.62f, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, 1.0f));
}

// Tick spacing giving at most `maxTicks` ticks over `span` seconds: 0.05, 0.1, 0.25, 0.5, 1, 2, 5 ...
double tickStep(double span, int maxTicks) {
    static const double kSteps[] = {0.05, 0.1, 0.25, 0.5, 1, 2, 5, 10, 30, 60, 120, 300};
    for (const double step : kSteps)
        if (span / step <= maxTicks) return step;
    return 600;
}

template <class Item, class ValueOf>
void drawRow(ImDrawList* draw, const char* name, std::span<const Item> items, ValueOf valueOf, float y,
             float x0, float width, double duration, ImVec2 origin) {
    draw->AddText(ImVec2(origin.x + 6.0f, y + 3.0f), kDim, name);
    for (const Item& item : items) {
        const float a = x0 + static_cast<float>(item.start / duration) * width;
        const float b = x0 + static_cast<float>(item.end / duration) * width;
        const std::string& value = valueOf(item);
        draw->AddRectFilled(ImVec2(a, y + 1.0f), ImVec2(std::max(b - 1.0f, a + 1.0f), y + kRowHeight - 1.0f),
                            colourOf(value));
        const ImVec2 text = ImGui::CalcTextSize(value.c_str());
        if (text.x + 4.0f < b - a)
            draw->AddText(ImVec2(0.5f * (a + b - text.x), y + 0.5f * (kRowHeight - text.y)), kTimelineText,
                          value.c_str());
    }
}

} // namespace

std::optional<double> speechTimeline(const char* id, const SpeechTimelineData& data, ImVec2 size) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    size.x = std::max(size.x, kLabelWidth + 50.0f);
    size.y = std::max(size.y, kAxisHeight + 3 * kRowHeight + 40.0f);
    ctl::InvisibleButton(id, size);
    const bool active = ImGui::IsItemActive();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 28, 33, 255));
    const double duration = data.duration > 0 ? data.duration : 1.0;
    const float x0 = origin.x + kLabelWidth, width = size.x - kLabelWidth - 12.0f;
    const auto xOf = [&](double t) { return x0 + static_cast<float>(t / duration) * width; };

    // Time axis.
    const double step = tickStep(duration, std::max(2, static_cast<int>(width / 60.0f)));
    for (double t = 0.0; t <= duration + 1e-9; t += step) {
        const float x = xOf(t);
        draw->AddLine(ImVec2(x, origin.y + kAxisHeight - 5.0f), ImVec2(x, origin.y + size.y),
                      IM_COL32(60, 60, 68, 255));
        char text[32];
        std::snprintf(text, sizeof text, step < 1.0 ? "%.2f s" : "%.0f s", t);
        draw->AddText(ImVec2(x + 2.0f, origin.y + 1.0f), kDim, text);
    }
    float y = origin.y + kAxisHeight;
    const auto phonemeValue = [](const TimedPhoneme& p) -> const std::string& { return p.phoneme; };
    const auto cueValue = [](const Cue& c) -> const std::string& { return c.value; };
    drawRow(draw, "phonemes", data.phonemes, phonemeValue, y, x0, width, duration, origin);
    y += kRowHeight;
    drawRow(draw, "full set", data.fullCues, cueValue, y, x0, width, duration, origin);
    y += kRowHeight;
    drawRow(draw, data.reducedName.empty() ? "reduced" : data.reducedName.c_str(), data.reducedCues, cueValue,
            y, x0, width, duration, origin);
    y += kRowHeight + 4.0f;

    // The per-frame error under the rows, scaled to its maximum, with its mean dashed.
    const float plotTop = y + 14.0f, plotBottom = origin.y + size.y - 4.0f;
    draw->AddText(ImVec2(origin.x + 6.0f, y), kDim, "error");
    if (data.error.empty()) {
        draw->AddText(ImVec2(x0 + 4.0f, y), kDim, "(no reduction yet)");
    } else {
        const double max = *std::max_element(data.error.begin(), data.error.end());
        const double scale = max > 0 ? max : 1.0;
        const auto yOf = [&](double value) {
            return plotBottom - static_cast<float>(value / scale) * (plotBottom - plotTop);
        };
        for (std::size_t f = 1; f < data.error.size(); ++f) {
            const double t0 = std::min(double(f - 1) / data.errorFps, duration);
            const double t1 = std::min(double(f) / data.errorFps, duration);
            draw->AddQuadFilled(ImVec2(xOf(t0), plotBottom), ImVec2(xOf(t0), yOf(data.error[f - 1])),
                                ImVec2(xOf(t1), yOf(data.error[f])), ImVec2(xOf(t1), plotBottom),
                                IM_COL32(204, 80, 50, 110));
            draw->AddLine(ImVec2(xOf(t0), yOf(data.error[f - 1])), ImVec2(xOf(t1), yOf(data.error[f])),
                          IM_COL32(240, 120, 80, 255), 1.5f);
        }
        const float meanY = yOf(data.errorMean);
        for (float x = x0; x < x0 + width; x += 10.0f)
            draw->AddLine(ImVec2(x, meanY), ImVec2(std::min(x + 5.0f, x0 + width), meanY),
                          IM_COL32(240, 220, 120, 200));
        char text[96];
        std::snprintf(text, sizeof text, "max %.3g, mean %.3g (weighted squared distance)", max,
                      data.errorMean);
        draw->AddText(ImVec2(x0 + 4.0f, y), kDim, text);
    }
    draw->AddLine(ImVec2(x0, plotBottom), ImVec2(x0 + width, plotBottom), IM_COL32(90, 90, 100, 255));

    // Playhead.
    const float playhead = xOf(std::clamp(data.time, 0.0, duration));
    draw->AddLine(ImVec2(playhead, origin.y), ImVec2(playhead, origin.y + size.y),
                  IM_COL32(255, 255, 255, 230), 2.0f);
    char now[32];
    std::snprintf(now, sizeof now, "%.2f s", data.time);
    draw->AddText(ImVec2(origin.x + 6.0f, origin.y + 1.0f), kTimelineText, now);

    if (active) {
        const float x = ImGui::GetIO().MousePos.x;
        return std::clamp(double((x - x0) / width) * duration, 0.0, data.duration);
    }
    return std::nullopt;
}

} // namespace vl::ui
