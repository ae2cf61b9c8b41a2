#include "core/batch/BatchJob.h"

#include "core/common/ContentHash.h"
#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/gltf/TargetNames.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackKeyframes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace vl::batch {

namespace {

constexpr std::size_t kMaxIdBytes = 100;
constexpr double kMaxFps = 1000; // as `say --fps`

// Reads the fields of one job object, each once, naming the line and the field in every error.
class Fields {
  public:
    Fields(const Json& object, std::string where) : object_(object), where_(std::move(where)) {}

    [[noreturn]] void fail(std::string_view field, std::string_view what) const {
        throwInputError(where_ + ": " + std::string(field), what);
    }
    const Json* find(std::string_view field) {
        used_.insert(std::string(field));
        const auto it = object_.find(std::string(field));
        return it == object_.end() ? nullptr : &*it;
    }
    bool has(std::string_view field) { return find(field) != nullptr; }

    std::string text(std::string_view field, std::string fallback = {}) {
        const Json* v = find(field);
        if (!v) return fallback;
        if (!v->is_string()) fail(field, "expected a string, got " + jsonTypeName(*v) + " " + quoteJson(*v));
        const std::string s = v->get<std::string>();
        if (s.empty()) fail(field, "is empty");
        return s;
    }
    bool flag(std::string_view field) {
        const Json* v = find(field);
        if (!v) return false;
        if (!v->is_boolean()) fail(field, "expected true or false, got " + quoteJson(*v));
        return v->get<bool>();
    }
    int positiveInt(std::string_view field) {
        const Json* v = find(field);
        if (!v) return 0;
        if (!v->is_number_integer() || v->get<std::int64_t>() < 1 ||
            v->get<std::int64_t>() > std::numeric_limits<int>::max())
            fail(field, "expected a whole number >= 1, got " + quoteJson(*v));
        return static_cast<int>(v->get<std::int64_t>());
    }
    double positive(std::string_view field, double fallback) {
        const Json* v = find(field);
        if (!v) return fallback;
        if (!v->is_number() || !(v->get<double>() > 0) || !std::isfinite(v->get<double>()))
            fail(field, "expected a number > 0, got " + quoteJson(*v));
        return v->get<double>();
    }
    std::vector<std::string> names(std::string_view field) {
        std::vector<std::string> out;
        const Json* v = find(field);
        if (!v) return out;
        if (!v->is_array()) fail(field, "expected an array of viseme names, got " + quoteJson(*v));
        for (const Json& name : *v) {
            if (!name.is_string() || name.get<std::string>().empty())
                fail(field, "expected viseme names, got " + quoteJson(name));
            out.push_back(name.get<std::string>());
        }
        return out;
    }
    // Pairs as "A,B" (as on the command line) or ["A", "B"].
    std::vector<std::pair<std::string, std::string>> pairs(std::string_view field) {
        std::vector<std::pair<std::string, std::string>> out;
        const Json* v = find(field);
        if (!v) return out;
        if (!v->is_array()) fail(field, "expected an array of viseme pairs, got " + quoteJson(*v));
        for (const Json& pair : *v) {
            if (pair.is_array() && pair.size() == 2 && pair[0].is_string() && pair[1].is_string() &&
                !pair[0].get<std::string>().empty() && !pair[1].get<std::string>().empty()) {
                out.emplace_back(pair[0].get<std::string>(), pair[1].get<std::string>());
                continue;
            }
            const std::string s = pair.is_string() ? pair.get<std::string>() : std::string();
            const auto comma = s.find(',');
            if (comma == std::string::npos || comma == 0 || comma + 1 == s.size() ||
                s.find(',', comma + 1) != std::string::npos)
                fail(field, "expected two viseme names as \"A,B\" or [\"A\", \"B\"], got " + quoteJson(pair));
            out.emplace_back(s.substr(0, comma), s.substr(comma + 1));
        }
        return out;
    }
    // An output: a path relative to the output folder, true (the default name), false or absent
    // (none; `required`: the default name).
    std::string output(std::string_view field, const std::string& defaultName, bool required = false) {
        const Json* v = find(field);
        if (!v) return required ? defaultName : std::string();
        if (v->is_boolean()) {
            if (!v->get<bool>() && required) fail(field, "this output is always written");
            return v->get<bool>() ? defaultName : std::string();
        }
        if (!v->is_string())
            fail(field, "expected a path in the output folder or true, got " + quoteJson(*v));
        const std::filesystem::path path(v->get<std::string>());
        if (path.empty() || path.is_absolute())
            fail(field, "must be a path relative to the output folder, got " + quoteJson(*v));
        for (const auto& part : path)
            if (part == ".." || part == "." || part.string().starts_with("."))
                fail(field, "must stay inside the output folder (no '..', '.' or hidden names), got " +
                                quoteJson(*v));
        if (path.generic_string().ends_with("/"))
            fail(field, "names a folder; give a file name, got " + quoteJson(*v));
        return path.generic_string();
    }
    // Every field of the object was read: anything else is a typo.
    void requireAllUsed() const {
        for (const auto& [key, value] : object_.items())
            if (!used_.count(key))
                fail(key, "not a field of a " + command_ + " job (docs/batch.md lists them)");
    }
    void setCommand(std::string command) { command_ = std::move(command); }

