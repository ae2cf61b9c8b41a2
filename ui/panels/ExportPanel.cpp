// Export panel: project save/load and the runtime exports of the core.
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void EditorUi::exportPanel() {
    sectionHeader("Project");
    const std::filesystem::path& file = session.path();
    ImGui::TextWrapped("File: %s", file.empty() ? "(not saved yet)" : file.string().c_str());
    if (session.modified()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "Unsaved changes");
    if (ctl::Button("Open project..."))
        guarded([this] {
            fileDialog_.open("Open project", FileDialog::Mode::OpenFile, {".vlproj", ".json"},
                             [this](const auto& path) {
                                 session.attempt("Open project", [&] { session.startOpenProject(path); });
                             });
        });
    ImGui::SameLine();
    if (ctl::Button("Save")) saveProject(false);
    ImGui::SameLine();
    if (ctl::Button("Save as...")) saveProject(true);

    sectionHeader("Runtime export (the reduced set)");
    const Grouping* grouping = session.currentGrouping();
    if (!session.visemes()) {
        ImGui::TextDisabled("Load a viseme set first.");
        return;
    }
    if (grouping)
        ImGui::Text("%zu visemes -> %zu keys (m = %d)", session.visemeCount(), grouping->groups.size(),
                    session.document().target);
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
        if (ctl::Button(target.label, ImVec2(200, 0))) {
            const ExportFormat format = target.format;
            auto run = [this, format](const std::filesystem::path& out) {
                session.attempt("Export", [&] { session.startExport(format, out); });
            };
            if (target.folder)
                fileDialog_.open(std::string("Export ") + target.label + ": choose a folder",
                                 FileDialog::Mode::OpenFolder, {}, run);
            else
                fileDialog_.open(std::string("Export ") + target.label, FileDialog::Mode::SaveFile, {}, run,
                                 target.defaultName);
        }
        ImGui::SameLine();
        noteText(target.help);
    }

    if (session.document().avatar.isSet()) avatarExportSection();

    sectionHeader("Import");
    if (ctl::Button("Import glTF morph targets...", ImVec2(200, 0)))
        guarded([this] {
            fileDialog_.open("Import glTF", FileDialog::Mode::OpenFile, {".glb", ".gltf"},
                             [this](const auto& path) {
                                 session.attempt("Import glTF", [&] { session.importGltf(path); });
                             });
        });
    ImGui::SameLine();
    noteText("the targets become the visemes");
    if (ctl::Button("Import avatar...", ImVec2(200, 0))) openAvatarImport();
    ImGui::SameLine();
    noteText("visemes of every mesh; export writes the same avatar back");
}

} // namespace vl::ui
