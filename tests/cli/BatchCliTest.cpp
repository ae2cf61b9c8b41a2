// `visemelab batch` end to end: a 200-job mixed file (say on a project and on an avatar, avatar
// reduce, bad jobs) -> every good job's outputs are the single command's bytes, bad jobs are
// reported with their line; killed mid-batch and run again -> the same final state, no job done
// twice; exit codes.
#include "tests/cli/CliRunner.h"
#include "tests/gltf/AvatarFolderTest.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sys/wait.h>
#include <unistd.h>

namespace vl {
namespace {

const std::string kProject = std::string(VISEMELAB_ASSETS_DIR) + "/sample/sample.vlproj";

std::string sentence(int i) {
    static const char* words[] = {"quick", "brown",   "foxes", "jump",   "over",  "lazy",   "dogs", "while",
                                  "seven", "sailors", "sing",  "softly", "about", "shells", "and",  "rain"};
    std::string s = "Line " + std::to_string(i);
    for (int w = 0; w < 8; ++w) s += std::string(" ") + words[(i * 7 + w * 3) % 16];
    return s + ".";
}

// One job per line: id "jN" for line N; `single` gets the `visemelab` arguments that make the same
// outputs in the folder SINGLE, for the jobs compared with the single command.
std::string jobLine(int line, std::string& single) {
    const std::string id = "j" + std::to_string(line);
    const std::string text = sentence(line);
    const std::string say = R"({"id":")" + id + R"(","command":"say","text":")" + text + R"(",)";
    switch (line % 5) {
    case 0:
        single = "say '" + text + "' --project " + kProject + " --out SINGLE/" + id + ".json --wav SINGLE/" +
                 id + ".wav";
        return say + R"("project":")" + kProject + R"(","wav":true})";
    case 1: {
        const char* format = line % 2 ? "rhubarb" : "talkinghead";
        single = "say '" + text + "' --project " + kProject + " --format " + format +
                 " --blend linear --out SINGLE/" + id + ".json --glb SINGLE/" + id + ".glb";
        return say + R"("project":")" + kProject + R"(","format":")" + format +
               R"(","blend":"linear","glb":true})";
    }
    case 2: {
        const int m = 4 + line % 3;
        single = "say '" + text + "' --avatar RPM -m " + std::to_string(m) + " --out SINGLE/" + id +
                 ".json --wav SINGLE/" + id + ".wav --glb SINGLE/" + id + ".glb";
        return say + R"("avatar":"rpm.glb","m":)" + std::to_string(m) + R"(,"wav":true,"glb":true})";
    }
    case 3: {
        const int m = 3 + line % 6;
        const bool merged = line % 2;
        single = "avatar reduce RPM -m " + std::to_string(m) + (merged ? " --names merged" : "") +
                 " --pin viseme_aa" + " --out SINGLE/" + id + ".glb";
        return R"({"id":")" + id + R"(","command":"avatar reduce","input":"rpm.glb","m":)" +
               std::to_string(m) + (merged ? R"(,"names":"merged")" : "") + R"(,"pin":["viseme_aa"]})";
    }
    default:
        single = "say '" + text + "' --project " + kProject + " --out SINGLE/" + id + ".json";
        return say + R"("project":")" + kProject + R"("})";
    }
}

// Bad jobs at these lines, each with the culprit its error must name.
const std::map<int, std::pair<std::string, std::string>> kBad = {
    {7, {R"({"id":"b7","command":"say","text":"Hi there.","project":"missing.vlproj"})", "project: "}},
    {23, {R"({"id":"b23","command":"say","text":"Hi there.","projekt":"x"})", "projekt: not a field"}},
    {41,
     {R"({"id":"b41","command":"say","text":"Hi there.","project":")" + kProject + R"(","voice":"xx-nope"})",
      "voice"}},
    {58, {R"({"id":"b58","command":"avatar reduce","input":"rpm.glb","m":99})", "99"}},
    {77, {R"({"id":"b77", "command": )", "invalid JSON"}},
    {96,
     {R"({"id":"b96","command":"say","text":"Hi.","project":"p","out":"../b96.json"})",
      "out: must stay inside"}},
    {115,
     {R"({"id":"b115","command":"say","text":"...","project":")" + kProject + R"("})", "nothing to say"}},
    {134, {R"({"id":"b134","command":"avatar reduce","input":"jobs.jsonl","m":3})", "input: "}},
    {153,
     {R"({"id":"b153","command":"say","text":"Hi there.","project":")" + kProject + R"(","out":"j150.json"})",
      "is also an output of line 150"}},
    {172,
     {R"({"id":"b172","command":"say","text":"Hi there.","project":")" + kProject + R"(","rate":5})",
      "rate"}},
};
constexpr int kLines = 200;

