#include "ui/widgets/JobProgress.h"

#include "ui/widgets/Controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vl::ui {

std::string jobProgressText(std::optional<double> fraction, std::optional<double> secondsLeft) {
    if (!fraction) return {};
    char text[64];
    const int percent = static_cast<int>(std::floor(100.0 * std::clamp(*fraction, 0.0, 1.0)));
    if (!secondsLeft) {
        std::snprintf(text, sizeof text, "%d %%", percent);
    } else if (*secondsLeft < 90.0) {
        std::snprintf(text, sizeof text, "%d %% - about %.0f s left", percent,
                      std::max(1.0, std::ceil(*secondsLeft)));
    } else {
        std::snprintf(text, sizeof text, "%d %% - about %.0f min left", percent,
                      std::ceil(*secondsLeft / 60.0));
    }
    return text;
}

bool jobProgress(const std::string& label, std::optional<double> fraction, std::optional<double> secondsLeft,
                 const char* cancelLabel, float width) {
    const std::string detail = jobProgressText(fraction, secondsLeft);
    const std::string text = detail.empty() ? label + "..." : label + " " + detail;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float button = ImGui::CalcTextSize("Cancel").x + 2 * style.FramePadding.x;
    const float bar = width < 0 ? ImGui::GetContentRegionAvail().x - button - style.ItemSpacing.x : width;
    // Negative fractions draw ImGui's moving stripes: a job without progress is still visibly alive.
    ImGui::ProgressBar(fraction ? static_cast<float>(*fraction)
                                : -1.0f * static_cast<float>(ImGui::GetTime()),
                       ImVec2(bar, 0), text.c_str());
    probe::recordArea(text.c_str(), "progress");
    ImGui::SameLine();
    return ctl::Button(cancelLabel);
}

} // namespace vl::ui
