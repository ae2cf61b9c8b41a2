// `visemelab batch JOBS.jsonl --out DIR [--results FILE]`: every job of the file (say, avatar reduce)
// on all cores with shared loads (core/batch, docs/batch.md). One result line per job, in line
// order, on the standard output (or --results); a progress bar on stderr when it is a terminal.
// Exit 0 when every job succeeded (or was already done), 3 when a job's input was bad, 1 when a
// job failed for an internal reason.
#include "app/cli/Command.h"
#include "app/cli/StandardOutput.h"
#include "core/batch/BatchRun.h"
#include "core/common/AtomicFileWriter.h"
#include "core/common/Error.h"
#include "core/common/OutputPolicy.h"
#include "core/project/SpeechCache.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <unistd.h>

namespace vl::cli {

namespace {

struct BatchCommandOptions {
    std::string jobs;
    std::string out;
    std::string results;
    bool noResume = false;
};

// "\r[=====     ] 512/1000 jobs" on a terminal's stderr.
void drawProgress(std::size_t done, std::size_t total) {
    constexpr int kWidth = 30;
    const int filled = total == 0 ? kWidth : static_cast<int>(kWidth * done / total);
    std::fprintf(stderr, "\r[%s%s] %zu/%zu jobs", std::string(static_cast<std::size_t>(filled), '=').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), ' ').c_str(), done, total);
    if (done == total) std::fprintf(stderr, "\r%*s\r", kWidth + 40, "");
    std::fflush(stderr);
}

int runBatch(const BatchCommandOptions& o) {
    if (isStandardOutput(o.out)) throwUsage("--out is a folder; it cannot be the standard output");
    std::error_code ec;
    if (std::filesystem::exists(o.out, ec) && !std::filesystem::is_directory(o.out, ec))
        throwUsage("--out " + o.out + " is a file; name a folder");
    batch::BatchOptions options;
    options.jobsFile = o.jobs;
    options.outFolder = o.out;
    options.assetsDir = VISEMELAB_ASSETS_DIR;
    options.resume = !o.noResume;
    options.speechCacheFolder = speechCacheFolder();
    const std::vector<std::string> lines = batch::readJobLines(o.jobs);
    batch::BatchContext context(options);

    std::optional<AtomicFileWriter> file;
    if (!o.results.empty() && !isStandardOutput(o.results)) file.emplace(o.results);
    const bool claimed = isStandardOutput(o.results);
    const batch::ResultSink sink = [&](const batch::JobResult& result) {
        const std::string text = result.json();
        if (file) {
            file->write(text);
        } else if (claimed) {
            writeToStandardOutput(text);
        } else {
            std::fwrite(text.data(), 1, text.size(), stdout);
            std::fflush(stdout); // a killed batch leaves every result it reported
        }
    };
    const bool terminal = ::isatty(STDERR_FILENO) != 0;
    const batch::BatchSummary summary =
        batch::runBatchLines(context, lines, sink, terminal ? batch::BatchProgress(drawProgress) : nullptr);
    if (file) file->commit();
    std::fprintf(stderr, "batch: %zu jobs: %zu ok, %zu skipped (done before), %zu failed%s%s\n",
                 summary.jobs(), summary.ok, summary.skipped, summary.errors + summary.internalErrors,
                 file ? "; results in " : "", file ? o.results.c_str() : "");
    if (summary.internalErrors > 0) return 1;
    return summary.errors > 0 ? kExitInvalidInput : kExitOk;
}

} // namespace

void addBatchCommand(CLI::App& app, CommandRunner& run) {
    auto o = std::make_shared<BatchCommandOptions>();
    auto* cmd = app.add_subcommand(
        "batch", "Run a JOBS.jsonl file of say and avatar reduce jobs on all cores (docs/batch.md): "
                 "resumable, one JSON result line per job");
    cmd->add_option("jobs", o->jobs, "JSON lines, one job per line; input paths relative to its folder")
        ->required();
    cmd->add_option("--out", o->out, "Output folder: job outputs are named relative to it")->required();
    cmd->add_option("--results", o->results,
                    "Write the result lines to this file (atomically, at the end) instead of the standard "
                    "output");
    cmd->add_flag("--no-resume", o->noResume, "Run every job, also those whose outputs are done");
    cmd->callback([&run, o] { run = [o] { return runBatch(*o); }; });
}

} // namespace vl::cli