  private:
    const Json& object_;
    std::string where_;
    std::set<std::string> used_;
    std::string command_;
};

std::filesystem::path inputPath(const std::string& field, const std::filesystem::path& folder) {
    if (field.empty()) return {};
    return (folder / field).lexically_normal();
}

// The designer's constraints, as `--pin`, `--apart`, `--together`, `--max-error-mm` and `--closure`
// ("none": no closure rule).
void readConstraints(Fields& f, ConstraintNames& constraints, double& maxErrorMm, std::string& closure) {
    constraints.pinned = f.names("pin");
    constraints.apart = f.pairs("apart");
    constraints.together = f.pairs("together");
    maxErrorMm = f.positive("max-error-mm", 0);
    closure = f.text("closure", "auto");
    if (closure == "none") closure.clear();
}

void parseSay(Fields& f, const std::filesystem::path& folder, const std::string& id, SayJob& s) {
    s.text = f.text("text");
    if (s.text.empty()) f.fail("text", "missing: the text to say");
    if (!isValidUtf8(s.text)) f.fail("text", "not UTF-8 text");
    s.project = inputPath(f.text("project"), folder);
    s.avatar = inputPath(f.text("avatar"), folder);
    s.reduced = inputPath(f.text("reduced"), folder);
    s.targets = f.text("targets");
    s.target = f.positiveInt("m");
    readConstraints(f, s.constraints, s.maxErrorMm, s.closure);
    s.map = inputPath(f.text("map"), folder);
    s.voice = f.text("voice", "en-us");
    if (const Json* rate = f.find("rate")) {
        if (!rate->is_number_integer()) f.fail("rate", "expected words per minute as a whole number");
        s.rate = rate->get<int>();
    }
    s.fps = f.positive("fps", 60);
    if (s.fps > kMaxFps) f.fail("fps", "must be in (0, 1000]");
    s.blend = f.text("blend", "cubic");
    if (!fromString<runtime::Interpolation>(s.blend))
        f.fail("blend", "must be linear, cubic or dominance, not '" + s.blend + "'");
    s.format = f.text("format", "oculus");
    if (!fromString<TrackFormat>(s.format))
        f.fail("format", "must be oculus, rhubarb or talkinghead, not '" + s.format + "'");
    s.out = f.output("out", id + ".json", true);
    s.wav = f.output("wav", id + ".wav");
    s.glb = f.output("glb", id + ".glb");
    for (const char* field : {"text-file", "html", "curve", "stdin", "quiet"})
        if (f.has(field))
            f.fail(field, "not available in batch jobs (use visemelab say for a corpus, pages and curves)");

    f.requireAllUsed(); // a misspelt field is named before the combinations it leaves
    if (s.project.empty() == s.avatar.empty()) f.fail("project", "give \"project\" or \"avatar\", not both");
    const bool constrained = !s.constraints.empty() || s.maxErrorMm > 0;
    if (s.avatar.empty() && (s.target > 0 || !s.reduced.empty() || !s.targets.empty() || constrained))
        f.fail("avatar", "\"m\", \"reduced\", \"targets\" and the constraints go with \"avatar\"");
    if (s.target > 0 && !s.reduced.empty()) f.fail("reduced", "give \"m\" or \"reduced\", not both");
    if (s.target > 0 && s.maxErrorMm > 0) f.fail("max-error-mm", "chooses the number of keys: drop \"m\"");
    if (constrained && !s.reduced.empty())
        f.fail("reduced", "constraints apply to a reduction in memory (\"m\" or \"max-error-mm\")");
    if (!s.avatar.empty() && !s.glb.empty() && std::filesystem::path(s.glb).extension() == ".gltf")
        f.fail("glb", "the speaking avatar is written as binary glTF; name it .glb (or .vrm)");
    if (!s.targets.empty()) checkGlobPattern(s.targets, "targets");
}

void parseReduce(Fields& f, const std::filesystem::path& folder, const std::string& id, AvatarReduceJob& r) {
    r.input = inputPath(f.text("input"), folder);
    if (r.input.empty()) f.fail("input", "missing: the avatar file to reduce");
    r.target = f.positiveInt("m");
    r.targets = f.text("targets");
    r.freqFile = inputPath(f.text("freq-file"), folder);
    r.mapFile = inputPath(f.text("map"), folder);
    r.weights = f.text("weights", "uniform");
    if (r.weights == "painted") f.fail("weights", "painted weights need a file: give its path");
    if (r.weights != "uniform" && r.weights != "area") r.weights = inputPath(r.weights, folder).string();
    r.names = f.text("names", "original");
    if (r.names != "original" && r.names != "merged") f.fail("names", "must be original or merged");
    r.noTargetNormals = f.flag("no-target-normals");
    r.maxTargets = f.positiveInt("max-targets");
    r.gltfpack = f.flag("gltfpack");
    r.rest = f.text("rest", "free");
    if (r.rest != "free" && r.rest != "key") f.fail("rest", "must be free or key, got '" + r.rest + "'");
    r.restViseme = f.text("rest-viseme");
    readConstraints(f, r.constraints, r.maxErrorMm, r.closure);
    r.out = f.output("out", id + ".glb", true);
    r.report = f.output("report", id + ".report.json");
    f.requireAllUsed();
    if ((r.target > 0) == (r.maxErrorMm > 0))
        f.fail("m", "give the number of keys \"m\", or \"max-error-mm\" (which chooses it)");
    if (std::filesystem::path(r.out).extension() == ".gltf")
        f.fail("out", "the reduced avatar is written as binary glTF; name it .glb (or .vrm)");
    if (!r.targets.empty()) checkGlobPattern(r.targets, "targets");
}

bool validId(const std::string& id) {
    if (id.empty() || id.size() > kMaxIdBytes || id.front() == '.') return false;
    return std::all_of(id.begin(), id.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
               c == '_' || c == '-';
    });
}

} // namespace

