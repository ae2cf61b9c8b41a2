#pragma once
// The resume rule of `visemelab batch` (docs/batch.md): a job is done, and skipped, when its stamp
// (<out>/.visemelab-batch/<id>.done, written after its outputs) records the same job (hash of its
// fields) and outputs, every output exists, and no input the job's run read is newer than its
// oldest output. A job killed before its stamp, edited since, or whose inputs changed runs again.
#include "core/batch/BatchJob.h"

#include <filesystem>
#include <vector>

namespace vl::batch {

std::filesystem::path stampPath(const std::filesystem::path& outFolder, const BatchJob& job);

// The stamp's bytes: the job's hash, its outputs and the inputs its run read (absolute).
std::string formatStamp(const BatchJob& job, const std::vector<std::filesystem::path>& inputs);

// True when the job is done by the rule above. Never throws (anything unreadable: not done).
bool jobIsDone(const std::filesystem::path& outFolder, const BatchJob& job);

} // namespace vl::batch
