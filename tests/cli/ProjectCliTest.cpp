// `visemelab project new` and `project check` end to end.
#include "tests/project/ProjectTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/project/Project.h"

#include <cstdlib>
#include <sys/wait.h>

namespace vl {
namespace {

int runCli(const std::string& arguments, const std::filesystem::path& output) {
    const std::string command =
        std::string("\"") + VISEMELAB_CLI + "\" " + arguments + " > \"" + output.string() + "\" 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// `visemelab project new` makes the sample project as committed; `project check` reports the JSON path.
TEST(ProjectCli, NewAndCheck) {
    if (!std::filesystem::exists(VISEMELAB_CLI)) GTEST_SKIP() << "CLI not built: " << VISEMELAB_CLI;
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    if (!std::filesystem::exists(assets / "sample" / "neutral.obj"))
        GTEST_SKIP() << "sample meshes not generated";
    test::ScratchDir dir("cli");
    const auto file = dir / "sample.vlproj";
    const std::string newArgs = "project new --out \"" + file.string() + "\" --visemes \"" +
                                (assets / "sample").string() + "\" --phonemes \"" +
                                (assets / "phonemes" / "en-us_frequencies.csv").string() + "\" --map \"" +
                                (assets / "phonemes" / "map_sample_face.csv").string() +
                                "\" --weights area --target 10 --face bundled --reduce"
                                " --order sil,PP,FF,TH,DD,kk,CH,SS,nn,RR,aa,E,ih,oh,ou";
    ASSERT_EQ(runCli(newArgs, dir / "new.txt"), 0) << readFileToString(dir / "new.txt");

    // Same state as the committed sample (paths differ: they are relative to another folder).
    Project made = loadProject(file);
    const Project committed = loadProject(assets / "sample" / "sample.vlproj");
    // Costs are sums in floating point: a solver that adds in another order may change the last digits.
    // Equal up to 1e-12 relative counts as the same state; everything else must match exactly.
    ASSERT_TRUE(made.reduction.result && committed.reduction.result);
    auto& madeCurve = made.reduction.result->curve;
    const auto& committedCurve = committed.reduction.result->curve;
    ASSERT_EQ(madeCurve.size(), committedCurve.size());
    for (std::size_t p = 0; p < madeCurve.size(); ++p) {
        EXPECT_NEAR(madeCurve[p].cost, committedCurve[p].cost, 1e-12 * (1 + committedCurve[p].cost)) << p;
        EXPECT_NEAR(madeCurve[p].lowerBound, committedCurve[p].lowerBound,
                    1e-12 * (1 + committedCurve[p].lowerBound))
            << p;
        madeCurve[p].cost = committedCurve[p].cost;
        madeCurve[p].lowerBound = committedCurve[p].lowerBound;
    }
    EXPECT_TRUE(rebaseProject(made, committed.path) == committed) << "run scripts/make-sample-project.sh";

    ASSERT_EQ(runCli("project check \"" + file.string() + "\"", dir / "check.txt"), 0);
    EXPECT_NE(readFileToString(dir / "check.txt").find("valid project (version 3): 15 visemes"),
              std::string::npos);

    std::string text = readFileToString(file);
    text.replace(text.find("\"target\": 10"), 12, "\"target\": 16");
    test::writeText(file, text);
    EXPECT_EQ(runCli("project check \"" + file.string() + "\"", dir / "bad.txt"), 3);
    EXPECT_NE(
        readFileToString(dir / "bad.txt").find("/reduction/target: 16 is outside the allowed range 1..15"),
        std::string::npos)
        << readFileToString(dir / "bad.txt");
}

// New projects run the rest-free model when their set has a rest viseme (auto); --rest chooses.
TEST(ProjectCli, NewProjectsAreRestFree) {
    if (!std::filesystem::exists(VISEMELAB_CLI)) GTEST_SKIP() << "CLI not built: " << VISEMELAB_CLI;
    const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
    if (!std::filesystem::exists(assets / "sample" / "neutral.obj"))
        GTEST_SKIP() << "sample meshes not generated";
    test::ScratchDir dir("cli_rest");
    const auto file = dir / "new.vlproj";
    const std::string args =
        "project new --out \"" + file.string() + "\" --visemes \"" + (assets / "sample").string() +
        "\" --phonemes \"" + (assets / "phonemes" / "en-us_frequencies.csv").string() + "\" --map \"" +
        (assets / "phonemes" / "map_sample_face.csv").string() + "\" --target 4 --reduce";
    ASSERT_EQ(runCli(args, dir / "new.txt"), 0) << readFileToString(dir / "new.txt");
    const Project made = loadProject(file);
    EXPECT_EQ(made.reduction.rest, RestChoice::Auto);
    ASSERT_TRUE(made.reduction.result);
    EXPECT_TRUE(made.reduction.result->restFree); // the sample has sil: it rests
    EXPECT_EQ(made.reduction.result->groupOf()[static_cast<std::size_t>(made.findViseme("sil"))], kRestGroup);
    EXPECT_NE(readFileToString(file).find("\"version\": 3"), std::string::npos);

    ASSERT_EQ(runCli(args + " --rest key", dir / "key.txt"), 0) << readFileToString(dir / "key.txt");
    EXPECT_EQ(loadProject(file).reduction.rest, RestChoice::Key);
    EXPECT_FALSE(loadProject(file).reduction.result->restFree);
    EXPECT_EQ(runCli(args + " --rest sometimes", dir / "bad.txt"), 2);
    EXPECT_NE(readFileToString(dir / "bad.txt").find("--rest must be auto, free or key, got 'sometimes'"),
              std::string::npos)
        << readFileToString(dir / "bad.txt");
}

} // namespace
} // namespace vl
