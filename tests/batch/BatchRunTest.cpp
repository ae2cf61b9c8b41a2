// Many lines on TBB: results in line order whatever the finishing order, a bad job never stops the
// others, two jobs naming one output, shared loads, and the second run skipping what is done.
#include "BatchTestSupport.h"

#include "core/batch/BatchCaches.h"
#include "core/batch/BatchRun.h"
#include "tests/gltf/AvatarFixtures.h"

#include <nlohmann/json.hpp>

namespace vl::batch {
namespace {

class BatchRun : public test::BatchFolderTest {
  protected:
    BatchOptions options() const {
        BatchOptions o;
        o.jobsFile = dir / "jobs.jsonl";
        o.outFolder = dir / "out";
        o.assetsDir = VISEMELAB_ASSETS_DIR;
        return o;
    }
    std::vector<std::string> lines() {
        write("rpm.glb", test::rpmLikeAvatar());
        const std::string reduce = R"("command":"avatar reduce","input":"rpm.glb")";
        return {
            R"({"id":"m3",)" + reduce + R"(,"m":3})",
            R"({"id":"m4",)" + reduce + R"(,"m":4,"names":"merged"})",
            "",
            R"({"id":"gone","command":"avatar reduce","input":"missing.glb","m":3})",
            R"({"id":"again",)" + reduce + R"(,"m":5,"out":"m3.glb"})",
            "not json",
            R"({"id":"m5",)" + reduce + R"(,"m":5,"pin":["viseme_PP"]})",
        };
    }
    static std::vector<nlohmann::json> run(BatchContext& context, const std::vector<std::string>& lines,
                                           BatchSummary* summary = nullptr) {
        std::vector<nlohmann::json> results;
        const BatchSummary s = runBatchLines(
            context, lines, [&](const JobResult& r) { results.push_back(nlohmann::json::parse(r.json())); });
        if (summary) *summary = s;
        return results;
    }
};

TEST_F(BatchRun, ResultsComeInLineOrderAndBadJobsDoNotStopTheOthers) {
    BatchContext context(options());
    BatchSummary summary;
    const auto results = run(context, lines(), &summary);
    ASSERT_EQ(results.size(), 6u); // the blank line holds no job
    const std::vector<int> order{1, 2, 4, 5, 6, 7};
    for (std::size_t i = 0; i < results.size(); ++i) EXPECT_EQ(results[i]["line"], order[i]);
    EXPECT_EQ(results[0]["status"], "ok");
    EXPECT_EQ(results[0]["outputs"], nlohmann::json::array({"m3.glb"}));
    EXPECT_EQ(results[1]["status"], "ok");
    EXPECT_EQ(results[2]["status"], "error");
    EXPECT_EQ(results[2]["id"], "gone");
    EXPECT_NE(results[2]["error"].get<std::string>().find("jobs.jsonl:4: input: "), std::string::npos)
        << results[2]["error"];
    EXPECT_NE(results[2]["error"].get<std::string>().find("missing.glb"), std::string::npos);
    EXPECT_EQ(results[3]["status"], "error");
    EXPECT_NE(
        results[3]["error"].get<std::string>().find("jobs.jsonl:5: out: m3.glb is also an output of line 1"),
        std::string::npos)
        << results[3]["error"];
    EXPECT_EQ(results[4]["status"], "error");
    EXPECT_NE(results[4]["error"].get<std::string>().find("jobs.jsonl:6: "), std::string::npos);
    EXPECT_EQ(results[5]["status"], "ok");
    EXPECT_EQ(summary.ok, 3u);
    EXPECT_EQ(summary.errors, 3u);
    EXPECT_EQ(summary.internalErrors, 0u);
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "out/m5.glb"));
    // The avatar was loaded once for its three jobs (one more entry: the missing file's error).
    EXPECT_EQ(context.caches().loads(), 2u);
}

TEST_F(BatchRun, ASecondRunSkipsWhatIsDoneAndRerunsAnEditedJob) {
    auto jobs = lines();
    {
        BatchContext context(options());
        run(context, jobs);
    }
    const std::string first = read(dir / "out/m4.glb");
    const auto before = std::filesystem::last_write_time(dir / "out/m4.glb");
    jobs[0] = R"({"id":"m3","command":"avatar reduce","input":"rpm.glb","m":2})"; // edited
    BatchContext context(options());
    const auto results = run(context, jobs);
    EXPECT_EQ(results[0]["status"], "ok");
    EXPECT_EQ(results[1]["status"], "skipped");
    EXPECT_EQ(results[1]["outputs"], nlohmann::json::array({"m4.glb"}));
    EXPECT_EQ(results[5]["status"], "skipped");
    EXPECT_EQ(results[2]["status"], "error"); // errors are never done
    EXPECT_EQ(std::filesystem::last_write_time(dir / "out/m4.glb"), before);

    // --no-resume runs it again, to the same bytes.
    BatchOptions again = options();
    again.resume = false;
    BatchContext fresh(again);
    EXPECT_EQ(runBatchJob(fresh, jobs[1], 2).status, JobStatus::Ok);
    EXPECT_EQ(read(dir / "out/m4.glb"), first);
}

TEST_F(BatchRun, OneLineGivesOneResultLine) {
    lines(); // writes the avatar
    BatchContext context(options());
    const std::string line =
        runBatchJobLine(context, R"({"id":"x","command":"avatar reduce","input":"rpm.glb","m":3})", 12);
    EXPECT_EQ(line, R"({"line":12,"id":"x","status":"ok","outputs":["x.glb"]})"
                    "\n");
    EXPECT_EQ(
        runBatchJobLine(context,
                        R"({"id":"y","command":"avatar reduce","input":"rpm.glb","m":3,"out":"rpm.glb"})", 3),
        R"({"line":3,"id":"y","status":"ok","outputs":["rpm.glb"]})"
        "\n"); // in the output folder, not over the input beside the jobs file
    const std::string over = runBatchJobLine(
        context, R"({"id":"z","command":"say","text":"Hi.","avatar":"out/z.glb","out":"z.glb"})", 4);
    EXPECT_NE(over.find(R"("status":"error")"), std::string::npos) << over;
    EXPECT_NE(over.find("would overwrite the input"), std::string::npos) << over;
}

} // namespace
} // namespace vl::batch
