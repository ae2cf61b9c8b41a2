#pragma once
// Outputs never overwrite inputs. While an InputRecording is alive (the CLI keeps one for each
// command it runs), every file the core reads is remembered by identity (device and inode, so hard
// links, symlinks and "./x" spellings are caught too), and every writer of the core
// (writeFileAtomically, OutputSet) refuses a destination that is one of them with an
// OutputOverwritesInputError, before anything is written. Files an input names without this run
// reading them (a project's meshes read by another command, its avatar) are noted as references:
// no output may replace them either (OutputRefusedError). Without a recording (the editor saving the
// project it opened) nothing is remembered and nothing is refused.
#include "core/common/Error.h"

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace vl {

// A destination that is an input of the run. It is a usage error (exit code 2), not bad data.
class OutputOverwritesInputError : public InputError {
  public:
    using InputError::InputError;
};

// An output refused for its own safety or the user's: it would replace or hide a file an input of
// the run references, it leads through a symbolic link, or another run holds its folder. The message
// names the path. A data-level refusal (exit code 3), unlike OutputOverwritesInputError.
class OutputRefusedError : public InputError {
  public:
    using InputError::InputError;
};

// Remembers inputs while alive; recordings do not nest (a second one is refused by an assert).
class InputRecording {
  public:
    InputRecording();
    ~InputRecording();
    InputRecording(const InputRecording&) = delete;
    InputRecording& operator=(const InputRecording&) = delete;
};

// Collects, while alive, every file noted as read (noteInputFile) or referenced (noteReferencedFile)
// by any thread, with or without a recording: what a cached result depends on
// (core/project/SpeechCache.h). Watches may overlap (concurrent batch jobs); each then sees a superset
// of its own work's files, which only makes a cache stricter.
class InputWatch {
  public:
    InputWatch();
    ~InputWatch();
    InputWatch(const InputWatch&) = delete;
    InputWatch& operator=(const InputWatch&) = delete;
    struct Read {
        std::filesystem::path file; // absolute
        std::uint64_t hash = 0;     // contentHash of the bytes read (core/common/ContentHash.h)
        bool hashed = false;        // false: noted without its bytes
        bool operator==(const Read&) const = default;
    };
    // Each file once (with the hash of its first read), in the order first noted.
    std::vector<Read> read() const;
    std::vector<std::filesystem::path> referenced() const; // absolute

  private:
    friend void noteWatched(const std::filesystem::path&, const std::string_view*, bool);
    std::vector<Read> read_;                        // guarded by the registry's mutex
    std::vector<std::filesystem::path> referenced_; // likewise
};

// Called by the readers for every file they read, with the bytes read when they have them (for
// InputWatch); no-op without a recording or a watch. Thread-safe.
void noteInputFile(const std::filesystem::path& file);
void noteInputFile(const std::filesystem::path& file, std::string_view bytes);
// A folder whose listing was an input (reduce --visemes DIR): outputs may not go into it.
void noteInputFolder(const std::filesystem::path& folder);

// A file an input of the run names (a project's mesh files and avatar, whether or not this run reads
// them): outputs may neither replace it nor be a folder holding it. No-op without a recording.
void noteReferencedFile(const std::filesystem::path& file);

// A command that updates `file` in place (refine --project P --save) releases it: it is no longer an
// input writers refuse. Other inputs stay protected. No-op without a recording.
void allowUpdatingInPlace(const std::filesystem::path& file);

// Throws OutputOverwritesInputError "<destination>: ..." when `destination` (after following
// symlinks) is a recorded input file, OutputRefusedError when it is a referenced file. `what` names
// the output in the message ("--out", "report").
void refuseOverwritingInput(const std::filesystem::path& destination, std::string_view what = "output");
// The same for a folder outputs are written into: refused when it is a recorded input folder.
void refuseWritingIntoInputFolder(const std::filesystem::path& folder,
                                  std::string_view what = "output folder");
// Throws OutputRefusedError when an input or referenced file lies inside `folder` (at any depth): a
// folder output replaces its folder as a whole (core/common/OutputSet.h).
void refuseFolderHoldingInputs(const std::filesystem::path& folder, std::string_view what = "output folder");

} // namespace vl
