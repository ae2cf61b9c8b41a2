#include "ui/panels/FileActions.h"

#include "ui/UiScale.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void FileActions::guarded(std::function<void()> action) {
    if (!session_.history().modified()) {
        action();
        return;
    }
    pendingGuarded_ = std::move(action);
    openUnsavedPopup_ = true;
}

void FileActions::saveProject(bool askForFile, std::function<void()> then) {
    if (!askForFile && !session_.files().path().empty()) {
        session_.attempt("Save project", [&] { session_.files().startSaveProject({}, std::move(then)); });
        return;
    }
    dialog_.open(
        "Save project as", FileDialog::Mode::SaveFile, {".vlproj"},
        [this, then](const auto& path) {
            session_.attempt("Save project", [&] { session_.files().startSaveProject(path, then); });
        },
        "project.vlproj");
}

void FileActions::openProject() {
    guarded([this] {
        dialog_.open("Open project", FileDialog::Mode::OpenFile, {".vlproj", ".json"},
                     [this](const auto& path) {
                         session_.attempt("Open project", [&] { session_.files().startOpenProject(path); });
                     });
    });
}

void FileActions::loadSample() {
    guarded([this] { session_.attempt("Load sample", [&] { session_.files().startLoadSample(); }); });
}

void FileActions::openVisemeFolder() {
    guarded([this] {
        dialog_.open("Open viseme folder", FileDialog::Mode::OpenFolder, {}, [this](const auto& path) {
            session_.attempt("Open folder", [&] { session_.files().startLoadVisemeFolder(path); });
        });
    });
}

void FileActions::importGltf(const char* dialogTitle) {
    guarded([this, dialogTitle] {
        dialog_.open(dialogTitle, FileDialog::Mode::OpenFile, {".glb", ".gltf"}, [this](const auto& path) {
            session_.attempt("Import glTF", [&] { session_.files().importGltf(path); });
        });
    });
}

void FileActions::requestQuit() {
    guarded([this] { quitConfirmed_ = true; });
}

void FileActions::draw() {
    dialog_.draw();
    unsavedChangesPopup();
}

void FileActions::unsavedChangesPopup() {
    if (openUnsavedPopup_) {
        ImGui::OpenPopup("Unsaved changes");
        openUnsavedPopup_ = false;
    }
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted("The project has unsaved changes.");
    const bool hasPath = !session_.files().path().empty();
    if (ctl::Button(hasPath ? "Save" : "Save as...", ImVec2(scaled(110), 0))) {
        ImGui::CloseCurrentPopup();
        saveProject(false, std::move(pendingGuarded_));
    }
    ImGui::SameLine();
    if (ctl::Button("Discard changes", ImVec2(scaled(130), 0))) {
        ImGui::CloseCurrentPopup();
        if (auto action = std::move(pendingGuarded_)) action();
    }
    ImGui::SameLine();
    if (ctl::Button("Cancel", ImVec2(scaled(90), 0))) {
        pendingGuarded_ = nullptr;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace vl::ui
