#pragma once
// One writer per output folder (internal to core/common, used by OutputSet): an exclusive flock on
// the folder itself. The kernel drops it when the process dies, so a killed writer never leaves a
// stale lock behind. A folder output swaps in a new folder (core/common/FolderSwap.h), so a waiter
// that gets the lock checks that it still holds the folder at the path, and else locks the new one;
// the writer locks the new folder too before swapping it in.
#include <filesystem>
#include <vector>

namespace vl::fileio {

class FolderLock {
  public:
    // Locks the existing folder `folder`. When another process holds it: waits, saying on stderr who
    // (pid and command), or with OutputPolicy::waitForBusyFolder off throws OutputRefusedError naming
    // `shownAs` and the holder. Throws InputError when the folder cannot be opened.
    FolderLock(const std::filesystem::path& folder, const std::filesystem::path& shownAs);
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

    // Also locks `other` (a fresh folder nobody else can hold yet): it is about to replace the folder.
    void alsoLock(const std::filesystem::path& other);
    // Releases every lock now (before the destructor).
    void release();

  private:
    std::vector<int> fds_;
};

// "pid 1234 (visemelab reduce --out D)" for the process holding a flock on the folder `folder`, from
// /proc/locks; "another process" when it cannot be told.
std::string describeLockHolder(const std::filesystem::path& folder);

} // namespace vl::fileio