std::string jobWhere(const std::filesystem::path& jobsFile, std::size_t line) {
    return fileLine(jobsFile.string(), line);
}

bool isBlankJobLine(std::string_view line) {
    return std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
}

std::vector<std::string> BatchJob::outputs() const {
    std::vector<std::string> out;
    if (command == JobCommand::Say) {
        for (const std::string* o : {&say.wav, &say.glb, &say.out})
            if (!o->empty()) out.push_back(*o);
    } else {
        for (const std::string* o : {&reduce.report, &reduce.out})
            if (!o->empty()) out.push_back(*o);
    }
    return out;
}

std::vector<std::filesystem::path> BatchJob::namedInputs() const {
    std::vector<std::filesystem::path> in;
    const auto add = [&](const std::filesystem::path& p) {
        if (!p.empty()) in.push_back(p);
    };
    if (command == JobCommand::Say) {
        add(say.project);
        add(say.avatar);
        add(say.reduced);
        add(say.map);
    } else {
        add(reduce.input);
        add(reduce.freqFile);
        add(reduce.mapFile);
        if (reduce.weights != "uniform" && reduce.weights != "area") add(reduce.weights);
    }
    return in;
}

BatchJob parseBatchJob(std::string_view line, std::size_t lineNumber, const std::filesystem::path& jobsFile) {
    const std::string where = jobWhere(jobsFile, lineNumber);
    const Json object = parseJsonStrict(line, where);
    if (!object.is_object()) throwInputError(where, "a job is a JSON object, got " + jsonTypeName(object));
    BatchJob job;
    job.line = lineNumber;
    Fields f(object, where);
    job.id = f.text("id");
    if (job.id.empty()) f.fail("id", "missing: every job needs an id (it names its outputs)");
    if (!validId(job.id))
        f.fail("id", "use at most 100 letters, digits, '.', '_' and '-', not starting with '.', got " +
                         quoteInput(job.id));
    const std::string command = f.text("command");
    const std::filesystem::path folder = jobsFile.parent_path();
    f.setCommand(command.empty() ? "batch" : command);
    if (command == "say") {
        job.command = JobCommand::Say;
        parseSay(f, folder, job.id, job.say);
    } else if (command == "avatar reduce") {
        job.command = JobCommand::AvatarReduce;
        parseReduce(f, folder, job.id, job.reduce);
    } else {
        f.fail("command", command.empty()
                              ? "missing: \"say\" or \"avatar reduce\""
                              : "must be \"say\" or \"avatar reduce\", got " + quoteInput(command));
    }
    f.requireAllUsed();
    // The job's meaning: its fields (in any order) and the folder its paths are relative to.
    const nlohmann::json canonical = nlohmann::json::parse(object.dump());
    std::error_code ec;
    const std::filesystem::path absoluteFolder = std::filesystem::absolute(jobsFile, ec).parent_path();
    job.hash = contentHash(canonical.dump() + "\n" + absoluteFolder.lexically_normal().string());
    std::set<std::string> seen;
    for (const std::string& output : job.outputs())
        if (!seen.insert(output).second)
            f.fail("out", "two outputs of the job are both " + quoteInput(output));
    return job;
}

} // namespace vl::batch
