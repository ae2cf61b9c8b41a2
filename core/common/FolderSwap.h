#pragma once
// A folder output replaces its whole folder at once (internal to core/common, used by OutputSet.h):
// the new contents are staged in a sibling folder ".<name>.vlstage-<pid>-<n>", which the kernel then
// exchanges with the folder (renameat2 RENAME_EXCHANGE): a reader sees the complete old or the
// complete new folder at every instant. The replaced folder ends at the staging path and is removed.
// Each staging folder holds a marker file whose text tells whether it was swapped in; with the pid
// in the name it is what lets the next run remove, and only remove, what a killed run left.
#include <filesystem>
#include <string_view>

namespace vl::fileio {

// The marker file, hidden; a folder output never copies it.
constexpr std::string_view kStageMarker = ".visemelab-staging";

// Creates the empty staging folder beside `place` (with the permission bits of `place`) and its
// marker. Throws InputError naming `shownAs` when it cannot (e.g. the parent folder is read-only).
std::filesystem::path createStagingFolder(const std::filesystem::path& place,
                                          const std::filesystem::path& shownAs);

// Writes the marker into `place` that says "replaced": after the exchange it is in the folder at the
// staging path, so that a run killed right after the exchange leaves a folder the next one can sweep.
void markAsReplaced(const std::filesystem::path& place);

// Exchanges the two folders atomically. False when the file system or the place cannot (no
// RENAME_EXCHANGE, a mount point): the caller falls back. Throws InputError naming `shownAs` for
// other errors.
bool exchangeFolders(const std::filesystem::path& staging, const std::filesystem::path& place,
                     const std::filesystem::path& shownAs);

// Empties and removes a staging folder of this or a dead process. Never swapped in: everything in it
// is staged or a hard link of a file of `place`, and goes. Replaced: files that `place` holds too
// (same inode), hidden files and files its manifests list go; any other file (created there by
// someone while the run swapped) is moved into `place` when its name is free there.
void removeStagingFolder(const std::filesystem::path& staging, const std::filesystem::path& place);

// Removes what killed runs left: staging folders beside `place` whose process is dead (empty ones, or
// ones with their marker; anything else is not provably ours and stays) and the marker in `place`.
// Call only while holding the folder's lock (core/common/FolderLock.h).
void sweepStagingDebris(const std::filesystem::path& place);

} // namespace vl::fileio
