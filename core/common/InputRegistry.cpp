#include "core/common/InputRegistry.h"

#include "core/common/ContentHash.h"

#include <algorithm>
#include <cassert>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <utility>

namespace vl {

// Adds `file` to every live InputWatch (the friend InputRegistry.h declares): read (with the hash of
// *bytes when given) or referenced.
void noteWatched(const std::filesystem::path& file, const std::string_view* bytes, bool read);

namespace {

using FileId = std::pair<dev_t, ino_t>;

struct Registry {
    std::mutex mutex;
    bool recording = false;
    std::map<FileId, std::filesystem::path> files;      // identity -> the path it was read as
    std::map<FileId, std::filesystem::path> folders;    // likewise for listed folders
    std::map<FileId, std::filesystem::path> references; // named by an input, maybe not read
    // Where every noted file is (absolute, symlinks resolved): a folder output may not hold one.
    std::map<std::filesystem::path, std::filesystem::path> locations; // location -> as noted
    std::vector<InputWatch*> watches;
};

std::filesystem::path locationOf(const std::filesystem::path& path) {
    std::error_code ec;
    const auto location = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
    return ec ? std::filesystem::path() : location;
}

// True when `inner` lies inside `folder` (both absolute and normal).
bool isInside(const std::filesystem::path& inner, const std::filesystem::path& folder) {
    const auto [f, i] = std::mismatch(folder.begin(), folder.end(), inner.begin(), inner.end());
    return f == folder.end() && i != inner.end();
}

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

enum class Kind { File, Folder, Reference };

void note(const std::filesystem::path& path, Kind kind) {
    const std::filesystem::path location = kind == Kind::Folder ? std::filesystem::path() : locationOf(path);
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (!r.recording) return;
    FileId id;
    auto& table = kind == Kind::File ? r.files : kind == Kind::Folder ? r.folders : r.references;
    if (identityOf(path, id)) table.emplace(id, path);
    if (!location.empty()) r.locations.emplace(location, path);
}

// The recorded path with the identity of `path`, or empty.
std::filesystem::path recordedAs(const std::filesystem::path& path, Kind kind) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    FileId id;
    if (!r.recording || !identityOf(path, id)) return {};
    const auto& table = kind == Kind::File ? r.files : kind == Kind::Folder ? r.folders : r.references;
    const auto it = table.find(id);
    return it == table.end() ? std::filesystem::path() : it->second;
}

} // namespace

void noteWatched(const std::filesystem::path& file, const std::string_view* bytes, bool read) {
    Registry& r = registry();
    {
        std::lock_guard lock(r.mutex);
        if (r.watches.empty()) return;
    }
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(file, ec).lexically_normal();
    if (ec) return;
    const InputWatch::Read entry{absolute, bytes ? contentHash(*bytes) : 0, bytes != nullptr};
    std::lock_guard lock(r.mutex);
    for (InputWatch* watch : r.watches) {
        if (!read) {
            auto& list = watch->referenced_;
            if (std::find(list.begin(), list.end(), absolute) == list.end()) list.push_back(absolute);
        } else {
            auto& list = watch->read_;
            const auto it = std::find_if(list.begin(), list.end(),
                                         [&](const InputWatch::Read& e) { return e.file == absolute; });
            if (it == list.end())
                list.push_back(entry);
            else if (!it->hashed)
                *it = entry; // noted first without its bytes (named as an input before it was read)
        }
    }
}

InputWatch::InputWatch() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.watches.push_back(this);
}

InputWatch::~InputWatch() {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    std::erase(r.watches, this);
}

std::vector<InputWatch::Read> InputWatch::read() const {
    std::lock_guard lock(registry().mutex);
    return read_;
}

std::vector<std::filesystem::path> InputWatch::referenced() const {
    std::lock_guard lock(registry().mutex);
    return referenced_;
}

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
    r.references.clear();
    r.locations.clear();
}

void noteInputFile(const std::filesystem::path& file) {
    noteWatched(file, nullptr, true);
    note(file, Kind::File);
}

void noteInputFile(const std::filesystem::path& file, std::string_view bytes) {
    noteWatched(file, &bytes, true);
    note(file, Kind::File);
}

void noteInputFolder(const std::filesystem::path& folder) {
    note(folder, Kind::Folder);
}

void noteReferencedFile(const std::filesystem::path& file) {
    noteWatched(file, nullptr, false);
    note(file, Kind::Reference);
}

void allowUpdatingInPlace(const std::filesystem::path& file) {
    const std::filesystem::path location = locationOf(file);
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    FileId id;
    if (!r.recording) return;
    if (identityOf(file, id)) r.files.erase(id), r.references.erase(id);
    r.locations.erase(location);
}

void refuseOverwritingInput(const std::filesystem::path& destination, std::string_view what) {
    const auto referenced = recordedAs(destination, Kind::Reference);
    if (!referenced.empty() && recordedAs(destination, Kind::File).empty())
        throw OutputRefusedError(destination.string() + ": " + std::string(what) + " would replace " +
                                 referenced.string() +
                                 ", a file an input of this run refers to; write it somewhere else");
    const auto input = recordedAs(destination, Kind::File);
    if (input.empty()) return;
    const bool same = input.lexically_normal() == destination.lexically_normal();
    throw OutputOverwritesInputError(
        destination.string() + ": " + std::string(what) + " would overwrite an input of this run" +
        (same ? std::string() : " (" + input.string() + ")") + "; write it somewhere else");
}

void refuseWritingIntoInputFolder(const std::filesystem::path& folder, std::string_view what) {
    const auto input = recordedAs(folder, Kind::Folder);
    if (input.empty()) return;
    throw OutputOverwritesInputError(folder.string() + ": " + std::string(what) + " is the input folder " +
                                     input.string() +
                                     " of this run (its files would be read as inputs next time); "
                                     "write it somewhere else");
}

void refuseFolderHoldingInputs(const std::filesystem::path& folder, std::string_view what) {
    const std::filesystem::path location = locationOf(folder);
    std::filesystem::path held;
    {
        Registry& r = registry();
        std::lock_guard lock(r.mutex);
        if (!r.recording || location.empty()) return;
        for (const auto& [where, noted] : r.locations)
            if (isInside(where, location)) {
                held = noted;
                break;
            }
    }
    if (held.empty()) return;
    throw OutputRefusedError(folder.string() + ": " + std::string(what) + " holds " + held.string() +
                             ", which an input of this run is or refers to (the output replaces the "
                             "folder's contents as a set); write it into another folder");
}

} // namespace vl
