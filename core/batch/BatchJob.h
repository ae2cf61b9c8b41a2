#pragma once
// One line of a JOBS.jsonl file (`visemelab batch`, docs/batch.md): a JSON object that is a `say`
// job or an `avatar reduce` job with the options of the single command, named by an `id` that gives
// its outputs stable default names. Paths of inputs are relative to the jobs file's folder, paths of
// outputs relative to the output folder (and must stay inside it).
//
//   {"id": "hello", "command": "say", "text": "Hello there.", "project": "sample.vlproj",
//    "wav": true, "glb": "faces/hello.glb"}
//   {"id": "rpm6", "command": "avatar reduce", "input": "rpm.glb", "m": 6, "pin": ["viseme_PP"]}
//
// An output field is a path or `true` (the id with the format's extension); the main output (say:
// "out", the track; avatar reduce: "out", the avatar) defaults to `true`.
#include "core/reduce/ReductionConstraints.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl::batch {

enum class JobCommand { Say, AvatarReduce };

// `visemelab say TEXT` options a job can give (docs/batch.md lists the fields). Input paths are
// resolved against the jobs file's folder; output paths are relative to the output folder.
struct SayJob {
    std::string text;
    std::filesystem::path project; // or
    std::filesystem::path avatar;
    std::filesystem::path reduced; // with avatar
    std::string targets;           // with avatar
    int target = 0;                // with avatar: "m"
    ConstraintNames constraints;   // with avatar: "pin", "apart", "together"
    double maxErrorMm = 0;         // with avatar: "max-error-mm"
    std::string closure = "auto";  // with avatar: "closure" ("none" -> no closure rule)
    std::filesystem::path map;
    std::string voice = "en-us";
    int rate = 175;
    double fps = 60;
    std::string blend = "cubic";
    std::string format = "oculus";
    std::string out; // the track, relative to the output folder
    std::string wav; // optional outputs ("" = not written)
    std::string glb;
};

// `visemelab avatar reduce INPUT` options a job can give.
struct AvatarReduceJob {
    std::filesystem::path input;
    int target = 0; // "m"
    std::string targets;
    std::filesystem::path freqFile;
    std::filesystem::path mapFile;
    std::string weights = "uniform"; // uniform, area or a weights file (resolved like inputs)
    std::string names = "original";  // or merged
    bool noTargetNormals = false;
    int maxTargets = 0;
    bool gltfpack = false;
    std::string rest = "free"; // or key
    std::string restViseme;
    ConstraintNames constraints;
    double maxErrorMm = 0;
    std::string closure = "auto";
    std::string out;    // the reduced avatar, relative to the output folder
    std::string report; // optional JSON report
};

struct BatchJob {
    std::size_t line = 0; // 1-based line of the jobs file
    std::string id;       // letters, digits, '.', '_', '-'; not starting with '.'
    JobCommand command = JobCommand::Say;
    SayJob say;
    AvatarReduceJob reduce;
    std::uint64_t hash = 0; // of the job's canonical JSON: a changed job is never skipped as done

    // The outputs, relative to the output folder, the main one last (it is written last).
    std::vector<std::string> outputs() const;
    // The files the job names as inputs (absolute or relative to the working folder as resolved).
    std::vector<std::filesystem::path> namedInputs() const;
};

// "<jobs file>:<line>": the start of every message about a job.
std::string jobWhere(const std::filesystem::path& jobsFile, std::size_t line);

// Parses one line. Throws InputError "<jobs file>:<line>: <field>: <what>" for text that is not a
// JSON object, an unknown or misspelt field, a value of the wrong type or range, a missing or bad
// id, an output outside the output folder or naming an input, and option combinations the single
// command refuses.
BatchJob parseBatchJob(std::string_view line, std::size_t lineNumber, const std::filesystem::path& jobsFile);

// True for a line that holds no job (empty or white space): it gets no result.
bool isBlankJobLine(std::string_view line);

} // namespace vl::batch
