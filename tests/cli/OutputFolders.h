#pragma once
// What a reader of an output folder sees, for the output safety tests: the visible files with their
// bytes, and the debris (staging folders, temporaries, markers) a run may leave.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace vl::test {

// Visible (not hidden) file -> its bytes; report.json (run times in it) only by name.
using FolderView = std::map<std::string, std::string>;

inline FolderView visibleFiles(const std::filesystem::path& folder) {
    FolderView view;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.starts_with('.')) continue;
        std::ifstream in(it->path(), std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        view[name] = name == "report.json" ? std::string("<report>") : bytes.str();
    }
    return view;
}

// Leftovers of interrupted runs: staging folders beside `folder`, temporaries and markers in it
// (manifests are outputs, not debris).
inline std::vector<std::string> debrisOf(const std::filesystem::path& folder) {
    std::vector<std::string> found;
    std::error_code ec;
    const std::string staging = "." + folder.filename().string() + ".vlstage-";
    for (std::filesystem::directory_iterator it(folder.parent_path(), ec), end; !ec && it != end;
         it.increment(ec))
        if (it->path().filename().string().starts_with(staging)) found.push_back(it->path().string());
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const bool manifest = name.starts_with(".visemelab-") && name.ends_with(".manifest");
        if (name.starts_with('.') && !manifest) found.push_back(it->path().string());
    }
    return found;
}

// A fresh folder "<prefix><test name>" in the temporary folder holding a copy of the bundled sample
// project as `sample` (sample/sample.vlproj and its meshes).
inline std::filesystem::path folderWithSample(const std::string& prefix, const std::string& sample) {
    const auto folder = std::filesystem::temp_directory_path() /
                        (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::filesystem::copy(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample", folder / sample);
    return folder;
}

// The names of a view, for failure messages.
inline std::string namesOf(const FolderView& view) {
    std::string names;
    for (const auto& [name, bytes] : view) names += name + " ";
    return names;
}

} // namespace vl::test
