// Reduction panel: target m, the optimal cost for every p with m marked, the groups, the compared
// viseme, and Say (panels/SaySection.cpp): speech on the full and the reduced set side by side.
#include "ui/panels/ReductionPanel.h"
#include "ui/UiScale.h"

#include "core/common/Error.h"
#include "core/inspect/DistanceUnits.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/panels/RestModelSection.h"
#include "ui/panels/SpeechPlayer.h"
#include "ui/widgets/Controls.h"
#include "ui/widgets/CostPlot.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vl::ui {

void ReductionPanel::draw() {
    const VisemeSet* set = session_.visemes();
    if (!set) {
        ImGui::TextWrapped("Load a viseme set first (Visemes panel or File > Load sample face).");
        return;
    }
    const int n = static_cast<int>(set->size());
    int m = session_.document().target;
    // With a free rest the rest viseme is no key: the slider stops at the keys the model allows.
    RestPose rest;
    session_.attempt("Rest viseme", [&] { rest = documentRestPose(session_.document()); });
    const int maxKeys = rest.free && rest.viseme >= 0 ? std::max(1, n - 1) : n;
    sectionHeader("Target");
    ImGui::SetNextItemWidth(scaled(-90.0f));
    if (ctl::SliderInt("groups m", &m, 1, maxKeys))
        session_.attempt("Target", [&] { session_.reduction().setTarget(m); });
    endEditOnRelease(session_);
    if (bool automatic = session_.reduction().automatic(); ctl::Checkbox("Re-run automatically", &automatic))
        session_.reduction().setAutomatic(automatic);
    ImGui::SameLine();
    if (ctl::Button("Run now")) session_.attempt("Reduction", [&] { session_.reduction().start(); });
    if (session_.reduction().running()) {
        ImGui::ProgressBar(static_cast<float>(session_.reduction().progress()), ImVec2(-80, 0),
                           "reducing...");
        ImGui::SameLine();
        if (ctl::Button("Cancel")) session_.reduction().stop();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Stops the search. A large set keeps the best groupings found so far, "
                              "each with its proven gap.");
        // Branch and bound: how far the proven lower bound has come towards the best grouping found.
        if (const auto bound = session_.reduction().bound()) {
            const double share = bound->bestFound > 0.0 ? bound->lowerBound / bound->bestFound : 1.0;
            char text[96];
            std::snprintf(text, sizeof text, "m = %d: bound %.0f %% of best found (gap %.1f %%)",
                          bound->groups, 100.0 * share, 100.0 * (1.0 - share));
            ImGui::ProgressBar(static_cast<float>(share), ImVec2(-80, 0), text);
        }
    }

    restModelSection(session_);
    constraints_.draw();

    const ReductionResult* curve = session_.reduction().curve();
    const Grouping* grouping = session_.reduction().grouping();
    if (!curve) {
        ImGui::TextDisabled(n > kMaxReductionVisemes ? "The reduction handles at most 64 visemes."
                                                     : "No result for the current inputs yet.");
        say_.draw();
        return;
    }

    sectionHeader(curve->restFree ? "Cost for p = 1..n keys (+ the free rest)" : "Cost for p = 1..n");
    ctl::Checkbox("log scale", &costView_.logarithmic);
    ImGui::SameLine();
    ctl::Checkbox("% of p = 1", &costView_.percent);
    ImGui::SameLine();
    static const char* const kUnits[] = {"auto", "m", "cm", "mm", "in"};
    ImGui::SetNextItemWidth(scaled(70.0f));
    ctl::Combo("model unit", &costView_.unit, kUnits, 5);
    helpMarker("The cost as a distance: the RMS weighted distance between each viseme and the merged "
               "shape of its group, averaged by frequency. 'auto' guesses the model's length unit from "
               "the size of the head (0.05 to 1 m across).");
    std::vector<double> weights;
    session_.attempt("Weights", [&] { weights = session_.weights().values(); });
    double weightSum = 0.0;
    for (const double w : weights) weightSum += w;
    const double millimetres = millimetresPerModelUnit();
    std::vector<double> distances;
    for (const Grouping& g : curve->curve)
        distances.push_back(rmsDistance(g.cost, 1.0, weightSum) * millimetres);
    if (costView_.percent && !distances.empty() && std::isfinite(distances[0]) && distances[0] > 0.0)
        for (double& d : distances) d = 100.0 * d / distances.front();
    CostPlotOptions options;
    options.logarithmic = costView_.logarithmic;
    options.unit = costView_.percent ? "%" : "mm";
    options.marked = m;
    if (curve->restFree) options.axis = "keys p (+ free rest)";
    if (const int picked = costPlot("##cost", distances, options, ImVec2(0, scaled(170.0f)));
        picked > 0 && picked != m)
        session_.attempt("Target", [&] {
            session_.reduction().setTarget(picked);
            session_.history().endEdit();
        });
    if (grouping && grouping->feasible()) {
        // What is proven about this grouping: optimal, or the best found with its gap to the bound.
        if (grouping->optimal)
            ImGui::TextColored(ImVec4(0.55f, 0.85f, 0.55f, 1.0f), "optimal (proved)");
        else
            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "best found, gap %.2f %% (lower bound %.4g)",
                               100.0 * grouping->gap(), grouping->lowerBound);
        ImGui::SameLine();
        helpMarker("Up to 20 visemes the reduction is exact. Larger sets run branch and bound for at most "
                   "10 s and show the best grouping found with its proven gap to the lower bound.");
    } else if (grouping) {
        ImGui::TextDisabled("m = %d: no grouping satisfies the constraints", m);
    }
    if (grouping && grouping->feasible()) {
        // Relative to the fewest keys that have a grouping (p = 1 may be ruled out by a pin).
        const Grouping* fewest = nullptr;
        for (const Grouping& g : curve->curve)
            if (!fewest && g.feasible() && std::isfinite(g.cost) && g.cost > 0.0) fewest = &g;
        const double rms = rmsDistance(grouping->cost, 1.0, weightSum) * millimetres;
        if (fewest)
            ImGui::Text("m = %d: RMS %.3g mm (%.1f%% of p = %zu); click the plot to choose m", m, rms,
                        100.0 * std::sqrt(grouping->cost / fewest->cost),
                        static_cast<std::size_t>(fewest - curve->curve.data()) + 1);
        else
            ImGui::Text("m = %d: RMS %.3g mm; click the plot to choose m", m, rms);
    }

    if (!grouping) {
        say_.draw();
        return;
    }
    sectionHeader("Groups");
    std::vector<double> frequencies;
    session_.attempt("Frequencies", [&] { frequencies = session_.frequencies().values(); });
    // A viseme no phoneme is spoken with weighs nothing: wherever it is merged costs 0, so its place
    // says nothing. Said here, where the groups are read.
    std::string unweighted;
    for (std::size_t i = 0; i < frequencies.size(); ++i)
        if (frequencies[i] == 0.0 && i < session_.visemeCount())
            unweighted += (unweighted.empty() ? "" : ", ") + session_.visemes()->visemes[i].name;
    if (!unweighted.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.4f, 1.0f));
        ImGui::TextWrapped("Frequency 0 %%: %s. No phoneme maps to it, so it costs nothing in any group and "
                           "its group is arbitrary; map phonemes to it (Frequencies) to weigh it.",
                           unweighted.c_str());
        ImGui::PopStyleColor();
        probe::recordArea(("Frequency 0 %: " + unweighted).c_str(), "warning");
    }
    if (ImGui::BeginTable("##groups", 3,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                              ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, scaled(24.0f));
        ImGui::TableSetupColumn("Members (click to compare)", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("Freq.", ImGuiTableColumnFlags_WidthFixed, scaled(52.0f));
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
                if (ctl::SmallButton(name.c_str())) session_.selectViseme(member);
                ImGui::PopID();
                if (static_cast<std::size_t>(member) < frequencies.size())
                    total += frequencies[static_cast<std::size_t>(member)];
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.1f%%", 100.0 * total);
        }
        // The resting visemes: no key, all weights 0 (the rest-free model).
        if (!grouping->rest.empty()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.6f, 0.75f, 0.9f, 1.0f), "rest");
            ImGui::TableNextColumn();
            double total = 0.0;
            for (std::size_t k = 0; k < grouping->rest.size(); ++k) {
                const int member = grouping->rest[k];
                if (k > 0) ImGui::SameLine(0.0f, 6.0f);
                ImGui::PushID(1000 + member);
                if (ctl::SmallButton(set->visemes[static_cast<std::size_t>(member)].name.c_str()))
                    session_.selectViseme(member);
                ImGui::PopID();
                if (static_cast<std::size_t>(member) < frequencies.size())
                    total += frequencies[static_cast<std::size_t>(member)];
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.1f%%", 100.0 * total);
        }
        ImGui::EndTable();
    }
    if (!grouping->rest.empty())
        ImGui::TextDisabled("Resting visemes have no key: the mouth stays at the neutral (all weights 0).");

    sectionHeader("Compare");
    const int selected = std::max(session_.selectedViseme(), 0);
    if (ctl::BeginCombo("viseme", set->visemes[static_cast<std::size_t>(selected)].name.c_str())) {
        for (int i = 0; i < n; ++i)
            if (ctl::Selectable(set->visemes[static_cast<std::size_t>(i)].name.c_str(), i == selected)) {
                session_.selectViseme(i);
                speech_.hide(); // the views compare this viseme again
            }
        ImGui::EndCombo();
    }
    if (const auto groupOf = grouping->groupOf(); static_cast<std::size_t>(selected) < groupOf.size() &&
                                                  groupOf[static_cast<std::size_t>(selected)] == kRestGroup) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(0.6f, 0.75f, 0.9f, 1.0f), "rests");
    }
    ImGui::TextUnformatted("Right view:");
    int display = static_cast<int>(mergedDisplay_);
    ImGui::SameLine();
    bool displayChanged = ctl::RadioButton("error colours", &display, 0);
    ImGui::SameLine();
    displayChanged |= ctl::RadioButton("skin", &display, 1);
    ImGui::SameLine();
    displayChanged |= ctl::RadioButton("overlay on original", &display, 2);
    if (displayChanged) mergedDisplay_ = static_cast<MergedDisplay>(display);
    helpMarker("Error colours: the weighted distance of each vertex to the merged shape. Skin: the merged "
               "shape as the face will look (in its materials when it has them). Overlay: the merged shape "
               "in skin with the original drawn over it as a cyan film; plain skin shows where the merged "
               "shape stands out in front.");

    say_.draw();
}

