// Parsing one JOBS.jsonl line: defaults, paths, and errors that name the line and the field.
#include "core/batch/BatchJob.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <string>

namespace vl::batch {
namespace {

const std::filesystem::path kJobs = "jobs/list.jsonl";

// The InputError message parsing `line` (as line 7) throws, or "" when it parses.
std::string errorOf(const std::string& line) {
    try {
        parseBatchJob(line, 7, kJobs);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

TEST(BatchJob, SayDefaultsNameOutputsAfterTheIdAndResolveInputsBesideTheJobsFile) {
    const BatchJob job = parseBatchJob(
        R"({"id":"j-1","command":"say","text":"Hello.","project":"p/a.vlproj","wav":true})", 3, kJobs);
    EXPECT_EQ(job.line, 3u);
    EXPECT_EQ(job.command, JobCommand::Say);
    EXPECT_EQ(job.say.project, std::filesystem::path("jobs/p/a.vlproj"));
    EXPECT_EQ(job.say.voice, "en-us");
    EXPECT_EQ(job.say.rate, 175);
    EXPECT_EQ(job.say.out, "j-1.json");
    EXPECT_EQ(job.say.wav, "j-1.wav");
    EXPECT_TRUE(job.say.glb.empty());
    EXPECT_EQ(job.outputs(), (std::vector<std::string>{"j-1.wav", "j-1.json"})); // the track last
    EXPECT_EQ(job.namedInputs(), (std::vector<std::filesystem::path>{"jobs/p/a.vlproj"}));
}

TEST(BatchJob, AvatarReduceTakesTheCommandsOptions) {
    const BatchJob job = parseBatchJob(
        R"({"id":"r","command":"avatar reduce","input":"/abs/a.glb","m":5,"pin":["viseme_PP"],)"
        R"("apart":["viseme_aa,viseme_O",["viseme_E","viseme_I"]],"names":"merged","report":"r/report.json",)"
        R"("closure":"none","rest":"key"})",
        1, kJobs);
    EXPECT_EQ(job.command, JobCommand::AvatarReduce);
    EXPECT_EQ(job.reduce.input, std::filesystem::path("/abs/a.glb")); // absolute paths stay
    EXPECT_EQ(job.reduce.target, 5);
    EXPECT_EQ(job.reduce.constraints.pinned, std::vector<std::string>{"viseme_PP"});
    ASSERT_EQ(job.reduce.constraints.apart.size(), 2u);
    EXPECT_EQ(job.reduce.constraints.apart[1],
              std::make_pair(std::string("viseme_E"), std::string("viseme_I")));
    EXPECT_EQ(job.reduce.closure, "");
    EXPECT_EQ(job.reduce.rest, "key");
    EXPECT_EQ(job.outputs(), (std::vector<std::string>{"r/report.json", "r.glb"}));
}

TEST(BatchJob, ErrorsNameTheLineAndTheField) {
    EXPECT_EQ(errorOf("[1]"), "jobs/list.jsonl:7: a job is a JSON object, got array");
    EXPECT_NE(errorOf("{nope").find("jobs/list.jsonl:7"), std::string::npos);
    EXPECT_EQ(errorOf(R"({"command":"say","text":"a","project":"p"})"),
              "jobs/list.jsonl:7: id: missing: every job needs an id (it names its outputs)");
    EXPECT_NE(errorOf(R"({"id":"../x","command":"say","text":"a","project":"p"})").find("7: id: use at most"),
              std::string::npos);
    EXPECT_EQ(errorOf(R"({"id":"a","command":"say","text":"a","projct":"p"})"),
              "jobs/list.jsonl:7: projct: not a field of a say job (docs/batch.md lists them)");
    EXPECT_EQ(errorOf(R"({"id":"a","command":"sing","text":"a"})"),
              "jobs/list.jsonl:7: command: must be \"say\" or \"avatar reduce\", got sing");
    EXPECT_NE(errorOf(R"({"id":"a","command":"avatar reduce","input":"a.glb","m":0})")
                  .find("7: m: expected a whole number >= 1"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"avatar reduce","input":"a.glb","m":3,"max-error-mm":1})")
                  .find("7: m: give the number of keys"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"say","text":"a","project":"p","out":"../x.json"})")
                  .find("7: out: must stay inside the output folder"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"say","text":"a","project":"p","out":"/tmp/x.json"})")
                  .find("7: out: must be a path relative to the output folder"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"say","text":"a","project":"p","m":3})").find("7: avatar: "),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"say","text":"a","project":"p","fps":2000})").find("7: fps: "),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"id":"a","command":"say","text":"a","project":"p","html":true})")
                  .find("7: html: not available"),
              std::string::npos);
    EXPECT_NE(
        errorOf(R"({"id":"a","command":"say","text":"a","project":"p","wav":"a.json"})").find("two outputs"),
        std::string::npos);
    EXPECT_EQ(errorOf(R"({"id":"a","command":"say","text":"a","project":"p"})"), "");
}

TEST(BatchJob, TheHashIsTheJobsMeaningNotItsSpelling) {
    const auto hash = [](const std::string& line) { return parseBatchJob(line, 1, kJobs).hash; };
    const std::uint64_t a = hash(R"({"id":"a","command":"say","text":"Hi.","project":"p"})");
    EXPECT_EQ(a, hash(R"({ "project": "p", "text": "Hi.", "command": "say", "id": "a" })"));
    EXPECT_NE(a, hash(R"({"id":"a","command":"say","text":"Hi!","project":"p"})"));
    EXPECT_NE(
        a,
        parseBatchJob(R"({"id":"a","command":"say","text":"Hi.","project":"p"})", 1, "other/j.jsonl").hash);
}

TEST(BatchJob, BlankLinesHoldNoJob) {
    EXPECT_TRUE(isBlankJobLine(""));
    EXPECT_TRUE(isBlankJobLine(" \t\r"));
    EXPECT_FALSE(isBlankJobLine(" {}"));
}

} // namespace
} // namespace vl::batch
