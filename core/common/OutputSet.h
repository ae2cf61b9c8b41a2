#pragma once
// Several files written into one folder as a set (reduce --out, export obj/vrml, visemes --out), all
// or nothing: a reader of the folder sees the complete old or the complete new set at every instant,
// whenever the run is killed.
//   1. The constructor locks the folder (one writer at a time; core/common/FolderLock.h), sweeps what
//      killed runs left, and creates an empty staging folder beside it (core/common/FolderSwap.h).
//   2. add() writes each file into the staging folder; a destination that already holds exactly
//      these bytes is hard-linked instead (same inode, same time stamp).
//   3. commit() writes the set's manifest (.visemelab-<set>.manifest: each file with its size and
//      content hash), hard-links every other file of the folder into the staging folder (the user's
//      files, other sets' outputs), except the files the previous run of this set wrote that this run
//      does not and that still hold what that run wrote (manifest hash): those are the stale outputs.
//      It makes the staging folder durable (fsync), exchanges it with the folder in one
//      renameat2(RENAME_EXCHANGE) and removes the replaced folder. A planted or stale manifest thus
//      removes nothing: a file goes only when its bytes are the ones the manifest recorded.
//      Where the file system cannot exchange the files are renamed in one by one (the manifest
//      last): not all-or-nothing, as before issue 30.
//   4. Destroyed without commit() (an error, an exception), the staging folder is removed.
// Refused before anything is written: a folder that is or holds an input or a file an input refers
// to (InputRegistry.h), a folder that is a symbolic link (unless OutputPolicy follows links), a
// folder holding subfolders (the folder is replaced as a whole; a subfolder cannot be carried over
// atomically), a mount point or the root folder, a member that is a symbolic link.
//
//     OutputSet out(folder, "export-obj");
//     out.add("neutral.obj", text);
//     out.commit();
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

namespace fileio {
class FolderLock;
}

class OutputSet {
  public:
    // `setName` (letters, digits, '-', '_') names the manifest: sets of different names share a
    // folder without removing each other's files. Creates `folder` when missing; waits while another
    // run writes it (or refuses, core/common/OutputPolicy.h). Throws InputError when it cannot,
    // OutputOverwritesInputError or OutputRefusedError for the refusals above.
    OutputSet(std::filesystem::path folder, std::string setName);
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    const std::filesystem::path& folder() const { return folder_; }

    // Stages `fileName` (a plain name inside the folder, not hidden, given once per set) with
    // `contents`. Throws InputError naming the file when it cannot be written (disk full, ...).
    void add(const std::string& fileName, std::string_view contents);
    // The same with the contents given as parts written one after another (parts many files share
    // need not be copied into one string first).
    void add(const std::string& fileName, std::initializer_list<std::string_view> parts);

    // The manifest, the carried-over files, the barrier and the swap, as above; releases the lock.
    // Returns the destinations in the order they were added.
    std::vector<std::filesystem::path> commit();

    // The manifest file of a set, and the names it lists (empty when there is none).
    static std::filesystem::path manifestPath(const std::filesystem::path& folder, std::string_view setName);
    static std::vector<std::string> readManifest(const std::filesystem::path& manifest);

  private:
    struct Staged {
        std::string name;
        std::uint64_t size = 0;
        std::string hash;
        bool linked = false; // the destination already held these bytes: hard-linked, not written
    };
    void stage(const std::string& fileName, std::initializer_list<std::string_view> parts);
    // The files the last run of this set wrote and this one does not, that no other set of the
    // folder claims: name -> the content hash that run recorded.
    std::map<std::string, std::string> staleOutputs() const;
    void writeManifest();
    void carryOverOtherFiles(const std::map<std::string, std::string>& stale);
    void makeStagingDurable() const;
    void renameFileByFile(const std::map<std::string, std::string>& stale);
    void discardStaging();

    std::filesystem::path folder_; // as given: messages and the paths commit() returns
    std::filesystem::path place_;  // absolute, links resolved: the folder that is replaced
    std::string setName_;
    std::unique_ptr<fileio::FolderLock> lock_;
    std::filesystem::path staging_;
    std::vector<Staged> staged_;
    bool committed_ = false;
};

} // namespace vl
