#pragma once
// The steps of a safe write shared by writeFileAtomically and OutputSet (internal to core/common):
// symlinks followed to the file they name, temporaries beside the destination that keep its mode,
// fsync of the folder after a rename, and the sweep of temporaries left by a killed process.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace vl::fileio {

// The file a write to `path` replaces: `path` itself, or the end of its chain of symlinks (so a
// symlinked destination is written through, not replaced by a regular file). Throws InputError
// naming `path` for a loop of links.
std::filesystem::path writeTarget(const std::filesystem::path& path);

// An open temporary file in the folder of `target` (so that renaming it over `target` is atomic),
// named ".<name>.vltmp-<pid>-<random>", with the permission bits of `target` when it exists and
// 0666 less the umask otherwise. Throws InputError naming `reportAs` when it cannot be created.
struct TemporaryFile {
    std::filesystem::path path;
    int fd = -1;
};
TemporaryFile createTemporaryFor(const std::filesystem::path& target, std::string_view reportAs);

// Writes every byte (retrying short writes); false on an error, with errno set.
bool writeAll(int fd, std::string_view data);
// The same for the concatenation of `parts`, in one writev where the kernel takes it all: the page
// cache then sees one long write (large folios) instead of a few short ones.
bool writeAll(int fd, std::span<const std::string_view> parts);

// True when `target` is a regular file whose bytes are exactly the concatenation of `parts`; it is
// then also made durable (fsync), as a newly written copy would be. False for a missing, different,
// unreadable or non-regular file. Reads the file in small chunks, stopping at the first difference.
bool holdsExactly(const std::filesystem::path& target, std::span<const std::string_view> parts);

// fsync of a folder, so that the renames into it survive a power cut. Errors are ignored: some
// file systems cannot sync a folder, and the data itself is already durable.
void syncFolder(const std::filesystem::path& folder);

// Removes the temporaries in `folder` whose writing process no longer exists (killed mid-save);
// only those for the file `name` when it is given. Temporaries of live processes are left alone.
void sweepStaleTemporaries(const std::filesystem::path& folder, std::string_view name = {});

// A number unique within the process and hard to guess, for names of temporaries.
std::uint64_t nextTemporarySuffix();
// The pid in "<pid>-<n>" (the end of a temporary's or staging folder's name), or -1.
long pidBeforeDash(std::string_view text);
// True while process `pid` exists (a temporary's writer may still be running).
bool processExists(long pid);

// A 64-bit hash of bytes given in pieces, with their count: the manifest of a folder output records
// it per file, so a later run removes a file only while it still holds what the run wrote.
class ContentHash {
  public:
    void update(std::string_view bytes);
    std::string hex() const; // 16 hex digits
  private:
    std::uint64_t state_ = 0x9E3779B97F4A7C15ull, size_ = 0;
    char tail_[8] = {};
    std::size_t tailSize_ = 0;
};
// ContentHash::hex of a regular file's bytes (not following a link); empty when it cannot be read.
std::string hashOfFile(const std::filesystem::path& file);

// "No space left on device" etc. for the current errno.
std::string lastSystemError();

} // namespace vl::fileio
