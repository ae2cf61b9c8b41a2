#include "core/common/OutputSet.h"

#include "core/common/Error.h"
#include "core/common/FileWriting.h"
#include "core/common/FolderLock.h"
#include "core/common/FolderSwap.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

namespace vl {

namespace {

constexpr std::string_view kManifestPrefix = ".visemelab-";
constexpr std::string_view kManifestSuffix = ".manifest";

// A name a set may write: one plain, visible file of the folder.
bool isPlainFileName(std::string_view name) {
    return !name.empty() && name != "." && name != ".." && !name.starts_with('.') &&
           name.find('/') == std::string_view::npos && name.find('\0') == std::string_view::npos &&
           name.find('\n') == std::string_view::npos;
}

bool isSetName(std::string_view name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
               c == '_';
    });
}

// One line of a manifest: "<size> <hash> <name>", or a bare name (manifests before issue 30: their
// files are never removed, as nothing says what they held).
struct ManifestEntry {
    std::string name;
    std::string hash; // empty: not recorded
};

bool isHash(std::string_view text) {
    return text.size() == 16 && std::all_of(text.begin(), text.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

std::vector<ManifestEntry> readManifestEntries(const std::filesystem::path& manifest) {
    // Read directly, not as an input of the run (the set rewrites it); an unreadable or oversized
    // manifest only means stale files stay.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(manifest, ec)) ||
        std::filesystem::file_size(manifest, ec) > (1u << 20))
        return {};
    std::ifstream in(manifest, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<ManifestEntry> entries;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = trim(std::string_view(text).substr(start, end - start));
        start = end + 1;
        if (line.empty() || line.starts_with('#')) continue;
        const auto first = line.find(' ');
        const auto second = first == std::string_view::npos ? first : line.find(' ', first + 1);
        if (second != std::string_view::npos && isHash(line.substr(first + 1, second - first - 1)) &&
            std::all_of(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(first),
                        [](char c) { return c >= '0' && c <= '9'; }))
            entries.push_back(
                {std::string(line.substr(second + 1)), std::string(line.substr(first + 1, 16))});
        else
            entries.push_back({std::string(line), {}});
    }
    return entries;
}

// The folder a set replaces: absolute, without "." or a trailing "/", links before it resolved.
std::filesystem::path placeOf(const std::filesystem::path& resolved) {
    std::error_code ec;
    auto place = std::filesystem::weakly_canonical(std::filesystem::absolute(resolved, ec), ec);
    if (!place.has_filename()) place = place.parent_path();
    return place;
}

// A folder on another file system than its parent: the staging folder beside it could not be
// swapped with it, nor hold hard links of its files.
bool isMountPoint(const std::filesystem::path& folder) {
    struct stat inside = {}, parent = {};
    return ::stat(folder.c_str(), &inside) == 0 && ::stat(folder.parent_path().c_str(), &parent) == 0 &&
           inside.st_dev != parent.st_dev;
}

bool isHiddenOurs(std::string_view name) {
    return name == fileio::kStageMarker || name.find(".vltmp-") != std::string_view::npos;
}

} // namespace