class BatchCli : public test::AvatarFolderTest {
  protected:
    void SetUp() override {
        AvatarFolderTest::SetUp();
        std::ofstream jobs(dir / "jobs.jsonl");
        for (int line = 1; line <= kLines; ++line) {
            std::string single;
            const auto bad = kBad.find(line);
            jobs << (bad != kBad.end() ? bad->second.first : jobLine(line, single)) << "\n";
            if (bad == kBad.end()) singles[line] = single;
        }
    }
    // The result lines of a run (lines starting with '{').
    static std::vector<nlohmann::json> results(const std::string& output) {
        std::vector<nlohmann::json> r;
        std::size_t start = 0;
        while (start < output.size()) {
            std::size_t end = output.find('\n', start);
            if (end == std::string::npos) end = output.size();
            if (output[start] == '{') r.push_back(nlohmann::json::parse(output.substr(start, end - start)));
            start = end + 1;
        }
        return r;
    }
    test::CliResult batch(const std::string& out, const std::string& more = "") {
        return test::runCli("batch " + path("jobs.jsonl") + " --out " + (dir / out).string() + more +
                            " 2>/dev/null");
    }
    // Every file under `folder` but the batch's own stamps, with its bytes.
    static std::map<std::string, std::string> files(const std::filesystem::path& folder) {
        std::map<std::string, std::string> all;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
            const std::string name = std::filesystem::relative(entry.path(), folder).generic_string();
            if (!entry.is_regular_file() || name.starts_with(".visemelab-batch")) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            all[name] = {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        }
        return all;
    }
    std::map<int, std::string> singles; // line -> the single command's arguments
};

TEST_F(BatchCli, GoodJobsAreTheSingleCommandsBytesAndBadJobsNameTheirLine) {
    const auto run = batch("out");
    const auto r = results(run.output);
    if (run.exitCode != 3 && run.output.find("espeak") != std::string::npos) GTEST_SKIP() << run.output;
    ASSERT_EQ(run.exitCode, 3) << run.output; // some jobs failed on their input
    ASSERT_EQ(r.size(), std::size_t(kLines));
    for (int line = 1; line <= kLines; ++line) {
        const nlohmann::json& result = r[std::size_t(line - 1)];
        ASSERT_EQ(result["line"], line);
        if (const auto bad = kBad.find(line); bad != kBad.end()) {
            EXPECT_EQ(result["status"], "error") << result;
            const std::string error = result.value("error", "");
            EXPECT_TRUE(error.starts_with(path("jobs.jsonl") + ":" + std::to_string(line) + ": ")) << error;
            EXPECT_NE(error.find(bad->second.second), std::string::npos) << error;
        } else {
            EXPECT_EQ(result["status"], "ok") << result;
            EXPECT_EQ(result["id"], "j" + std::to_string(line));
        }
    }
    // A sample of every kind (lines 1..20 and a later stretch) against the single command.
    const auto batchFiles = files(dir / "out");
    const auto single = [&](int line) {
        std::string arguments = singles.at(line);
        for (const auto& [token, value] :
             {std::pair<std::string, std::string>{"SINGLE", (dir / "single").string()},
              {"RPM", path("rpm.glb")}})
            for (std::size_t at; (at = arguments.find(token)) != std::string::npos;)
                arguments.replace(at, token.size(), value);
        return std::make_pair(arguments,
                              test::runCli(arguments + (arguments.starts_with("say") ? " --quiet" : "")));
    };
    for (int line :
         {1, 2, 3, 4, 5, 6, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 187, 188, 189, 190}) {
        const auto [arguments, command] = single(line);
        ASSERT_EQ(command.exitCode, 0) << arguments << "\n" << command.output;
        for (const auto& value : r[std::size_t(line - 1)]["outputs"]) {
            const std::string output = value.get<std::string>();
            std::ifstream in(dir / "single" / output, std::ios::binary);
            const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            EXPECT_FALSE(bytes.empty()) << output;
            EXPECT_TRUE(bytes == batchFiles.at(output))
                << "line " << line << ": " << output << " differs from `" << arguments << "`";
        }
    }
}

