#include "core/batch/BatchRun.h"

#include "core/batch/BatchCaches.h"
#include "core/batch/BatchJob.h"
#include "core/batch/BatchResume.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/JsonParse.h"
#include "core/export/ReductionOutputs.h"
#include "core/project/SpokenTrack.h"
#include "core/reduce/Weights.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackKeyframes.h"
#include "core/speech/WavFile.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <map>
#include <mutex>
#include <optional>

namespace vl::batch {

namespace {

const char* statusName(JobStatus status) {
    switch (status) {
    case JobStatus::Ok:
        return "ok";
    case JobStatus::Skipped:
        return "skipped";
    case JobStatus::Error:
        break;
    }
    return "error";
}

// The job's error with its line in front (messages of loaders already name their file).
std::string located(const std::string& where, const std::string& field, const std::string& what) {
    if (what.starts_with(where)) return what; // parse errors carry the line already
    return where + ": " + (field.empty() ? std::string() : field + ": ") + what;
}

// The id of a line that is not a valid job, when it has a string one: results name it.
std::string idOf(std::string_view line) {
    try {
        checkJsonNesting(line, "", 16); // a hostile line is not parsed again without the limit
    } catch (const InputError&) {
        return {};
    }
    const auto json = nlohmann::json::parse(line, nullptr, false);
    if (json.is_object())
        if (const auto id = json.find("id");
            id != json.end() && id->is_string() && isValidUtf8(id->get<std::string>()))
            return quoteInput(id->get<std::string>(), 100);
    return {};
}

// Outputs never replace the job's inputs (with or without an InputRecording: the Python binding
// runs jobs without one).
void refuseOutputsOverInputs(const BatchJob& job, const std::filesystem::path& outFolder,
                             const std::string& where) {
    for (const std::string& output : job.outputs())
        for (const auto& input : job.namedInputs()) {
            std::error_code ec, ec2;
            const auto o = std::filesystem::weakly_canonical(outFolder / output, ec);
            if (!ec && o == std::filesystem::weakly_canonical(input, ec2))
                throwInputError(where + ": " + output, "would overwrite the input " + input.string());
        }
}

void requireSpeech(const Utterance& utterance, const std::string& where) {
    for (const auto& p : utterance.phonemes)
        if (p.phoneme != kSilencePhoneme) return;
    throwInputError(where + ": text", "nothing to say: the text has no words espeak-ng speaks");
}

// Runs a say job; returns the inputs its run read.
std::vector<std::filesystem::path> runSay(BatchContext& context, const BatchJob& job,
                                          const std::string& where) {
    const SayJob& s = job.say;
    const std::filesystem::path& out = context.options().outFolder;
    const std::string culprit = s.avatar.empty() ? "project" : "avatar";
    Shared<SpeakingFace> face;
    try {
        face = context.caches().face(s);
    } catch (const InputError& e) {
        throwInputError(where + ": " + culprit, e.what());
    }
    FreshSpeech::Spoken spoken;
    try {
        spoken = context.caches().speech().speak({s.voice, s.rate}, s.text);
    } catch (const InputError& e) {
        throwInputError(where + ": voice/rate", e.what());
    }
    requireSpeech(spoken.utterance, where);
    const auto interpolation = *fromString<runtime::Interpolation>(s.blend);
    const SpokenTrackOptions options{out / s.out,
                                     s.wav.empty() ? std::filesystem::path() : out / s.wav,
                                     "",
                                     s.voice,
                                     s.rate,
                                     s.project.string(),
                                     interpolation,
                                     s.fps};
    const SpokenTrack track = spokenTrack(*face.value, spoken.utterance, options, s.text);
    const std::string trackText =
        formatTrack(track.file, *fromString<TrackFormat>(s.format), (out / s.out).string());
    // Written as `say` writes them: the track last.
    if (!s.wav.empty())
        writeFileAtomically(out / s.wav, formatWav(spoken.utterance.samples, spoken.utterance.sampleRate));
    if (!s.glb.empty()) writeFileAtomically(out / s.glb, spokenGlb(*face.value, track, s.fps));
    writeFileAtomically(out / s.out, trackText);
    return face.inputs;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::filesystem::path> runReduce(BatchContext& context, const BatchJob& job,
                                             const std::string& where) {
    const AvatarReduceJob& r = job.reduce;
    const std::filesystem::path& out = context.options().outFolder;
    AvatarReduceRequest request;
    request.target = r.target;
    request.maxErrorMm = r.maxErrorMm;
    request.targets = r.targets;
    request.freqFile = r.freqFile;
    request.mapFile = r.mapFile;
    if (const auto mode = fromString<WeightMode>(r.weights)) {
        request.weightMode = *mode;
    } else {
        request.weightMode = WeightMode::Painted;
        request.paintedWeights = loadWeightsFile(r.weights);
        request.paintedWeightsSource = r.weights;
    }
    request.rest = r.rest == "key" ? RestChoice::Key : RestChoice::Free;
    request.restViseme = r.restViseme;
    request.constraints = r.constraints;
    request.closure = r.closure;
    request.write.names = r.names == "merged" ? AvatarNames::Merged : AvatarNames::Original;
    request.write.targetNormals = !r.noTargetNormals;
    request.write.maxTargets = r.maxTargets;
    request.gltfpack = r.gltfpack;

    const auto t0 = std::chrono::steady_clock::now();
    Shared<LoadedAvatar> avatar;
    try {
        avatar = context.caches().avatar(r.input, r.targets);
    } catch (const InputError& e) {
        throwInputError(where + ": input", e.what());
    }
    const AvatarScan& scan = avatar.value->scan;
    std::string chosen;
    const FrequencySource frequencies =
        avatarReduceFrequencies(request, scan, context.caches().bundledFrequencies(), chosen);
    ReduceTimings timings;
    timings.loadMs = millisecondsSince(t0);
    const auto t1 = std::chrono::steady_clock::now();
    AvatarReduceResult run = runAvatarReduce(avatar.value->doc, scan, frequencies, request);
    timings.reduceMs = millisecondsSince(t1);
    const auto t2 = std::chrono::steady_clock::now();
    // The report first, the avatar last: the main output is there only when the job is whole.
    const std::string outPath = (out / r.out).string();
    if (!r.report.empty()) {
        timings.writeMs = millisecondsSince(t2);
        writeFileAtomically(out / r.report,
                            avatarReductionReport(run.reduction, scan, run.settings, request.write, timings,
                                                  r.input.string(), outPath));
    }
    writeFileAtomically(outPath, run.reduction.glb);
    return avatar.inputs;
}

// The files a stamp records: the job's named inputs and what its shared loads read, without the
// speech cache (rewritten by other runs, it is not an input of the job's bytes).
std::vector<std::filesystem::path> stampInputs(const BatchContext& context, const BatchJob& job,
                                               const std::vector<std::filesystem::path>& read) {
    std::vector<std::filesystem::path> inputs = job.namedInputs();
    std::error_code ec;
    const std::string cache =
        context.options().speechCacheFolder.empty()
            ? std::string()
            : std::filesystem::absolute(context.options().speechCacheFolder, ec).string();
    for (const auto& file : read)
        if (cache.empty() || !file.string().starts_with(cache)) inputs.push_back(file);
    return inputs;
}

} // namespace

std::string JobResult::json() const {
    nlohmann::ordered_json j{
        {"line", line}, {"id", id}, {"status", statusName(status)}, {"outputs", outputs}};
    if (status == JobStatus::Error) j["error"] = error;
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

JobResult runBatchJob(BatchContext& context, std::string_view line, std::size_t lineNumber) {
    JobResult result;
    result.line = lineNumber;
    const BatchOptions& options = context.options();
    const std::string where = jobWhere(options.jobsFile, lineNumber);
    try {
        const BatchJob job = parseBatchJob(line, lineNumber, options.jobsFile);
        result.id = job.id;
        refuseOutputsOverInputs(job, options.outFolder, where);
        if (options.resume && jobIsDone(options.outFolder, job)) {
            result.status = JobStatus::Skipped;
            result.outputs = job.outputs();
            return result;
        }
        const auto read =
            job.command == JobCommand::Say ? runSay(context, job, where) : runReduce(context, job, where);
        writeFileAtomically(stampPath(options.outFolder, job),
                            formatStamp(job, stampInputs(context, job, read)));
        result.outputs = job.outputs();
    } catch (const InputError& e) {
        result.status = JobStatus::Error;
        result.error = located(where, "", e.what());
        if (result.id.empty()) result.id = idOf(line);
    } catch (const std::bad_alloc&) {
        result.status = JobStatus::Error;
        result.error = where + ": out of memory (the job's input is too large for this machine)";
    } catch (const std::exception& e) {
        result.status = JobStatus::Error;
        result.internal = true;
        result.error = where + ": internal error: " + e.what();
    }
    if (result.status == JobStatus::Error) result.outputs.clear();
    return result;
}

std::string runBatchJobLine(BatchContext& context, std::string_view line, std::size_t lineNumber) {
    return runBatchJob(context, line, lineNumber).json();
}

std::vector<std::string> readJobLines(const std::filesystem::path& jobsFile) {
    const std::string text = readFileToString(jobsFile);
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.emplace_back(text, start, end - start);
        if (!isValidUtf8(lines.back()))
            throwInputError(fileLine(jobsFile.string(), lines.size()), "not UTF-8 text");
        start = end + 1;
    }
    return lines;
}

BatchSummary runBatchLines(BatchContext& context, std::span<const std::string> lines,
                           const ResultSink& onResult, const BatchProgress& progress) {
    // The jobs (blank lines hold none), and the lines whose outputs an earlier job already names.
    std::vector<std::size_t> jobs;
    std::map<std::size_t, std::string> collisions; // job index -> error
    std::map<std::string, std::size_t> owner;      // output -> line
    bool speaks = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (isBlankJobLine(lines[i])) continue;
        jobs.push_back(i);
        try {
            const BatchJob job = parseBatchJob(lines[i], i + 1, context.options().jobsFile);
            speaks = speaks || job.command == JobCommand::Say;
            for (const std::string& output : job.outputs()) {
                const auto [it, added] = owner.emplace(output, i + 1);
                if (!added && !collisions.count(jobs.size() - 1))
                    collisions[jobs.size() - 1] = jobWhere(context.options().jobsFile, i + 1) +
                                                  ": out: " + quoteInput(output) +
                                                  " is also an output of line " + std::to_string(it->second);
            }
        } catch (const std::exception&) {
            // Reported by the job's own run.
        }
    }
    // The speech helper is forked before the workers start (core/phonetics/EspeakFreshSynthesis.h).
    if (speaks) try {
            context.caches().speech();
        } catch (const std::exception&) {
            // Each say job reports it.
        }

