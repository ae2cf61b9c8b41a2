#pragma once
// The editor window's title: the project's file name, a '*' while it has unsaved changes, then the
// folder it is in, so a designer with several editors open knows which is which.
//   "sample.vlproj* - assets/sample - VisemeLab", "Untitled* - VisemeLab"
#include <filesystem>
#include <string>

namespace vl::ui {

inline std::string windowTitle(const std::filesystem::path& project, bool modified) {
    const std::string marker = modified ? "*" : "";
    if (project.empty()) return "Untitled" + marker + " - VisemeLab";
    const std::string folder = project.parent_path().string();
    return project.filename().string() + marker + (folder.empty() ? "" : " - " + folder) + " - VisemeLab";
}

} // namespace vl::ui