TEST_F(BatchCli, KilledMidBatchAndRunAgainEndsTheSameWithNoJobDoneTwice) {
    // The whole batch once, uninterrupted: the final state to reach.
    const auto whole = batch("whole");
    if (whole.exitCode != 3 && whole.output.find("espeak") != std::string::npos) GTEST_SKIP() << whole.output;
    ASSERT_EQ(whole.exitCode, 3) << whole.output;

    // Killed (SIGKILL) after its first 40 results.
    int pipe[2];
    ASSERT_EQ(::pipe(pipe), 0);
    const pid_t child = ::fork();
    if (child == 0) {
        ::dup2(pipe[1], STDOUT_FILENO);
        ::close(pipe[0]);
        const std::string jobs = path("jobs.jsonl"), out = (dir / "killed").string();
        ::execl(VISEMELAB_CLI, VISEMELAB_CLI, "batch", jobs.c_str(), "--out", out.c_str(),
                static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(pipe[1]);
    std::string first;
    char buffer[4096];
    while (std::count(first.begin(), first.end(), '\n') < 40) {
        const ssize_t n = ::read(pipe[0], buffer, sizeof buffer);
        if (n <= 0) break;
        first.append(buffer, std::size_t(n));
    }
    ::kill(child, SIGKILL);
    ::close(pipe[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the batch ended before it was killed";
    first.resize(first.rfind('\n') + 1); // the last whole line
    std::set<std::string> doneFirst;
    std::map<std::string, std::filesystem::file_time_type> times;
    for (const auto& result : results(first))
        if (result["status"] == "ok") {
            doneFirst.insert(result["id"].get<std::string>());
            for (const auto& value : result["outputs"]) {
                const std::string output = value.get<std::string>();
                times[output] = std::filesystem::last_write_time(dir / "killed" / output);
            }
        }
    ASSERT_GE(doneFirst.size(), 30u);

    // Run again: what the killed run reported is skipped, not redone; everything else runs.
    const auto resumed = batch("killed");
    ASSERT_EQ(resumed.exitCode, 3) << resumed.output;
    const auto again = results(resumed.output);
    ASSERT_EQ(again.size(), std::size_t(kLines));
    std::size_t skipped = 0;
    for (const auto& result : again) {
        const std::string id = result["id"];
        if (doneFirst.count(id)) {
            EXPECT_EQ(result["status"], "skipped") << result;
        }
        skipped += result["status"] == "skipped";
    }
    EXPECT_GE(skipped, doneFirst.size());
    EXPECT_LT(skipped, std::size_t(kLines - kBad.size())); // the kill left work to do
    for (const auto& [output, time] : times)
        EXPECT_EQ(std::filesystem::last_write_time(dir / "killed" / output), time)
            << output << " was written again";
    EXPECT_TRUE(files(dir / "killed") == files(dir / "whole")) << "the resumed batch's outputs differ";

    // Results are byte-comparable between runs: the resumed run's are the whole run's, with the
    // jobs the killed run did reported as skipped.
    std::string expected;
    for (auto result : again) {
        if (result["status"] == "skipped") result["status"] = "ok";
        expected += result.dump() + "\n";
    }
    std::string wholeResults;
    for (const auto& result : results(whole.output)) wholeResults += result.dump() + "\n";
    EXPECT_EQ(expected, wholeResults);
}

TEST_F(BatchCli, ExitCodes) {
    std::ofstream(dir / "good.jsonl") << R"({"id":"r","command":"avatar reduce","input":"rpm.glb","m":3})"
                                      << "\n";
    EXPECT_EQ(test::runCli("batch " + path("good.jsonl") + " --out " + path("o")).exitCode, 0);
    const auto again = test::runCli("batch " + path("good.jsonl") + " --out " + path("o"));
    EXPECT_EQ(again.exitCode, 0); // skipped jobs succeeded before
    EXPECT_NE(again.output.find(R"("status":"skipped")"), std::string::npos) << again.output;
    EXPECT_EQ(test::runCli("batch " + path("good.jsonl")).exitCode, 2); // no --out
    const auto missing = test::runCli("batch " + path("none.jsonl") + " --out " + path("o"));
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_NE(missing.output.find("none.jsonl"), std::string::npos) << missing.output;
    // --results FILE takes the result lines; the standard output stays free of them.
    const auto file = test::runCli("batch " + path("good.jsonl") + " --out " + path("o") + " --results " +
                                   path("results.jsonl") + " --no-resume");
    EXPECT_EQ(file.exitCode, 0);
    EXPECT_EQ(file.output.find('{'), std::string::npos) << file.output;
    std::ifstream in(dir / "results.jsonl");
    const std::string results{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_EQ(results, R"({"line":1,"id":"r","status":"ok","outputs":["r.glb"]})"
                       "\n");
}

} // namespace
} // namespace vl
