// Frequencies panel: the phoneme -> viseme map editor. A map starts from a bundled map, a map file or
// one row per phoneme; each of its visemes is assigned to a viseme of the set (suggested by name), so
// visemes with any names (e.g. the ICT FaceKit mouth shapes) get phoneme-derived frequencies. Then
// one row per phoneme (frequency, share, viseme) and one row per viseme (its phonemes, their share,
// move them all); visemes no phoneme maps to are listed in colour.
#include "ui/panels/PhonemeMapEditor.h"
#include "core/common/Error.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "ui/UiScale.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/session/BundledAssets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace vl::ui {
namespace {

const ImVec4 kWarning(1.0f, 0.7f, 0.3f, 1.0f);
constexpr const char* kPerPhoneme = "per-phoneme";

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
    return text;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : " ") + name;
    return text;
}

// A combo over the set's viseme names; `current` empty shows `none`. True when a name was chosen.
bool visemeNameCombo(const char* label, const VisemeSet& set, std::string& current, const char* none) {
    bool chosen = false;
    if (ctl::BeginCombo(label, current.empty() ? none : current.c_str(), ImGuiComboFlags_HeightLargest)) {
        for (const Viseme& viseme : set.visemes)
            if (ctl::Selectable(viseme.name.c_str(), viseme.name == current)) {
                current = viseme.name;
                chosen = true;
            }
        ImGui::EndCombo();
    }
    return chosen;
}

} // namespace

void PhonemeMapEditor::restVisemeRow() {
    ImGui::SetNextItemWidth(scaled(120.0f));
    ctl::InputTextWithHint("##rest-name", "name", &restName_);
    ImGui::SameLine();
    if (ctl::Button("Add rest viseme") &&
        session_.attempt("Rest viseme",
                         [&] {
                             // An avatar's rest is its base mesh, carried by no target (AvatarRest.h).
                             if (session_.document().avatar.isSet())
                                 session_.authoring().addAvatarRestViseme(restName_);
                             else
                                 session_.authoring().addRestViseme(restName_);
                         }) &&
        mapStart_.open) {
        // A map being assigned: rows still unassigned take the new viseme when it fits their name.
        const auto suggested =
            edit::suggestMapAssignment(session_.document(), mapStart_.table, mapStart_.map);
        for (edit::MapAssignment& row : mapStart_.rows)
            for (const edit::MapAssignment& suggestion : suggested)
                if (row.to.empty() && suggestion.from == row.from) row.to = suggestion.to;
    }
    helpMarker("A viseme with the neutral's shape, for the pause 'sil' when your set has no mouth at rest.");
}

void PhonemeMapEditor::openMapStart(std::string title, const PhonemeVisemeMap& map) {
    mapStart_.table = session_.frequencies().startingPhonemeTable();
    mapStart_.map = map;
    mapStart_.rows = edit::suggestMapAssignment(session_.document(), mapStart_.table, map);
    mapStart_.title = std::move(title);
    mapStart_.open = true;
}

void PhonemeMapEditor::startFrom(const std::string& id) {
    if (!session_.visemes()) throwInputError("phoneme map", "load a viseme set first");
    if (id == kPerPhoneme) {
        openMapStart("one viseme per phoneme",
                     edit::phonemePerVisemeMap(session_.frequencies().startingPhonemeTable()));
        return;
    }
    for (const BundledPhonemeMap& map : bundledPhonemeMaps(assetsDirectory()))
        if (map.id == id) return openMapStart(map.title, loadPhonemeMapFile(map.file));
    throwInputError("phoneme map", "no bundled map '" + id + "' (or " + kPerPhoneme + ")");
}

