#include "core/common/InputRegistry.h"

#include <cassert>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <utility>

namespace vl {

namespace {

using FileId = std::pair<dev_t, ino_t>;

struct Registry {
    std::mutex mutex;
    bool recording = false;
    std::map<FileId, std::filesystem::path> files;   // identity -> the path it was read as
    std::map<FileId, std::filesystem::path> folders; // likewise for listed folders
};

Registry& registry() {
    static Registry instance;
    return instance;
}

// stat() follows symlinks: a link and its target have the same identity.
bool identityOf(const std::filesystem::path& path, FileId& id) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return false;
    id = {info.st_dev, info.st_ino};
    return true;
}

void note(const std::filesystem::path& path, bool folder) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (!r.recording) return;
    FileId id;
    if (identityOf(path, id)) (folder ? r.folders : r.files).emplace(id, path);
}

// The recorded path with the identity of `path`, or empty.
std::filesystem::path recordedAs(const std::filesystem::path& path, bool folder) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    FileId id;
    if (!r.recording || !identityOf(path, id)) return {};
    const auto& table = folder ? r.folders : r.files;
    const auto it = table.find(id);
    return it == table.end() ? std::filesystem::path() : it->second;
}

} // namespace

InputRecording::InputRecording() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    assert(!r.recording && "input recordings do not nest");
    r.recording = true;
}

InputRecording::~InputRecording() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.recording = false;
    r.files.clear();
    r.folders.clear();
}

void noteInputFile(const std::filesystem::path& file) {
    note(file, false);
}

void noteInputFolder(const std::filesystem::path& folder) {
    note(folder, true);
}

void allowUpdatingInPlace(const std::filesystem::path& file) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    FileId id;
    if (r.recording && identityOf(file, id)) r.files.erase(id);
}

void refuseOverwritingInput(const std::filesystem::path& destination, std::string_view what) {
    const auto input = recordedAs(destination, false);
    if (input.empty()) return;
    const bool same = input.lexically_normal() == destination.lexically_normal();
    throw OutputOverwritesInputError(
        destination.string() + ": " + std::string(what) + " would overwrite an input of this run" +
        (same ? std::string() : " (" + input.string() + ")") + "; write it somewhere else");
}

void refuseWritingIntoInputFolder(const std::filesystem::path& folder, std::string_view what) {
    const auto input = recordedAs(folder, true);
    if (input.empty()) return;
    throw OutputOverwritesInputError(folder.string() + ": " + std::string(what) + " is the input folder " +
                                     input.string() +
                                     " of this run (its files would be read as inputs next time); "
                                     "write it somewhere else");
}

} // namespace vl
