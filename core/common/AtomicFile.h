#pragma once
// File reading and atomic writing shared by every loader and saver.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace vl {

// Reads a whole regular file (at most limits::kMaxInputFileBytes) and notes it as an input of the
// run (core/common/InputRegistry.h); throws InputError naming the file when it is missing,
// unreadable, not a regular file or too large.
std::string readFileToString(const std::filesystem::path& path);

// The same bytes in a buffer that is not zero-filled before the read overwrites it (a std::string
// clears every byte first: 8.6 % of reading a large binary mesh, issue 33).
struct FileBytes {
    std::unique_ptr<char[]> data;
    std::size_t size = 0;
    std::size_t capacity = 0; // bytes `data` holds (>= size)
    std::string_view view() const { return {data.get(), size}; }
};
FileBytes readFileBytes(const std::filesystem::path& path);
// The same into `buffer`, whose memory is reused when it holds enough: a loader reading many files of
// one size has fresh pages cleared by the kernel once, not once per file.
void readFileBytesInto(const std::filesystem::path& path, FileBytes& buffer);

// Writes `contents` to a temporary file beside `path`, fsyncs it, renames it over `path` and fsyncs
// the folder, so a crash, kill -9 or a full disk never leaves a half-written file where the old one
// was. Keeps the permission bits of the file it replaces; a symlink `path` is refused or written
// through (its target replaced, the link kept) as the output policy says (core/common/OutputPolicy.h).
// Temporaries (hidden, ".<name>.vltmp-<pid>-<n>") that killed writers left in the folder are removed
// first; a failed save removes its own. Refuses to overwrite an input of the run
// (OutputOverwritesInputError) or a file an input refers to (OutputRefusedError). Creates missing
// parent folders, never through a link.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

} // namespace vl