    BatchSummary summary;
    std::mutex emitting;
    std::vector<std::optional<JobResult>> results(jobs.size());
    std::size_t next = 0, done = 0;
    tbb::parallel_for(std::size_t(0), jobs.size(), [&](std::size_t k) {
        JobResult result;
        if (const auto c = collisions.find(k); c != collisions.end()) {
            result.line = jobs[k] + 1;
            result.status = JobStatus::Error;
            result.error = c->second;
            try {
                result.id = parseBatchJob(lines[jobs[k]], jobs[k] + 1, context.options().jobsFile).id;
            } catch (const InputError&) {
            }
        } else {
            result = runBatchJob(context, lines[jobs[k]], jobs[k] + 1);
        }
        std::lock_guard lock(emitting);
        results[k] = std::move(result);
        ++done;
        for (; next < jobs.size() && results[next]; ++next) {
            const JobResult& r = *results[next];
            switch (r.status) {
            case JobStatus::Ok:
                ++summary.ok;
                break;
            case JobStatus::Skipped:
                ++summary.skipped;
                break;
            case JobStatus::Error:
                ++(r.internal ? summary.internalErrors : summary.errors);
                break;
            }
            if (onResult) onResult(r);
            results[next].reset();
        }
        if (progress) progress(done, jobs.size());
    });
    return summary;
}

} // namespace vl::batch
