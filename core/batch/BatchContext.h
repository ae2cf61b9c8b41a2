#pragma once
// What the jobs of one batch share: the options (jobs file, output folder, bundled assets) and the
// loaded projects, avatars and speaking faces, each loaded once by whichever job needs it first and
// kept for the others. Entries are keyed by the file's absolute path and its content hash plus the
// options the load depends on, never by address: a file replaced during the batch is loaded again.
// Thread-safe: the jobs of runBatchLines use one context from all cores.
#include <cstdint>
#include <filesystem>
#include <memory>

namespace vl::batch {

struct BatchOptions {
    std::filesystem::path jobsFile;  // input paths in jobs are relative to its folder
    std::filesystem::path outFolder; // output paths in jobs are relative to it
    std::filesystem::path assetsDir; // the bundled phoneme tables and maps (VISEMELAB_ASSETS_DIR)
    bool resume = true;              // skip jobs whose outputs are done (docs/batch.md)
    // Where `say` jobs' project faces are cached between runs (core/project/SpeechCache.h); empty:
    // no cache file.
    std::filesystem::path speechCacheFolder;
};

class BatchCaches; // defined in BatchCaches.h

class BatchContext {
  public:
    explicit BatchContext(BatchOptions options);
    ~BatchContext();
    BatchContext(const BatchContext&) = delete;
    BatchContext& operator=(const BatchContext&) = delete;

    const BatchOptions& options() const { return options_; }
    BatchCaches& caches() { return *caches_; }

  private:
    BatchOptions options_;
    std::unique_ptr<BatchCaches> caches_;
};

} // namespace vl::batch