void ReductionPanel::setMergedDisplay(const std::string& name) {
    const char* const names[] = {"errors", "skin", "overlay"};
    for (int i = 0; i < 3; ++i)
        if (name == names[i]) {
            mergedDisplay_ = static_cast<MergedDisplay>(i);
            return;
        }
    throwInputError("--merged", "expected errors, skin or overlay, got '" + name + "'");
}

double ReductionPanel::millimetresPerModelUnit() const {
    static const LengthUnit kChosen[] = {LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Millimetre,
                                         LengthUnit::Inch};
    if (costView_.unit >= 1 && costView_.unit <= 4) return millimetresPer(kChosen[costView_.unit - 1]);
    const VisemeSet* set = session_.visemes();
    return set ? guessMillimetresPerUnit(set->neutral.positions) : millimetresPer(LengthUnit::Metre);
}

nlohmann::json ReductionPanel::reductionProbe() const {
    nlohmann::json out = {{"running", session_.reduction().running()}};
    if (const auto bound = session_.reduction().bound())
        out["bound"] = {{"groups", bound->groups}, {"lower", bound->lowerBound}, {"best", bound->bestFound}};
    if (const Grouping* grouping = session_.reduction().grouping(); grouping && grouping->feasible()) {
        out["current"] = {{"optimal", grouping->optimal}, {"gap", grouping->gap()}, {"cost", grouping->cost}};
        nlohmann::json resting = nlohmann::json::array();
        for (const int i : grouping->rest)
            resting.push_back(session_.visemes()->visemes[static_cast<std::size_t>(i)].name);
        out["current"]["resting"] = std::move(resting);
        out["current"]["keys"] = grouping->groups.size();
    }
    const Document& document = session_.document();
    nlohmann::json rest = {{"model", toString(document.rest)}, {"rest_viseme", document.restViseme}};
    try {
        const RestPose pose = documentRestPose(document);
        rest["free"] = pose.free;
        rest["resolved"] =
            pose.viseme >= 0 ? document.visemes->visemes[static_cast<std::size_t>(pose.viseme)].name : "";
    } catch (const InputError&) {
    }
    out["rest"] = std::move(rest);
    out["last_avatar_export"] = session_.files().lastAvatarExport();
    return out;
}

void ReductionPanel::addProbe(nlohmann::json& summary) const {
    summary["reduction"] = reductionProbe();
    summary["merged_display"] = static_cast<int>(mergedDisplay_);
    say_.addProbe(summary);
}

} // namespace vl::ui
