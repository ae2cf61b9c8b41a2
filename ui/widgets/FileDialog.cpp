#include "ui/widgets/FileDialog.h"
#include "ui/UiScale.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>

namespace vl::ui {
namespace fs = std::filesystem;

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> extensions, Accept accept,
                      std::string defaultName) {
    title_ = std::move(title);
    mode_ = mode;
    extensions_ = std::move(extensions);
    accept_ = std::move(accept);
    name_ = std::move(defaultName);
    replacing_.clear();
    folderText_ = folder.string();
    visible_ = true;
    openPending_ = true;
}

bool FileDialog::matches(const fs::path& file) const {
    if (extensions_.empty()) return true;
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end();
}

void FileDialog::finish(fs::path chosen) { // a copy: replacing_ is cleared below
    visible_ = false;
    replacing_.clear();
    ImGui::CloseCurrentPopup();
    accept_(chosen);
}

void FileDialog::drawReplaceQuestion() {
    ImGui::TextWrapped("%s already exists. Replace it?", replacing_.filename().string().c_str());
    ImGui::TextDisabled("%s", replacing_.parent_path().string().c_str());
    if (ctl::Button("Replace", ImVec2(scaled(100), 0))) finish(replacing_);
    ImGui::SameLine();
    if (ctl::Button("Cancel", ImVec2(scaled(100), 0))) replacing_.clear(); // back to choosing a name
}

void FileDialog::draw() {
    if (!visible_) return;
    const std::string id = title_ + "###file-dialog";
    if (openPending_) {
        ImGui::OpenPopup(id.c_str());
        openPending_ = false;
    }
    ImGui::SetNextWindowSize(ImVec2(scaled(640), scaled(460)), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(id.c_str(), &visible_)) return;
    if (!replacing_.empty()) {
        drawReplaceQuestion();
        ImGui::EndPopup();
        return;
    }

    ImGui::SetNextItemWidth(-70);
    if (ctl::InputText("##folder", &folderText_, ImGuiInputTextFlags_EnterReturnsTrue)) {
        std::error_code ec;
        if (fs::is_directory(folderText_, ec)) folder = fs::path(folderText_);
    }
    ImGui::SameLine();
    if (ctl::Button("Up")) {
        folder = folder.parent_path().empty() ? folder : folder.parent_path();
        folderText_ = folder.string();
    }

    std::vector<fs::directory_entry> entries;
    std::error_code ec;
    for (const auto& entry :
         fs::directory_iterator(folder, fs::directory_options::skip_permission_denied, ec))
        if (entry.is_directory(ec) || (mode_ != Mode::OpenFolder && matches(entry.path())))
            entries.push_back(entry);
    std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        if (a.is_directory() != b.is_directory()) return a.is_directory();
        return a.path().filename() < b.path().filename();
    });

    ImGui::BeginChild("##entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2.2f), true);
    for (const auto& entry : entries) {
        const bool isDir = entry.is_directory(ec);
        const std::string label = (isDir ? "[dir] " : "      ") + entry.path().filename().string();
        if (ctl::Selectable(label.c_str(), !isDir && name_ == entry.path().filename().string(),
                            ImGuiSelectableFlags_AllowDoubleClick | ImGuiSelectableFlags_DontClosePopups)) {
            if (isDir) {
                if (ImGui::IsMouseDoubleClicked(0) || mode_ == Mode::OpenFolder) {
                    folder = entry.path();
                    folderText_ = folder.string();
                }
            } else {
                name_ = entry.path().filename().string();
                if (ImGui::IsMouseDoubleClicked(0) && mode_ == Mode::OpenFile) finish(folder / name_);
            }
        }
    }
    ImGui::EndChild();

    if (mode_ != Mode::OpenFolder) {
        ImGui::SetNextItemWidth(-1);
        ctl::InputTextWithHint("##name", "file name", &name_);
    } else {
        ImGui::TextUnformatted(("Folder: " + folder.string()).c_str());
    }
    const bool ready = mode_ == Mode::OpenFolder || !name_.empty();
    if (!ready) ImGui::BeginDisabled();
    if (ctl::Button(mode_ == Mode::SaveFile ? "Save" : "Open", ImVec2(scaled(100), 0)) && visible_) {
        const fs::path chosen = mode_ == Mode::OpenFolder ? folder : folder / name_;
        if (mode_ == Mode::SaveFile && fs::exists(fs::symlink_status(chosen, ec)))
            replacing_ = chosen; // asked on the next frame
        else
            finish(chosen);
    }
    if (!ready) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ctl::Button("Cancel", ImVec2(scaled(100), 0))) {
        visible_ = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace vl::ui
