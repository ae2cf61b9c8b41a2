// The status bar: mesh statistics, progress of background work and the newest message, which
// expires (StatusLine) and wraps onto up to kMaxLines lines (the bar grows) instead of running
// off the window; the full history is in its tooltip.
#include "ui/EditorUi.h"
#include "ui/probe/GuiProbe.h"
#include "ui/widgets/JobProgress.h"

#include <imgui.h>

#include <algorithm>

namespace vl::ui {
namespace {

constexpr int kMaxLines = 3;
constexpr float kPadding = 8.0f;       // window padding, left and right
constexpr float kProgressGap = 8.0f;   // ImGui's item spacing before each progress bar
constexpr float kJobBarWidth = 260.0f; // a job's bar (label, percentage, time left), then its Cancel

int lineCount(const std::string& text, float width) {
    const float height = ImGui::CalcTextSize(text.c_str(), nullptr, false, width).y;
    return std::max(1, static_cast<int>(height / ImGui::GetTextLineHeight() + 0.5f));
}

// `text` as it fits in `maxLines` lines of `width` pixels: whole, or its longest prefix with "...".
std::string fitted(const std::string& text, float width, int maxLines) {
    if (lineCount(text, width) <= maxLines) return text;
    std::size_t lo = 0, hi = text.size();
    while (lo + 1 < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (lineCount(text.substr(0, mid) + "...", width) <= maxLines)
            lo = mid;
        else
            hi = mid;
    }
    return text.substr(0, lo) + "...";
}

} // namespace

float EditorUi::statusBarHeight() {
    const ImGuiIO& io = ImGui::GetIO();
    status_.stats = views_.statistics();
    // The message column starts after the statistics and the progress bars shown this frame.
    float x = kPadding + ImGui::CalcTextSize(status_.stats.c_str()).x;
    for (const bool running : {session_.files().saving(), session_.files().exporting()})
        if (running) x += kProgressGap + 200.0f;
    const float cancel = ImGui::CalcTextSize("Cancel").x + 2 * ImGui::GetStyle().FramePadding.x;
    x += static_cast<float>(session_.jobs().running().size()) * (2 * kProgressGap + kJobBarWidth + cancel);
    status_.messageX = std::max(x + 30.0f, io.DisplaySize.x * 0.3f);
    status_.wrapWidth = std::max(80.0f, io.DisplaySize.x - status_.messageX - kPadding);
    const auto& messages = session_.messages();
    status_.shown =
        statusLine_.update(messages.empty() ? nullptr : &messages.back(), ImGui::GetTime(), statusHovered_);
    status_.message =
        status_.shown ? fitted(status_.shown->text, status_.wrapWidth, kMaxLines) : std::string();
    status_.lines = status_.shown ? lineCount(status_.message, status_.wrapWidth) : 1;
    const float lines = static_cast<float>(std::max(1, status_.lines));
    return std::max(ImGui::GetFrameHeight(), lines * ImGui::GetTextLineHeightWithSpacing()) + 8.0f;
}

void EditorUi::statusBar(float height) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kPadding, 4));
    ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    statusHovered_ = ImGui::IsWindowHovered();
    ImGui::TextUnformatted(status_.stats.c_str());
    const float bar = ImGui::GetFrameHeight();
    // Every job that can be cancelled: its progress, time left and Cancel (one list, EditorSession).
    for (const SessionJobs::JobStatus& job : session_.jobs().running()) {
        ImGui::SameLine();
        const std::string cancel = "Cancel##job" + std::to_string(static_cast<int>(job.job));
        if (jobProgress(job.label, job.fraction, job.secondsLeft, cancel.c_str(), kJobBarWidth))
            session_.jobs().cancel(job.job);
    }
    // File work runs on workers too: an indeterminate bar each while it lasts.
    for (const auto& [running, label] :
         {std::pair{session_.files().saving(), session_.files().savingLabel()},
          std::pair{session_.files().exporting(), session_.files().exportingLabel()}}) {
        if (!running) continue;
        ImGui::SameLine();
        ImGui::ProgressBar(-1.0f * static_cast<float>(ImGui::GetTime()), ImVec2(200, bar), label.c_str());
    }
    if (status_.shown) {
        ImGui::SameLine(status_.messageX);
        const ImVec4 colour = status_.shown->kind == StatusMessage::Kind::Error
                                  ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f)
                                  : ImVec4(0.75f, 0.85f, 0.75f, 1.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::PushTextWrapPos(status_.messageX + status_.wrapWidth);
        ImGui::TextUnformatted(status_.message.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
        probe::recordArea(status_.shown->text.c_str(), "status");
    }
    if (statusHovered_ && !session_.messages().empty()) {
        // The history, newest last, wrapped to a readable width.
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(std::min(io.DisplaySize.x * 0.6f, 900.0f));
        const auto& all = session_.messages();
        for (std::size_t i = all.size() > 12 ? all.size() - 12 : 0; i < all.size(); ++i) {
            const bool error = all[i].kind == StatusMessage::Kind::Error;
            ImGui::PushStyleColor(ImGuiCol_Text, error ? ImVec4(1.0f, 0.55f, 0.5f, 1.0f)
                                                       : ImGui::GetStyleColorVec4(ImGuiCol_Text));
            ImGui::TextUnformatted(all[i].text.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    ImGui::End();
    ImGui::PopStyleVar();
}

} // namespace vl::ui
