#pragma once
// Running the jobs of a JOBS.jsonl file (`visemelab batch`, docs/batch.md). Each job writes its
// outputs by the single commands' protocol (atomic, never over an input) and yields one result
// line; a failing job never stops the others.
//
//   {"line":3,"id":"hello","status":"ok","outputs":["hello.json","hello.wav"]}
//   {"line":4,"id":"bad","status":"error","outputs":[],"error":"jobs.jsonl:4: project: ..."}
//   {"line":5,"id":"rpm6","status":"skipped","outputs":["rpm6.glb"]}
//
// Results carry no timings, so two runs' results compare byte for byte.
#include "core/batch/BatchContext.h"

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl::batch {

enum class JobStatus { Ok, Error, Skipped };

struct JobResult {
    std::size_t line = 0;
    std::string id; // empty when the line has none
    JobStatus status = JobStatus::Ok;
    std::vector<std::string> outputs; // relative to the output folder
    std::string error;                // with Error: "<jobs file>:<line>: <culprit>: <what>"
    bool internal = false;            // with Error: not bad input but a fault (exit code 1)

    // One JSON line, ending in "\n".
    std::string json() const;
};

// Runs the job on line `lineNumber` (1-based) of the jobs file: parse, skip when done (resume),
// else run and write its outputs. Never throws for a bad job: its error is the result.
JobResult runBatchJob(BatchContext& context, std::string_view line, std::size_t lineNumber);

// The same, as its result line (JobResult::json()): what the Python binding and cluster workers
// call per line.
std::string runBatchJobLine(BatchContext& context, std::string_view line, std::size_t lineNumber);

struct BatchSummary {
    std::size_t ok = 0, skipped = 0, errors = 0, internalErrors = 0;
    std::size_t jobs() const { return ok + skipped + errors + internalErrors; }
};

// Called with each job's result in line order (results are held until every earlier line's is
// out), from one thread at a time.
using ResultSink = std::function<void(const JobResult& result)>;
// Called after each finished job with (jobs finished, jobs in all); from one thread at a time.
using BatchProgress = std::function<void(std::size_t done, std::size_t total)>;

// Runs every job of `lines` (line i is line i + 1 of the jobs file; blank lines hold no job) on all
// cores (TBB). Two jobs naming the same output: the later one fails, naming the earlier line.
BatchSummary runBatchLines(BatchContext& context, std::span<const std::string> lines,
                           const ResultSink& onResult, const BatchProgress& progress = {});

// Reads the jobs file into lines (InputError naming it when it cannot be read or is not UTF-8).
std::vector<std::string> readJobLines(const std::filesystem::path& jobsFile);

} // namespace vl::batch
