// visemelab.run_jobs: lines of a JOBS.jsonl run by core/batch as `visemelab batch` runs them, with one
// context per process and per (jobs file, output folder): a Dask worker that gets many chunks of the
// same batch loads each project, avatar and speaking face once (the context's caches check the
// files' content, so a file replaced between chunks is loaded again).
#include "app/python/src/Bindings.h"
#include "core/batch/BatchContext.h"
#include "core/batch/BatchJob.h"
#include "core/batch/BatchRun.h"
#include "core/project/SpeechCache.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <tbb/task_arena.h>

#include <map>
#include <mutex>
#include <tuple>

namespace py = pybind11;

namespace vl::python {

namespace {

using ContextKey = std::tuple<std::filesystem::path, std::filesystem::path, bool>;

// Kept for the life of the process (a worker's whole point is to keep what it loaded).
batch::BatchContext& contextFor(const std::filesystem::path& jobsFile, const std::filesystem::path& outFolder,
                                bool resume) {
    static std::mutex mutex;
    static std::map<ContextKey, std::unique_ptr<batch::BatchContext>> contexts;
    const std::scoped_lock lock(mutex);
    auto& context = contexts[ContextKey{jobsFile, outFolder, resume}];
    if (!context) {
        batch::BatchOptions options;
        options.jobsFile = jobsFile;
        options.outFolder = outFolder;
        options.assetsDir = VISEMELAB_ASSETS_DIR;
        options.resume = resume;
        options.speechCacheFolder = speechCacheFolder();
        context = std::make_unique<batch::BatchContext>(std::move(options));
    }
    return *context;
}

std::string withoutNewline(std::string line) {
    if (!line.empty() && line.back() == '\n') line.pop_back();
    return line;
}

// The result lines of `lines`, numbered from `firstLine` in the jobs file, in line order (blank lines
// hold no job and get none). threads 1: in the calling thread, one job after the other (a Dask worker
// thread); 0: all cores, as `visemelab batch`.
std::vector<std::string> runJobs(const std::vector<std::string>& lines,
                                 const std::filesystem::path& outFolder,
                                 const std::filesystem::path& jobsFile, std::size_t firstLine, int threads,
                                 bool resume) {
    if (firstLine < 1) throw py::value_error("first_line is 1-based");
    if (threads < 0) throw py::value_error("threads must be >= 0 (0: all cores)");
    std::vector<std::string> results;
    py::gil_scoped_release release;
    batch::BatchContext& context = contextFor(jobsFile, outFolder, resume);
    if (threads == 1) {
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (!batch::isBlankJobLine(lines[i]))
                results.push_back(withoutNewline(batch::runBatchJobLine(context, lines[i], firstLine + i)));
        return results;
    }
    // runBatchLines numbers its lines from 1: blank lines in front (no jobs) keep the file's numbers.
    std::vector<std::string> numbered(firstLine - 1);
    numbered.insert(numbered.end(), lines.begin(), lines.end());
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : threads);
    arena.execute([&] {
        batch::runBatchLines(context, numbered, [&](const batch::JobResult& result) {
            results.push_back(withoutNewline(result.json()));
        });
    });
    return results;
}

} // namespace

void bindBatch(py::module_& m) {
    m.def("run_jobs", &runJobs, py::arg("lines"), py::arg("out_dir"), py::arg("jobs_file"), py::kw_only(),
          py::arg("first_line") = 1, py::arg("threads") = 0, py::arg("resume") = true,
          "Runs lines of a JOBS.jsonl file as `visemelab batch JOBS --out OUT_DIR` does (outputs written "
          "the same way, the same result lines, in line order, without their newline). jobs_file names "
          "the file the lines come from: relative input paths are read from its folder and messages "
          "name it. first_line is the jobs-file line number of lines[0]. threads: 1 runs the jobs one "
          "after the other in the calling thread (a Dask worker's), 0 on all cores. The loaded "
          "projects, avatars and faces stay cached in this process for the next call");
}

} // namespace vl::python
