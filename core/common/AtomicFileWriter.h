#pragma once
// A file written piece by piece (too large to hold in memory) that appears at its path only when
// commit() succeeds: data goes to a temporary file beside it, which is flushed, synced and renamed
// over the path. Destroyed without commit(), the temporary file is removed and the path untouched.
// The same protocol as writeFileAtomically (core/common/AtomicFile.h): inputs of the run refused,
// mode kept, symlinks as the output policy says (core/common/OutputPolicy.h), the folder synced after
// the rename, the temporaries of killed writers in the folder swept. A path `-` under a policy that
// sends it to the standard output (OutputPolicy::standardOutputFd) is held in memory and written there
// at commit, so a failed run writes nothing to the pipe either.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace vl {

class AtomicFileWriter {
  public:
    // Throws InputError naming `path` when the temporary file cannot be created.
    explicit AtomicFileWriter(const std::filesystem::path& path);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    // Appends; throws InputError naming the path when the write fails (disk full).
    void write(std::string_view bytes);
    // Overwrites bytes already written at `offset` (a header whose sizes are known at the end).
    void overwrite(std::uint64_t offset, std::string_view bytes);
    std::uint64_t size() const { return size_; }

    // Syncs and renames the temporary file over the path.
    void commit();

  private:
    [[noreturn]] void fail(const char* what);

    std::filesystem::path path_;
    std::filesystem::path target_; // path_, or the file its symlinks lead to
    std::filesystem::path temp_;
    std::FILE* file_ = nullptr;
    std::uint64_t size_ = 0;
    bool toStandardOutput_ = false;
    bool open_ = false;   // written to until commit() or a failure
    std::string pending_; // the bytes for the standard output
};

} // namespace vl
