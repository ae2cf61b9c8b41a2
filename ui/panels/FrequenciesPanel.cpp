// Frequencies panel: the phoneme -> viseme map editor (PhonemeMapEditor.cpp) or direct viseme
// frequencies, the resulting viseme frequencies live, CSV/JSON load and CSV save.
#include "ui/panels/FrequenciesPanel.h"

#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"
#include "ui/widgets/FrequencyHistogram.h"
#include "ui/widgets/JobProgress.h"

#include <imgui.h>

#include <cfloat>

namespace vl::ui {

void FrequenciesPanel::draw() {
    const VisemeSet* set = session_.visemes();
    if (!set) {
        ImGui::TextWrapped("Load a viseme set first.");
        return;
    }
    if (ctl::Button("Load table..."))
        files_.dialog().open(
            "Load frequencies", FileDialog::Mode::OpenFile, {".csv", ".json"}, [this](const auto& path) {
                session_.attempt("Load frequencies", [&] { session_.frequencies().load(path); });
            });
    ImGui::SameLine();
    if (ctl::Button("Save as CSV..."))
        files_.dialog().open(
            "Save frequencies", FileDialog::Mode::SaveFile, {".csv"},
            [this](const auto& path) {
                if (session_.attempt("Save frequencies", [&] { session_.frequencies().saveCsv(path); }))
                    session_.info("Saved " + path.string());
            },
            "frequencies.csv");
    helpMarker(
        "CSV lines 'name,frequency', or JSON {\"phonemes\": {...}, \"map\": {...}}. A phoneme table needs a "
        "map that covers every phoneme; errors name the file and line.");

    // Decided before the section draws: applying closes it mid-frame, and the editor below would then
    // draw its controls a second time in this frame.
    const bool assigning = mapEditor_.assigning();
    mapEditor_.startSection();
    const bool counting = session_.frequencies().countRunning();
    if (counting) ImGui::BeginDisabled();
    if (ctl::Button("Count phonemes in a text file..."))
        files_.dialog().open("Text corpus (espeak-ng, en-us)", FileDialog::Mode::OpenFile,
                             {".txt", ".md", ""}, [this](const auto& path) {
                                 session_.attempt("Phoneme count",
                                                  [&] { session_.frequencies().startPhonemeCount(path); });
                             });
    if (counting) {
        ImGui::EndDisabled();
        for (const auto& job : session_.jobs().running())
            if (job.job == SessionJobs::Job::PhonemeCount &&
                jobProgress(job.label, job.fraction, job.secondsLeft, "Cancel##transcription", -1))
                session_.jobs().cancel(job.job);
    }

    std::vector<double> frequencies;
    const bool ok = session_.attempt("Frequencies", [&] { frequencies = session_.frequencies().values(); });
    sectionHeader("Viseme frequencies (normalised)");
    if (ok) {
        std::vector<std::string> names;
        for (const auto& v : set->visemes) names.push_back(v.name);
        frequencyHistogram("##viseme-frequencies", frequencies, names, 80.0f);
    }

    const FrequencySource& source = session_.document().frequencies;
    if (source.isPhonemeBased() && !assigning) {
        mapEditor_.editor();
    } else if (!source.isPhonemeBased()) {
        sectionHeader("Viseme frequencies (direct)");
        if (ImGui::BeginTable("##direct", 2,
                              ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV,
                              ImVec2(0, ImGui::GetContentRegionAvail().y))) {
            ImGui::TableSetupScrollFreeze(0, 1);
            ImGui::TableSetupColumn("Viseme");
            ImGui::TableSetupColumn("Frequency");
            ImGui::TableHeadersRow();
            for (std::size_t i = 0; i < set->size(); ++i) {
                const std::string& name = set->visemes[i].name;
                const double* value = source.visemeFrequencies.find(name);
                ImGui::PushID(static_cast<int>(i));
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::AlignTextToFramePadding();
                ImGui::TextUnformatted(name.c_str());
                ImGui::TableNextColumn();
                float f = value ? static_cast<float>(*value) : 0.0f;
                ImGui::SetNextItemWidth(-1);
                if (ctl::DragFloat("##f", &f, 0.01f, 0.0f, 1e9f, "%.3f"))
                    session_.attempt("Frequency", [&] {
                        session_.frequencies().setVisemeFrequency(static_cast<int>(i), f);
                    });
                endEditOnRelease(session_);
                ImGui::PopID();
            }
            ImGui::EndTable();
        }
    }
}

} // namespace vl::ui
