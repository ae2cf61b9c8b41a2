#pragma once
// The loaded things jobs of a batch share (core/batch/BatchContext.h): speaking faces, avatars with
// their scans, the bundled frequency tables and the fresh-process speech. Each entry is loaded once,
// by the first job that needs it, while the others needing it wait; a load that fails is kept as its
// error, so every job naming a broken file reports it without loading it again. Keys are absolute
// paths with the content hash of the files (and the options the load depends on).
#include "core/batch/BatchContext.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/phonetics/EspeakFreshSynthesis.h"
#include "core/project/AvatarReduceRun.h"
#include "core/project/SpeakingFace.h"

#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace vl::batch {

struct SayJob;

// A shared entry and the files its load read or referenced (for the resume rule).
template <class T> struct Shared {
    std::shared_ptr<const T> value;
    std::vector<std::filesystem::path> inputs;
};

struct LoadedAvatar {
    GltfDocument doc;
    AvatarScan scan;
};

class BatchCaches {
  public:
    explicit BatchCaches(const BatchOptions& options);
    ~BatchCaches();

    // Throws what the load threw (the same error for every job asking).
    Shared<SpeakingFace> face(const SayJob& job);
    Shared<LoadedAvatar> avatar(const std::filesystem::path& file, const std::string& targets);
    const BundledFrequencies& bundledFrequencies();
    const FreshSpeech& speech();

    std::size_t loads() const; // entries loaded so far (tests: shared, not reloaded)

  private:
    struct Slot;
    // The entry of `key`, loading it with `load` (outside the table's lock) when absent.
    std::shared_ptr<const void> entry(const std::string& key, std::vector<std::filesystem::path>& inputs,
                                      const std::function<std::shared_ptr<const void>()>& load);

    const BatchOptions& options_;
    mutable std::mutex mutex_;
    std::map<std::string, std::shared_ptr<Slot>> slots_;
    std::once_flag speechOnce_, bundledOnce_;
    std::unique_ptr<FreshSpeech> speech_;
    std::exception_ptr speechError_;
    BundledFrequencies bundled_;
    std::exception_ptr bundledError_;
};

} // namespace vl::batch