void PhonemeMapEditor::startSection() {
    sectionHeader("Phoneme map");
    ImGui::SetNextItemWidth(std::min(260.0f, ImGui::GetContentRegionAvail().x * 0.55f));
    if (ctl::BeginCombo("##map-start", "Start a map from...", ImGuiComboFlags_HeightLargest)) {
        for (const BundledPhonemeMap& map : bundledPhonemeMaps(assetsDirectory()))
            if (ctl::Selectable(map.title.c_str()))
                session_.attempt("Phoneme map", [&] { startFrom(map.id); });
        if (ctl::Selectable("One viseme per phoneme (ARPAbet)"))
            session_.attempt("Phoneme map", [&] { startFrom(kPerPhoneme); });
        if (ctl::Selectable("A map file..."))
            files_.dialog().open("Phoneme map file (CSV phoneme,viseme or JSON)", FileDialog::Mode::OpenFile,
                                 {".csv", ".json"}, [this](const auto& path) {
                                     session_.attempt("Phoneme map", [&] {
                                         openMapStart(path.filename().string(), loadPhonemeMapFile(path));
                                     });
                                 });
        ImGui::EndCombo();
    }
    helpMarker(
        "The phoneme table is the current one (or the bundled American English table). Each viseme "
        "of the map you start from is assigned to one of yours; then edit the map phoneme by phoneme.");
    const bool phonemeBased = session_.document().frequencies.isPhonemeBased();
    if (!phonemeBased) ImGui::BeginDisabled();
    if (ctl::Button("Save map...", ImVec2(0, 0)))
        files_.dialog().open(
            "Save phoneme map", FileDialog::Mode::SaveFile, {".csv", ".json"},
            [this](const auto& path) {
                if (session_.attempt("Save map", [&] { session_.frequencies().savePhonemeMap(path); }))
                    session_.info("Saved " + path.string());
            },
            "phoneme-map.csv");
    ImGui::SameLine();
    if (ctl::Button("Use direct frequencies"))
        session_.attempt("Direct frequencies", [&] { session_.frequencies().useDirectFrequencies(); });
    if (!phonemeBased) ImGui::EndDisabled();

    if (!mapStart_.open) return;
    const VisemeSet& set = *session_.visemes();
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "Assign the visemes of %s to yours",
                       mapStart_.title.c_str());
    ImGui::PushID("assigning"); // the editor below may draw its own row in the frame this opens
    restVisemeRow();
    ImGui::PopID();
    int unassigned = 0;
    if (ImGui::BeginTable("##map-assignment", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("Map's viseme", ImGuiTableColumnFlags_WidthFixed, scaled(95.0f));
        ImGui::TableSetupColumn("Phonemes", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("Share", ImGuiTableColumnFlags_WidthFixed, scaled(55.0f));
        ImGui::TableSetupColumn("Your viseme", ImGuiTableColumnFlags_WidthFixed, scaled(130.0f));
        ImGui::TableHeadersRow();
        for (edit::MapAssignment& row : mapStart_.rows) {
            ImGui::PushID(row.from.c_str());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(row.from.c_str());
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextWrapped("%s", joined(row.phonemes).c_str());
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(percent(row.share).c_str());
            ImGui::TableNextColumn();
            ImGui::SetNextItemWidth(-1);
            if (row.to.empty()) {
                ++unassigned;
                ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
            }
            const bool wasEmpty = row.to.empty();
            const std::string label = "##assign-" + row.from;
            visemeNameCombo(label.c_str(), set, row.to, "(choose)");
            if (wasEmpty) ImGui::PopStyleColor();
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    if (unassigned > 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
        ImGui::TextWrapped("%d of the map's visemes are not assigned yet: their phonemes would be unmapped.",
                           unassigned);
        ImGui::PopStyleColor();
    }
    if (unassigned > 0) ImGui::BeginDisabled();
    if (ctl::Button("Apply map"))
        if (session_.attempt("Phoneme map", [&] {
                session_.frequencies().startPhonemeMap(mapStart_.table, mapStart_.map, mapStart_.rows,
                                                       mapStart_.title);
            }))
            mapStart_.open = false;
    if (unassigned > 0) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ctl::Button("Cancel##map-start")) mapStart_.open = false;
}

void PhonemeMapEditor::editor() {
    const VisemeSet& set = *session_.visemes();
    const FrequencySource& source = session_.document().frequencies;
    const edit::MapCoverage coverage = edit::mapCoverage(session_.document());

    // Visemes no phoneme maps to have frequency 0: say so before the table.
    if (!coverage.visemesWithoutPhoneme.empty()) {
        std::vector<std::string> names;
        for (const int i : coverage.visemesWithoutPhoneme)
            names.push_back(set.visemes[static_cast<std::size_t>(i)].name);
        ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
        ImGui::TextWrapped("No phoneme maps to %s: frequency 0.", joined(names).c_str());
        ImGui::PopStyleColor();
    } else {
        ImGui::TextDisabled("Every viseme has at least one phoneme.");
    }
    restVisemeRow();

    double total = 0.0;
    for (const auto& entry : source.phonemes.entries) total += entry.second;
    sectionHeader("Phonemes");
    if (ImGui::BeginTable("##phonemes", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("Phoneme", ImGuiTableColumnFlags_WidthFixed, scaled(70.0f));
        ImGui::TableSetupColumn("Frequency", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableSetupColumn("Share", ImGuiTableColumnFlags_WidthFixed, scaled(55.0f));
        ImGui::TableSetupColumn("Viseme", ImGuiTableColumnFlags_WidthStretch, 1.2f);
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < source.phonemes.entries.size(); ++i) {
            const auto& [phoneme, value] = source.phonemes.entries[i];
            ImGui::PushID(static_cast<int>(i));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const std::string ipa = ipaOf(phoneme);
            ImGui::AlignTextToFramePadding();
            ImGui::Text("%s  %s", phoneme.c_str(),
                        ipa.empty() || ipa == phoneme ? "" : ("/" + ipa + "/").c_str());
            ImGui::TableNextColumn();
            float f = static_cast<float>(value);
            ImGui::SetNextItemWidth(-1);
            const std::string frequencyLabel = "##freq-" + phoneme;
            if (ctl::DragFloat(frequencyLabel.c_str(), &f, 1.0f, 0.0f, 1e9f, "%.6g"))
                session_.attempt("Phoneme frequency",
                                 [&] { session_.frequencies().setPhonemeFrequency(static_cast<int>(i), f); });
            endEditOnRelease(session_);
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(percent(total > 0.0 ? value / total : 0.0).c_str());
            ImGui::TableNextColumn();
            const std::string* mapped = source.map.visemeOf(phoneme);
            std::string choice = mapped ? *mapped : std::string();
            ImGui::SetNextItemWidth(-1);
            const std::string mapLabel = "##map-" + phoneme;
            if (visemeNameCombo(mapLabel.c_str(), set, choice, "(unmapped)") &&
                (!mapped || choice != *mapped))
                session_.attempt("Phoneme map", [&] {
                    session_.frequencies().setPhonemeViseme(static_cast<int>(i), choice);
                });
            ImGui::PopID();
        }
        ImGui::EndTable();
    }

    sectionHeader("By viseme");
    if (ImGui::BeginTable("##by-viseme", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("Viseme", ImGuiTableColumnFlags_WidthFixed, scaled(90.0f));
        ImGui::TableSetupColumn("Share", ImGuiTableColumnFlags_WidthFixed, scaled(55.0f));
        ImGui::TableSetupColumn("Phonemes", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("Move all to", ImGuiTableColumnFlags_WidthFixed, scaled(110.0f));
        ImGui::TableHeadersRow();
        for (std::size_t v = 0; v < set.size(); ++v) {
            const std::string& name = set.visemes[v].name;
            ImGui::PushID(static_cast<int>(v));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            const bool none = coverage.phonemesOf[v].empty();
            if (none) ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(percent(coverage.share[v]).c_str());
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", none ? "(no phoneme)" : joined(coverage.phonemesOf[v]).c_str());
            if (none) ImGui::PopStyleColor();
            ImGui::TableNextColumn();
            if (!none) {
                std::string to;
                ImGui::SetNextItemWidth(-1);
                const std::string label = "##move-" + name;
                if (visemeNameCombo(label.c_str(), set, to, "move to...") && to != name)
                    session_.attempt("Move phonemes", [&] { session_.frequencies().movePhonemes(name, to); });
            }
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
}

void PhonemeMapEditor::addProbe(nlohmann::json& summary) const {
    summary["map_start_open"] = mapStart_.open;
    summary["map_start_unassigned"] = std::count_if(mapStart_.rows.begin(), mapStart_.rows.end(),
                                                    [](const auto& r) { return r.to.empty(); });
}

} // namespace vl::ui
