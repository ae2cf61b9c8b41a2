#pragma once
// The editor window's title: which project is open and whether it has unsaved changes, so a user
// never loses track of what Save will write (issue 30).
#include <filesystem>
#include <string>

namespace vl::ui {

// "face.vlproj* - VisemeLab" (the asterisk: unsaved changes); "Untitled" for a project never saved.
inline std::string windowTitle(const std::filesystem::path& project, bool modified) {
    const std::string name = project.empty() ? std::string("Untitled") : project.filename().string();
    return name + (modified ? "*" : "") + " - VisemeLab";
}

} // namespace vl::ui
