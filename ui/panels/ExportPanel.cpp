// Export panel: project save/load and the runtime exports of the core.
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"

#include <imgui.h>

namespace vl::ui {

void EditorUi::exportPanel() {
    sectionHeader("Project");
    const Project& project = session.project();
    ImGui::TextWrapped("File: %s", project.path.empty() ? "(not saved yet)" : project.path.string().c_str());
    if (session.modified()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "Unsaved changes");
    if (ImGui::Button("Open project..."))
        guarded([this] {
            fileDialog_.open("Open project", FileDialog::Mode::OpenFile, {".vlproj", ".json"},
                             [this](const auto& path) {
                                 session.attempt("Open project", [&] { session.openProject(path); });
                             });
        });
    ImGui::SameLine();
    if (ImGui::Button("Save")) {
        if (project.path.empty())
            fileDialog_.open(
                "Save project as", FileDialog::Mode::SaveFile, {".vlproj"},
                [this](const auto& path) {
                    session.attempt("Save project", [&] { session.saveProject(path); });
                },
                "project.vlproj");
        else
            session.attempt("Save project", [&] { session.saveProject(); });
    }
    ImGui::SameLine();
    if (ImGui::Button("Save as..."))
        fileDialog_.open(
            "Save project as", FileDialog::Mode::SaveFile, {".vlproj"},
            [this](const auto& path) { session.attempt("Save project", [&] { session.saveProject(path); }); },
            "project.vlproj");
}

} // namespace vl::ui
