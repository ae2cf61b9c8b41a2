#pragma once
// Several files written into one folder as a set (reduce --out, export obj/vrml, visemes --out):
//   1. add() writes each file to a temporary beside its destination (nothing visible changes), unless
//      the destination already holds exactly these bytes: that file is left as it is (made durable);
//   2. commit() stages the folder's manifest of the set (.visemelab-<set>.manifest: the files this
//      run writes), makes every temporary durable (fsync: one barrier before the first rename),
//      renames them over their destinations (the manifest last), fsyncs the folder once, then removes
//      the files the previous run of the same set wrote that this run did not: no stale outputs, and
//      files the set never wrote are never touched;
//   3. an OutputSet destroyed without commit() (an error, an exception) removes its temporaries,
//      and a new OutputSet sweeps the temporaries of runs that were killed.
// Every destination is checked against the run's inputs (InputRegistry.h) before anything is
// written. Destinations keep their permission bits; symlinked ones are written through.
//
//     OutputSet out(folder, "export-obj");
//     out.add("neutral.obj", text);
//     out.commit();
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

class OutputSet {
  public:
    // `setName` (letters, digits, '-', '_') names the manifest: sets of different names share a
    // folder without removing each other's files. Creates `folder` when missing; throws InputError
    // when it cannot, and OutputOverwritesInputError when it is an input folder of the run.
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

    // The durability barrier, the renames, the manifest and the removal of stale outputs, as above.
    // Returns the destinations in the order they were added.
    std::vector<std::filesystem::path> commit();

    // The manifest file of a set, and the names it lists (empty when there is none).
    static std::filesystem::path manifestPath(const std::filesystem::path& folder, std::string_view setName);
    static std::vector<std::string> readManifest(const std::filesystem::path& manifest);

  private:
    struct Staged {
        std::string name;
        std::filesystem::path target;    // the file replaced (a symlink's target)
        std::filesystem::path temporary; // empty when the destination already holds the contents
        bool unchanged() const { return temporary.empty(); }
    };
    void stage(const std::string& fileName, std::initializer_list<std::string_view> parts);
    void discardTemporaries();
    void removeStaleOutputs(const std::vector<std::string>& previous);

    std::filesystem::path folder_;
    std::string setName_;
    std::vector<Staged> staged_;
    bool committed_ = false;
};

} // namespace vl
