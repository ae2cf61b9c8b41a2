// The resume rule: a job is done when its stamp records this job and its outputs, every output
// exists and no input is newer than the oldest output.
#include "BatchTestSupport.h"

#include "core/batch/BatchResume.h"

namespace vl::batch {
namespace {

class BatchResume : public test::BatchFolderTest {
  protected:
    // A say job on `input` with a WAV, its outputs written and stamped.
    BatchJob doneJob(const std::string& text = "Hello.") {
        write("in.vlproj", "{}");
        const BatchJob job = parseBatchJob(R"({"id":"s","command":"say","text":")" + text +
                                               R"(","project":"in.vlproj","wav":true})",
                                           1, dir / "j.jsonl");
        write("out/s.wav", "wav");
        write("out/s.json", "track");
        write("out/.visemelab-batch/s.done", formatStamp(job, job.namedInputs()));
        // Inputs older than the outputs, as when the job ran after they were made.
        const auto outputs = std::filesystem::last_write_time(dir / "out/s.json");
        std::filesystem::last_write_time(dir / "in.vlproj", outputs - std::chrono::seconds(10));
        return job;
    }
    std::filesystem::path out() const { return dir / "out"; }
};

TEST_F(BatchResume, AStampedJobWithItsOutputsIsDone) {
    const BatchJob job = doneJob();
    EXPECT_TRUE(jobIsDone(out(), job));
}

TEST_F(BatchResume, WithoutTheStampTheJobIsNotDone) {
    const BatchJob job = doneJob();
    std::filesystem::remove(stampPath(out(), job));
    EXPECT_FALSE(jobIsDone(out(), job)); // killed after its outputs, before its stamp
}

TEST_F(BatchResume, AMissingOutputMeansNotDone) {
    const BatchJob job = doneJob();
    std::filesystem::remove(dir / "out/s.wav");
    EXPECT_FALSE(jobIsDone(out(), job));
}

TEST_F(BatchResume, AnInputNewerThanTheOutputsMeansNotDone) {
    const BatchJob job = doneJob();
    std::filesystem::last_write_time(dir / "in.vlproj", std::filesystem::last_write_time(dir / "out/s.wav") +
                                                            std::chrono::seconds(5));
    EXPECT_FALSE(jobIsDone(out(), job));
    std::filesystem::remove(dir / "in.vlproj");
    EXPECT_FALSE(jobIsDone(out(), job)); // a vanished input: the run will say so
}

TEST_F(BatchResume, AnEditedJobIsNotDone) {
    doneJob();
    const BatchJob edited = parseBatchJob(
        R"({"id":"s","command":"say","text":"Bye.","project":"in.vlproj","wav":true})", 1, dir / "j.jsonl");
    EXPECT_FALSE(jobIsDone(out(), edited));
    const BatchJob fewerOutputs = parseBatchJob(
        R"({"id":"s","command":"say","text":"Hello.","project":"in.vlproj"})", 1, dir / "j.jsonl");
    EXPECT_FALSE(jobIsDone(out(), fewerOutputs));
}

TEST_F(BatchResume, ADamagedStampMeansNotDone) {
    const BatchJob job = doneJob();
    write("out/.visemelab-batch/s.done", "visemelab batch job 1\njob 0\n");
    EXPECT_FALSE(jobIsDone(out(), job));
}

} // namespace
} // namespace vl::batch
