#include "core/common/FolderSwap.h"

#include "core/common/Error.h"
#include "core/common/FileWriting.h"
#include "core/common/OutputSet.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace vl::fileio {

namespace {

constexpr std::string_view kStageInfix = ".vlstage-";
constexpr std::string_view kStaging = "staging\n";
constexpr std::string_view kReplaced = "replaced\n";

std::string stagingPrefix(const std::filesystem::path& place) {
    return "." + place.filename().string().substr(0, 180) + std::string(kStageInfix);
}

// The pid in "<prefix><pid>-<n>", or -1.
long ownerOf(std::string_view name, std::string_view prefix) {
    if (!name.starts_with(prefix)) return -1;
    return pidBeforeDash(name.substr(prefix.size()));
}

void writeMarker(const std::filesystem::path& file, std::string_view text) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) throwInputError(file.string(), "cannot write the staging marker: " + lastSystemError());
    const bool ok = writeAll(fd, text);
    ::close(fd);
    if (!ok) throwInputError(file.string(), "cannot write the staging marker: " + lastSystemError());
}

std::string readSmallFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char text[64];
    in.read(text, sizeof text);
    return std::string(text, static_cast<std::size_t>(in.gcount()));
}

bool sameInode(const std::filesystem::path& a, const std::filesystem::path& b) {
    struct stat x = {}, y = {};
    return ::lstat(a.c_str(), &x) == 0 && ::lstat(b.c_str(), &y) == 0 && x.st_dev == y.st_dev &&
           x.st_ino == y.st_ino;
}

} // namespace

std::filesystem::path createStagingFolder(const std::filesystem::path& place,
                                          const std::filesystem::path& shownAs) {
    struct stat info {};
    const mode_t mode = ::stat(place.c_str(), &info) == 0 ? (info.st_mode & 07777) : 0777;
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path staging =
            place.parent_path() / (stagingPrefix(place) + std::to_string(::getpid()) + "-" +
                                   std::to_string(nextTemporarySuffix() % 1'000'000'000));
        if (::mkdir(staging.c_str(), 0700) != 0) {
            if (errno == EEXIST) continue;
            throwInputError(shownAs.string(), "cannot create the staging folder beside it (" +
                                                  lastSystemError() +
                                                  "); a folder output is prepared beside its folder and "
                                                  "swapped in whole");
        }
        writeMarker(staging / kStageMarker, kStaging);
        (void)::chmod(staging.c_str(), mode); // the new folder keeps the old one's permissions
        return staging;
    }
    throwInputError(shownAs.string(), "cannot create the staging folder beside it");
}

void markAsReplaced(const std::filesystem::path& place) {
    writeMarker(place / kStageMarker, kReplaced);
}

bool exchangeFolders(const std::filesystem::path& staging, const std::filesystem::path& place,
                     const std::filesystem::path& shownAs) {
    if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, place.c_str(), RENAME_EXCHANGE) == 0) return true;
    if (errno == EINVAL || errno == ENOSYS || errno == EBUSY || errno == ENOTSUP || errno == EXDEV)
        return false;
    throwInputError(shownAs.string(), "cannot swap the new outputs in: " + lastSystemError() +
                                          "; the previous outputs are unchanged");
}

void removeStagingFolder(const std::filesystem::path& staging, const std::filesystem::path& place) {
    const bool replaced = readSmallFile(staging / kStageMarker) == kReplaced;
    std::set<std::string> listed; // outputs of the replaced folder's sets
    std::error_code ec;
    if (replaced)
        for (std::filesystem::directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.starts_with(".visemelab-") && name.ends_with(".manifest"))
                for (auto& file : OutputSet::readManifest(it->path())) listed.insert(std::move(file));
        }
    // Visible files first, the manifests after them: a run killed half-way through leaves the
    // manifests that tell the next sweep which of the remaining files were outputs.
    bool marker = false;
    for (const bool hidden : {false, true})
        for (std::filesystem::directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec)) {
            const std::filesystem::path file = it->path();
            const std::string name = file.filename().string();
            std::error_code ignored;
            if (name.starts_with('.') != hidden) continue;
            if (it->is_directory(ignored) && !it->is_symlink(ignored)) continue; // never ours: stays
            if (name == kStageMarker) {
                marker = true; // removed last: until then the folder is recognisably ours
                continue;
            }
            const bool ours = !replaced || hidden || listed.count(name) || sameInode(file, place / name);
            if (!ours &&
                ::renameat2(AT_FDCWD, file.c_str(), AT_FDCWD, (place / name).c_str(), RENAME_NOREPLACE) == 0)
                continue; // someone's new file: moved into the folder it was meant for
            std::filesystem::remove(file, ignored);
        }
    if (marker) std::filesystem::remove(staging / kStageMarker, ec);
    std::filesystem::remove(staging, ec); // fails, harmlessly, when something not ours stayed
}

void sweepStagingDebris(const std::filesystem::path& place) {
    std::error_code ec;
    std::filesystem::remove(place / kStageMarker, ec);
    const std::string prefix = stagingPrefix(place);
    const std::filesystem::path parent = place.parent_path();
    for (std::filesystem::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const long owner = ownerOf(name, prefix);
        std::error_code ignored;
        if (owner <= 0 || owner == ::getpid() || processExists(owner)) continue;
        if (!it->is_directory(ignored) || it->is_symlink(ignored)) continue;
        const bool empty = std::filesystem::is_empty(it->path(), ignored);
        if (empty)
            std::filesystem::remove(it->path(), ignored);
        else if (std::filesystem::is_regular_file(
                     std::filesystem::symlink_status(it->path() / kStageMarker, ignored)))
            removeStagingFolder(it->path(), place);
    }
}

} // namespace vl::fileio
