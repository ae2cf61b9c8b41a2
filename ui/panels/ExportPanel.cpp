// Export panel: project save/load and the runtime exports of the core.
#include "ui/panels/ExportPanel.h"
#include "ui/UiScale.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void ExportPanel::draw() {
    sectionHeader("Project");
    const std::filesystem::path& file = session_.files().path();
    ImGui::TextWrapped("File: %s", file.empty() ? "(not saved yet)" : file.string().c_str());
    if (session_.history().modified()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "Unsaved changes");
    if (ctl::Button("Open project...")) files_.openProject();
    ImGui::SameLine();
    if (ctl::Button("Save")) files_.saveProject(false);
    ImGui::SameLine();
    if (ctl::Button("Save as...")) files_.saveProject(true);

    sectionHeader("Runtime export (the reduced set)");
    const Grouping* grouping = session_.reduction().grouping();
    if (!session_.visemes()) {
        ImGui::TextDisabled("Load a viseme set first.");
        return;
    }
    if (grouping)
        ImGui::Text("%zu visemes -> %zu keys (m = %d)", session_.visemeCount(), grouping->groups.size(),
                    session_.document().target);
    else
        ImGui::TextDisabled("No current reduction: the export runs it with the project's settings.");
    struct Target {
        ExportFormat format;
        const char* label;
        const char* help;
        bool folder;
        const char* defaultName;
    };
    const Target targets[] = {
        {ExportFormat::Glb, "glTF binary (.glb)", "neutral + one morph target per merged viseme", false,
         "face.glb"},
        {ExportFormat::Runtime, "Runtime package", "compact little-endian package for the C++ runtime", false,
         "face.vlrt"},
        {ExportFormat::Vrml, "XfaceEd (VRML + .fdp)", "VRML97 meshes, face definition and phoneme dictionary",
         true, ""},
        {ExportFormat::Obj, "OBJ per key", "one OBJ file per merged viseme", true, ""},
    };
    for (const Target& target : targets) {
        if (ctl::Button(target.label, ImVec2(scaled(200), 0))) {
            const ExportFormat format = target.format;
            auto run = [this, format](const std::filesystem::path& out) {
                session_.attempt("Export", [&] { session_.files().startExport(format, out); });
            };
            if (target.folder)
                files_.dialog().open(std::string("Export ") + target.label + ": choose a folder",
                                     FileDialog::Mode::OpenFolder, {}, run);
            else
                files_.dialog().open(std::string("Export ") + target.label, FileDialog::Mode::SaveFile, {},
                                     run, target.defaultName);
        }
        ImGui::SameLine();
        noteText(target.help);
    }

    if (session_.document().avatar.isSet()) avatar_.exportSection();

    sectionHeader("Import");
    if (ctl::Button("Import glTF morph targets...", ImVec2(scaled(200), 0))) files_.importGltf("Import glTF");
    ImGui::SameLine();
    noteText("the targets become the visemes");
    if (ctl::Button("Import avatar...", ImVec2(scaled(200), 0))) avatar_.openImport();
    ImGui::SameLine();
    noteText("visemes of every mesh; export writes the same avatar back");
}

} // namespace vl::ui