OutputSet::OutputSet(std::filesystem::path folder, std::string setName)
    : folder_(folder.empty() ? std::filesystem::path(".") : std::move(folder)), setName_(std::move(setName)) {
    if (!isSetName(setName_)) throwInputError("output set", "invalid set name '" + setName_ + "'");
    if (isStandardOutput(folder_))
        throwInputError("-", "this output is a folder of several files; the standard output takes one file");
    refuseWritingIntoInputFolder(folder_);
    refuseFolderHoldingInputs(folder_);
    place_ = placeOf(resolveOutputPath(folder_, true));
    if (place_ == place_.root_path())
        throwInputError(folder_.string(), "the root folder cannot be an output folder");
    std::error_code ec;
    std::filesystem::create_directories(place_, ec); // fails on a dangling link: nothing created through it
    if (ec) throwInputError(folder_.string(), "cannot create the output folder: " + ec.message());
    if (!std::filesystem::is_directory(std::filesystem::symlink_status(place_, ec)))
        throwInputError(folder_.string(), "is not a folder; outputs go into a folder here");
    if (isMountPoint(place_))
        throwInputError(folder_.string(), "is a mount point; the outputs are staged beside their folder and "
                                          "swapped in, so write them into a folder inside it");
    lock_ = std::make_unique<fileio::FolderLock>(place_, folder_);
    fileio::sweepStagingDebris(place_);
    fileio::sweepStaleTemporaries(place_);
    for (std::filesystem::directory_iterator it(place_, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code ignored;
        if (it->is_directory(ignored) && !it->is_symlink(ignored))
            throw OutputRefusedError(
                (folder_ / it->path().filename()).string() +
                ": the output folder holds a subfolder; a folder output replaces its folder's contents "
                "as a whole, so write it into a folder without subfolders");
    }
    staging_ = fileio::createStagingFolder(place_, folder_);
}

OutputSet::~OutputSet() {
    if (!committed_) discardStaging();
}

void OutputSet::discardStaging() {
    if (staging_.empty()) return;
    std::error_code ec;
    std::filesystem::remove(place_ / fileio::kStageMarker, ec);
    fileio::removeStagingFolder(staging_, place_);
    staging_.clear();
}

void OutputSet::add(const std::string& fileName, std::string_view contents) {
    add(fileName, {contents});
}

void OutputSet::add(const std::string& fileName, std::initializer_list<std::string_view> parts) {
    const std::filesystem::path destination = folder_ / fileName;
    if (committed_) throwInputError(destination.string(), "the output set was already written");
    if (!isPlainFileName(fileName))
        throwInputError(destination.string(), "not a plain file name for an output of " + folder_.string());
    if (std::any_of(staged_.begin(), staged_.end(), [&](const Staged& s) { return s.name == fileName; }))
        throwInputError(destination.string(), "written twice by the same run");
    stage(fileName, parts);
}

void OutputSet::stage(const std::string& fileName, std::initializer_list<std::string_view> parts) {
    const std::filesystem::path shown = folder_ / fileName;
    const std::filesystem::path destination = place_ / fileName;
    refuseOverwritingInput(destination);
    struct stat existing {};
    const bool exists = ::lstat(destination.c_str(), &existing) == 0;
    if (exists && S_ISLNK(existing.st_mode))
        throw OutputRefusedError(shown.string() + ": the output is a symbolic link; a folder output "
                                                  "never writes through links (remove the link)");
    if (exists && S_ISDIR(existing.st_mode))
        throwInputError(shown.string(), "is a folder; cannot write a file there");
    const std::span<const std::string_view> contents(parts.begin(), parts.size());
    Staged staged{fileName, 0, {}, false};
    fileio::ContentHash hash;
    for (const std::string_view part : contents) hash.update(part), staged.size += part.size();
    staged.hash = hash.hex();
    const std::filesystem::path file = staging_ / fileName;
    // A destination that already holds these bytes stays as it is (same inode, same time stamp):
    // comparing costs a read from the page cache, replacing costs a new inode, the writing, the
    // writeback and the old file's removal; and tools that watch the folder see only real changes.
    if (fileio::holdsExactly(destination, contents) && ::link(destination.c_str(), file.c_str()) == 0) {
        staged.linked = true;
        staged_.push_back(std::move(staged));
        return;
    }
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throwInputError(shown.string(), "cannot stage the file: " + fileio::lastSystemError());
    if (exists) (void)::fchmod(fd, existing.st_mode & 07777); // a replaced file keeps its permissions
    staged_.push_back(std::move(staged));
    const bool ok = fileio::writeAll(fd, contents);
    const std::string problem = ok ? std::string() : fileio::lastSystemError();
    // Start writing the data out now, without waiting: the device works on this file while the next
    // ones are formatted, and the barrier's fsync then mostly waits. Advisory, so errors are ignored
    // here; the fsync reports them.
    if (ok) (void)::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
    ::close(fd);
    if (!ok) throwInputError(shown.string(), "write failed (" + problem + "); no output was changed");
}

void OutputSet::writeManifest() {
    std::string text = "# Files the last '" + setName_ +
                       "' run of VisemeLab wrote into this folder (size, content hash, name); the next "
                       "run removes those it does not write again while they still hold these bytes.\n";
    for (const Staged& s : staged_) text += std::to_string(s.size) + " " + s.hash + " " + s.name + "\n";
    const std::filesystem::path manifest = manifestPath(staging_, setName_);
    const std::filesystem::path current = manifestPath(place_, setName_);
    const std::string_view parts[] = {text};
    if (fileio::holdsExactly(current, parts) && ::link(current.c_str(), manifest.c_str()) == 0) return;
    const int fd = ::open(manifest.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    const bool ok = fd >= 0 && fileio::writeAll(fd, text);
    const std::string problem = ok ? std::string() : fileio::lastSystemError();
    if (fd >= 0) ::close(fd);
    if (!ok)
        throwInputError(manifestPath(folder_, setName_).string(), "cannot write the manifest: " + problem);
}

std::map<std::string, std::string> OutputSet::staleOutputs() const {
    std::map<std::string, std::string> stale; // name -> the hash the last run of the set recorded
    for (auto& entry : readManifestEntries(manifestPath(place_, setName_)))
        if (!entry.hash.empty() && isPlainFileName(entry.name)) stale[entry.name] = entry.hash;
    for (const Staged& s : staged_) stale.erase(s.name);
    // A file another set of the folder claims too stays: two kinds of output may share a folder.
    const std::string own = manifestPath(place_, setName_).filename().string();
    std::error_code ec;
    for (std::filesystem::directory_iterator it(place_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name != own && name.starts_with(kManifestPrefix) && name.ends_with(kManifestSuffix))
            for (const auto& entry : readManifestEntries(it->path())) stale.erase(entry.name);
    }
    return stale;
}

void OutputSet::carryOverOtherFiles(const std::map<std::string, std::string>& stale) {
    const std::string manifest = manifestPath(place_, setName_).filename().string();
    std::error_code ec;
    for (std::filesystem::directory_iterator it(place_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name == manifest || isHiddenOurs(name)) continue;
        if (std::any_of(staged_.begin(), staged_.end(), [&](const Staged& s) { return s.name == name; }))
            continue;
        const auto old = stale.find(name);
        if (old != stale.end() && fileio::hashOfFile(it->path()) == old->second)
            continue; // a stale output, still as that run wrote it: left behind with the old folder
        std::error_code ignored;
        if (it->is_directory(ignored) && !it->is_symlink(ignored))
            throw OutputRefusedError((folder_ / name).string() +
                                     ": a subfolder appeared in the output folder");
        // A hard link (of the link itself for a symlink): the same file, visible in both folders.
        if (::linkat(AT_FDCWD, it->path().c_str(), AT_FDCWD, (staging_ / name).c_str(), 0) != 0)
            throwInputError((folder_ / name).string(),
                            "cannot keep this file in the new output folder (hard link: " +
                                fileio::lastSystemError() + "); no output was changed");
    }
    if (ec) throwInputError(folder_.string(), "cannot list the output folder: " + ec.message());
}

void OutputSet::makeStagingDurable() const {
    auto sync = [&](const std::filesystem::path& file, const std::filesystem::path& shown) {
        const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
        const bool ok = fd >= 0 && ::fsync(fd) == 0;
        const std::string problem = ok ? std::string() : fileio::lastSystemError();
        if (fd >= 0) ::close(fd);
        if (!ok)
            throwInputError(shown.string(),
                            "cannot flush the file to disk (" + problem + "); no output was changed");
    };
    for (const Staged& s : staged_)
        if (!s.linked) sync(staging_ / s.name, folder_ / s.name); // linked ones were synced when compared
    sync(manifestPath(staging_, setName_), manifestPath(folder_, setName_));
    fileio::syncFolder(staging_);
}

std::vector<std::filesystem::path> OutputSet::commit() {
    if (committed_) throwInputError(folder_.string(), "the output set was already written");
    const auto stale = staleOutputs();
    writeManifest();
    carryOverOtherFiles(stale);
    makeStagingDurable(); // the barrier: the new folder is on disk before it replaces the old one
    fileio::markAsReplaced(place_);
    lock_->alsoLock(staging_); // a waiter that wakes after the swap finds the new folder locked too
    struct stat here = {}, folder = {};
    const bool inside = ::stat(".", &here) == 0 && ::stat(place_.c_str(), &folder) == 0 &&
                        here.st_dev == folder.st_dev && here.st_ino == folder.st_ino;
    if (fileio::exchangeFolders(staging_, place_, folder_)) {
        committed_ = true;
        fileio::syncFolder(place_.parent_path());
        if (inside) (void)::chdir(place_.c_str()); // relative paths go on naming the outputs' folder
        std::error_code ec;
        std::filesystem::remove(place_ / fileio::kStageMarker, ec);
        fileio::removeStagingFolder(staging_, place_); // the replaced folder, now at the staging path
    } else {
        renameFileByFile(stale);
    }
    staging_.clear();
    lock_->release();
    std::vector<std::filesystem::path> written;
    for (const Staged& s : staged_) written.push_back(folder_ / s.name);
    return written;
}

void OutputSet::renameFileByFile(const std::map<std::string, std::string>& stale) {
    std::error_code ec;
    std::filesystem::remove(place_ / fileio::kStageMarker, ec);
    std::vector<std::string> names;
    for (const Staged& s : staged_)
        if (!s.linked) names.push_back(s.name);
    names.push_back(manifestPath(place_, setName_).filename().string()); // last: it lists the new set
    for (std::size_t i = 0; i < names.size(); ++i) {
        std::filesystem::rename(staging_ / names[i], place_ / names[i], ec);
        if (ec) {
            committed_ = true;
            const std::string problem = ec.message();
            discardStaging();
            throwInputError((folder_ / names[i]).string(),
                            "cannot replace the file: " + problem + " (" + std::to_string(i) + " of " +
                                std::to_string(names.size()) + " files were replaced)");
        }
    }
    committed_ = true;
    fileio::syncFolder(place_);
    for (const auto& [name, hash] : stale)
        if (fileio::hashOfFile(place_ / name) == hash) std::filesystem::remove(place_ / name, ec);
    discardStaging();
}

std::filesystem::path OutputSet::manifestPath(const std::filesystem::path& folder, std::string_view setName) {
    return folder / (std::string(kManifestPrefix) + std::string(setName) + std::string(kManifestSuffix));
}

std::vector<std::string> OutputSet::readManifest(const std::filesystem::path& manifest) {
    std::vector<std::string> names;
    for (auto& entry : readManifestEntries(manifest)) names.push_back(std::move(entry.name));
    return names;
}

} // namespace vl
