// Visemes panel: the viseme list (frequency, group after reduction), preview on click, loading and
// importing meshes with the core's interpolability errors shown; under the list, authoring of the
// selected viseme (VisemeAuthoring.cpp).
#include "ui/panels/VisemesPanel.h"
#include "ui/UiScale.h"

#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/panels/SpeechPlayer.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace vl::ui {

void VisemesPanel::draw() {
    if (ctl::Button("Load sample face")) files_.loadSample();
    ImGui::SameLine();
    if (ctl::Button("Open viseme folder...")) files_.openVisemeFolder();

    ImGui::SameLine();
    if (ctl::Button("Import avatar...")) avatar_.openImport();

    if (!session_.visemes()) {
        ImGui::Spacing();
        ImGui::TextWrapped("No viseme set yet. Load the sample face, open a project (Ctrl+O), a folder of "
                           "interpolable meshes (OBJ/PLY/VRML) with one file named *neutral*, or an avatar "
                           "(glTF, GLB, VRM) with viseme morph targets.");
        return;
    }

    // An avatar's visemes are its morph targets (chosen by the pattern); other sets take meshes.
    if (session_.document().avatar.isSet())
        avatar_.visemesSection();
    else
        importSection();

    // The table shows the document as it is after those sections: a new target pattern replaced it
    // (another viseme count), and the set, its files, frequencies and grouping must be of one document.
    const Document& shown = session_.document();
    const VisemeSet* set = shown.visemes.get();
    if (!set) return;
    std::vector<double> frequencies;
    const bool frequenciesOk =
        session_.attempt("Frequencies", [&] { frequencies = session_.frequencies().values(); });
    const Grouping* grouping = session_.reduction().grouping();
    std::vector<int> groupOf(set->size(), -2); // -2: no grouping yet
    if (grouping && grouping->feasible()) groupOf = grouping->groupOf();

    sectionHeader("Visemes");
    ImGui::Text("%zu visemes, neutral: %s", set->size(),
                set->neutralSource.empty() ? "generated" : set->neutralSource.filename().string().c_str());
    if (ImGui::BeginTable("##visemes", 4,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_SizingStretchProp,
                          ImVec2(0, ImGui::GetContentRegionAvail().y -
                                        4.0f * ImGui::GetFrameHeightWithSpacing() -
                                        ImGui::GetStyle().ItemSpacing.y))) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("Name", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("Frequency", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("Group", ImGuiTableColumnFlags_WidthStretch, 0.8f);
        ImGui::TableSetupColumn("Source", ImGuiTableColumnFlags_WidthStretch, 1.6f);
        ImGui::TableHeadersRow();
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (ctl::Selectable("(neutral)", session_.selectedViseme() < 0, ImGuiSelectableFlags_SpanAllColumns))
            session_.selectViseme(-1);
        for (std::size_t i = 0; i < set->size(); ++i) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushID(static_cast<int>(i));
            ImGui::AlignTextToFramePadding();
            if (ctl::Selectable(set->visemes[i].name.c_str(),
                                session_.selectedViseme() == static_cast<int>(i),
                                ImGuiSelectableFlags_SpanAllColumns))
                session_.selectViseme(static_cast<int>(i));
            ImGui::TableNextColumn();
            if (frequenciesOk) {
                const float f = static_cast<float>(frequencies[i]);
                char text[32];
                std::snprintf(text, sizeof text, "%.1f%%", 100.0 * frequencies[i]);
                ImGui::ProgressBar(std::min(1.0f, f * 4.0f), ImVec2(-1, 0), text);
            }
            ImGui::TableNextColumn();
            if (groupOf[i] >= 0)
                ImGui::Text("%d", groupOf[i] + 1);
            else if (groupOf[i] == kRestGroup) // rest-free model: no key, the neutral
                ImGui::TextColored(ImVec4(0.6f, 0.75f, 0.9f, 1.0f), "rest");
            else
                ImGui::TextDisabled("-");
            ImGui::TableNextColumn();
            // An avatar's visemes are morph targets of its file (the set's neutral source).
            const std::filesystem::path& file = shown.visemeFiles.at(i);
            const std::filesystem::path& source =
                file.empty() && shown.avatar.isSet() ? set->neutralSource : file;
            ImGui::TextDisabled("%s", source.empty() ? "generated" : source.filename().string().c_str());
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    // An avatar's visemes are its morph targets, selected by the pattern: no per-viseme authoring.
    if (session_.document().avatar.isSet())
        ImGui::TextDisabled("Visemes of the avatar: the target pattern selects them.");
    else
        authoring_.draw();
    ImGui::SameLine();
    const auto& clip = session_.speech().clip();
    bool playAll = speech_.shown() && speech_.playing() && clip->loops && clip->sequence.empty();
    if (ctl::Checkbox("Play all", &playAll)) {
        if (playAll)
            speech_.playSequence({});
        else
            speech_.hide();
    }
    sculptor_.controls(); // one row: the sculpt brush and Blend...
}

void VisemesPanel::importSection() {
    sectionHeader("Import a viseme mesh");
    ImGui::SetNextItemWidth(scaled(150.0f));
    ctl::InputTextWithHint("##import-name", "name", &importName_);
    ImGui::SameLine();
    if (ctl::Button("Choose file...")) {
        if (importName_.empty()) {
            session_.error("Import: type a name for the new viseme first");
        } else {
            files_.dialog().open("Import viseme " + importName_, FileDialog::Mode::OpenFile,
                                 {".obj", ".ply", ".wrl", ".vrml"}, [this](const auto& path) {
                                     importError_.clear();
                                     if (session_.attempt("Import", [&] {
                                             session_.authoring().importViseme(importName_, path);
                                         }))
                                         importName_.clear();
                                     else
                                         importError_ = session_.messages().back().text;
                                 });
        }
    }
    ImGui::SameLine();
    if (ctl::Button("glTF...")) files_.importGltf("Import glTF morph targets");
    if (!importError_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", importError_.c_str());
        ImGui::PopStyleColor();
    }
    helpMarker("The mesh must have the neutral's vertex count and triangles (same order); otherwise the "
               "core's error names the first mismatch and nothing changes.");
}

} // namespace vl::ui
