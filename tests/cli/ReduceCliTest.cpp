#include "tests/cli/CliRunner.h"

#include "core/common/AtomicFile.h"
#include "core/io/MeshIO.h"
#include "core/project/Project.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace vl;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / name) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

MeshData quad(double lift) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, lift), Vec3(0, 1, 0)};
    mesh.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
    return mesh;
}

void writeSmallSet(const fs::path& dir) {
    writeMesh(dir / "neutral.obj", quad(0));
    writeMesh(dir / "a.obj", quad(0.1));
    writeMesh(dir / "b.obj", quad(0.2));
    writeMesh(dir / "c.obj", quad(3.0));
}

nlohmann::json readJson(const fs::path& path) {
    return nlohmann::json::parse(readFileToString(path));
}

const fs::path kSample = fs::path(VISEMELAB_ASSETS_DIR) / "sample";

} // namespace

TEST(CliReduce, ReducesSmallSetAndWritesEverything) {
    TempDir dir("visemelab_cli_small");
    writeSmallSet(dir.path);
    const auto out = dir.path / "out";
    const auto r = test::runCli("reduce --visemes " + dir.path.string() +
                                " --freq a=1 --freq b=1 --freq c=2 --target 2 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = readJson(out / "report.json");
    EXPECT_EQ(report["n"], 3);
    EXPECT_EQ(report["m"], 2);
    EXPECT_EQ(report["weights"], "uniform");
    EXPECT_EQ(report["groups"], nlohmann::json::parse(R"([["a","b"],["c"]])"));
    EXPECT_EQ(report["cost_curve"].size(), 2u);
    EXPECT_GT(report["cost_curve"][0].get<double>(), report["cost"].get<double>());
    for (const char* key : {"load", "reduce", "write"}) EXPECT_TRUE(report["timing_ms"].contains(key)) << key;
    const auto mapping = readJson(out / "mapping.json");
    EXPECT_EQ(mapping["visemes"]["a"], 0);
    EXPECT_EQ(mapping["visemes"]["c"], 1);
    const auto merged = readMesh(out / "reduced_0_a+b.obj");
    EXPECT_DOUBLE_EQ(merged.positions[2][2], 0.15); // mean of 0.1 and 0.2 with equal frequencies
    EXPECT_TRUE(fs::exists(out / "reduced_1_c.wrl"));
}

// --format writes the key files asked for (binary PLY: float32 positions) and names them in the mapping;
// auto keeps OBJ + VRML for small sets (large ones: docs/performance.md, issue 33).
TEST(CliReduce, FormatChoosesTheKeyMeshFiles) {
    TempDir dir("visemelab_cli_format");
    writeSmallSet(dir.path);
    const auto out = dir.path / "out";
    const std::string args =
        "reduce --visemes " + dir.path.string() + " --freq a=1 --freq b=1 --freq c=2 -m 2";
    auto r = test::runCli(args + " --format ply --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_FALSE(fs::exists(out / "reduced_0_a+b.obj"));
    EXPECT_FLOAT_EQ(static_cast<float>(readMesh(out / "reduced_0_a+b.ply").positions[2][2]), 0.15f);
    EXPECT_EQ(readJson(out / "mapping.json")["reduced"][0]["ply"], "reduced_0_a+b.ply");
    // Binary PLY only: the set held as float32 (FloatVisemeSet), this OBJ text rounded to it; groups and
    // costs are the double path's within the bound of core/mesh/VisemeSet.h.
    const auto floatReport = readJson(out / "report.json");
    r = test::runCli(args + " --format obj --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto doubleReport = readJson(out / "report.json");
    EXPECT_EQ(floatReport["groups"], doubleReport["groups"]);
    EXPECT_NEAR(floatReport["cost"].get<double>(), doubleReport["cost"].get<double>(),
                1e-6 * doubleReport["cost"].get<double>());
    EXPECT_TRUE(fs::exists(out / "reduced_0_a+b.obj"));
    EXPECT_FALSE(fs::exists(out / "reduced_0_a+b.wrl") || fs::exists(out / "reduced_0_a+b.ply"));
    r = test::runCli(args + " --format stl --out " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

TEST(CliReduce, PhonemeTableWithMapGivesPhonemeMapping) {
    TempDir dir("visemelab_cli_phonemes");
    writeSmallSet(dir.path);
    std::ofstream(dir.path / "table.csv") << "phoneme,frequency\nAA,3\nP,1\nB,1\nF,2\n";
    std::ofstream(dir.path / "map.csv") << "phoneme,viseme\nAA,c\nP,a\nB,a\nF,b\n";
    const auto out = dir.path / "out";
    const auto r = test::runCli(
        "reduce --visemes " + dir.path.string() + " --freq-file " + (dir.path / "table.csv").string() +
        " --map " + (dir.path / "map.csv").string() + " --weights area -m 2 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto mapping = readJson(out / "mapping.json");
    EXPECT_EQ(mapping["phonemes"]["P"], mapping["visemes"]["a"]);
    EXPECT_EQ(mapping["phonemes"]["AA"], mapping["visemes"]["c"]);
    EXPECT_EQ(readJson(out / "report.json")["weights"], "area");
}

TEST(CliReduce, ReadsAProjectFileAndLetsFlagsOverrideIt) {
    TempDir dir("visemelab_cli_project");
    writeSmallSet(dir.path);
    Project project;
    project.path = dir.path / "p.vlproj"; // relative mesh paths below resolve against its folder
    project.neutral.file = "neutral.obj";
    for (const char* name : {"a", "b", "c"})
        project.visemes.push_back({name, std::string(name) + ".obj", {}});
    project.frequencies.visemeFrequencies.entries = {{"a", 1}, {"b", 1}, {"c", 2}};
    project.weights.mode = WeightMode::Area;
    project.reduction.target = 2;
    saveProject(dir.path / "p.vlproj", project);

    const auto out = dir.path / "out";
    auto r = test::runCli("reduce --project " + (dir.path / "p.vlproj").string() + " --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto report = readJson(out / "report.json");
    EXPECT_EQ(report["m"], 2);
    EXPECT_EQ(report["weights"], "area");
    EXPECT_EQ(report["groups"], nlohmann::json::parse(R"([["a","b"],["c"]])"));

    r = test::runCli("reduce --project " + (dir.path / "p.vlproj").string() +
                     " -m 1 --weights uniform --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    report = readJson(out / "report.json");
    EXPECT_EQ(report["m"], 1);
    EXPECT_EQ(report["weights"], "uniform");

    r = test::runCli("reduce --project " + (dir.path / "p.vlproj").string() + " --visemes " +
                     dir.path.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = test::runCli("reduce --project " + (dir.path / "missing.vlproj").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("missing.vlproj"), std::string::npos) << r.output;
}

TEST(CliReduce, UsageErrorsExitWith2) {
    EXPECT_EQ(test::runCli("").exitCode, 2);
    EXPECT_EQ(test::runCli("reduce --visemes x").exitCode, 2); // --target missing
    EXPECT_EQ(test::runCli("reduce --target notanumber").exitCode, 2);
    EXPECT_EQ(test::runCli("reduce --help").exitCode, 0);
    EXPECT_EQ(test::runCli("reduce -m 2").exitCode, 2); // no meshes named
    EXPECT_EQ(test::runCli("reduce -m 2 --visemes a --viseme b=c.obj").exitCode, 2);
    EXPECT_EQ(test::runCli("reduce -m 2 --visemes a --freq a=1 --freq-file f.csv").exitCode, 2);
}

TEST(CliReduce, InvalidInputExitsWith3AndNamesTheProblem) {
    TempDir dir("visemelab_cli_bad");
    writeSmallSet(dir.path);
    const std::string set = " --visemes " + dir.path.string() + " --out " + (dir.path / "out").string();
    auto expect3 = [](const test::CliResult& r, const std::string& fragment) {
        EXPECT_EQ(r.exitCode, 3) << r.output;
        EXPECT_NE(r.output.find(fragment), std::string::npos) << r.output;
    };
    expect3(test::runCli("reduce" + set + " --target 4"), "target m = 4 is outside 1..3");
    expect3(test::runCli("reduce" + set + " --target 0"), "outside 1..3");
    expect3(test::runCli("reduce" + set + " -m 2 --freq a=1 --freq b=-1 --freq c=1"), "frequency must be");
    expect3(test::runCli("reduce" + set + " -m 2 --freq a=0 --freq b=0 --freq c=0"),
            "all viseme frequencies are zero");
    expect3(test::runCli("reduce" + set + " -m 2 --weights " + (dir.path / "missing.json").string()),
            "missing.json: file not found");
    expect3(test::runCli("reduce --neutral " + (dir.path / "nope.obj").string() +
                         " --viseme a=" + (dir.path / "a.obj").string() +
                         " --viseme b=" + (dir.path / "b.obj").string() + " -m 1"),
            "nope.obj: file not found");
    std::ofstream(dir.path / "broken.obj") << "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n";
    expect3(test::runCli("reduce --neutral " + (dir.path / "neutral.obj").string() +
                         " --viseme a=" + (dir.path / "a.obj").string() +
                         " --viseme b=" + (dir.path / "broken.obj").string() + " -m 1"),
            "broken.obj:2");
}

TEST(CliReduce, ReducesTheBundledSample) {
    TempDir dir("visemelab_cli_sample");
    const fs::path phonemes = fs::path(VISEMELAB_ASSETS_DIR) / "phonemes";
    const auto r = test::runCli("reduce --visemes " + kSample.string() + " --freq-file " +
                                (phonemes / "en-us_frequencies.csv").string() + " --map " +
                                (phonemes / "map_sample_face.csv").string() +
                                " --weights area --target 10 --out " + (dir.path / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = readJson(dir.path / "out" / "report.json");
    EXPECT_EQ(report["m"], 10);
    EXPECT_GE(report["n"].get<int>(), 15);
    EXPECT_EQ(report["groups"].size(), 10u);
    const auto mapping = readJson(dir.path / "out" / "mapping.json");
    EXPECT_GE(mapping["phonemes"].size(), 39u); // every phoneme of the inventory maps to a reduced viseme
}

TEST(CliReduce, ReportAlwaysCarriesTheCertificate) {
    TempDir dir("visemelab_cli_certificate");
    writeSmallSet(dir.path);
    for (const char* method : {"auto", "dp", "bnb", "lp"}) {
        const auto out = dir.path / method;
        const auto r = test::runCli("reduce --visemes " + dir.path.string() + " -m 2 --method " + method +
                                    " --out " + out.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto report = readJson(out / "report.json");
        EXPECT_EQ(report["method"], std::string(method) == "auto" ? "dp" : method);
        EXPECT_EQ(report["optimal"], true);
        EXPECT_EQ(report["gap"], 0.0);
        EXPECT_EQ(report["lower_bound"], report["cost"]);
        EXPECT_EQ(report["lower_bound_curve"].size(), 2u);
        EXPECT_EQ(report["optimal_curve"], nlohmann::json::parse("[true,true]"));
        EXPECT_NE(r.output.find("(proved)"), std::string::npos) << r.output;
    }
}

TEST(CliReduce, ConstraintFlagsAreHonouredAndInfeasibleOnesExplained) {
    TempDir dir("visemelab_cli_constraints");
    writeSmallSet(dir.path);
    const std::string set = " --visemes " + dir.path.string() + " --out " + (dir.path / "out").string();
    // Unconstrained, a and b merge (they are close); pinning a keeps it alone.
    auto r = test::runCli("reduce" + set + " -m 2 --pin a");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto report = readJson(dir.path / "out" / "report.json");
    EXPECT_EQ(report["groups"], nlohmann::json::parse(R"([["a"],["b","c"]])"));
    EXPECT_EQ(report["constraints"]["pin"], nlohmann::json::parse(R"(["a"])"));
    EXPECT_TRUE(report["cost_curve"][0].is_null()); // one group cannot keep a alone
    r = test::runCli("reduce" + set + " -m 2 --apart a,b --together b,c");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    report = readJson(dir.path / "out" / "report.json");
    EXPECT_EQ(report["groups"], nlohmann::json::parse(R"([["a"],["b","c"]])"));

    auto expectError = [](const test::CliResult& result, int code, const std::string& fragment) {
        EXPECT_EQ(result.exitCode, code) << result.output;
        EXPECT_NE(result.output.find(fragment), std::string::npos) << result.output;
    };
    expectError(
        test::runCli("reduce" + set + " -m 1 --pin a"), 3,
        "no grouping into 1 groups satisfies the constraints: pinned visemes and 'apart' pairs need at "
        "least 2 groups");
    expectError(test::runCli("reduce" + set + " -m 3 --together a,c"), 3,
                "the 'together' constraints leave 2 separable units");
    expectError(test::runCli("reduce" + set + " -m 2 --together a,c --apart c,a"), 3,
                "the constraints contradict");
    expectError(test::runCli("reduce" + set + " -m 2 --pin zz"), 3,
                "unknown viseme 'zz' (the visemes are: a, b, c)");
    expectError(test::runCli("reduce" + set + " -m 2 --apart a"), 2,
                "--apart expects two viseme names as A,B");
    expectError(test::runCli("reduce" + set + " -m 2 --method fast"), 2,
                "--method must be auto, dp, bnb or lp");
    expectError(test::runCli("reduce" + set + " -m 2 --time-limit -1"), 2, "--time-limit must be >= 0");
}

TEST(CliReduce, ReducesMoreThanTwentyVisemes) {
    TempDir dir("visemelab_cli_large");
    writeMesh(dir.path / "neutral.obj", quad(0));
    for (int i = 0; i < 26; ++i) { // four clusters of lifts, so the optimum is clear-cut
        char name[16];
        std::snprintf(name, sizeof name, "v%02d.obj", i);
        writeMesh(dir.path / name, quad((i % 4) * 2.0 + 0.01 * i));
    }
    const auto r =
        test::runCli("reduce --visemes " + dir.path.string() + " -m 4 --out " + (dir.path / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = readJson(dir.path / "out" / "report.json");
    EXPECT_EQ(report["n"], 26);
    EXPECT_EQ(report["method"], "bnb");
    EXPECT_EQ(report["optimal"], true);
    ASSERT_EQ(report["groups"].size(), 4u);
    for (const auto& group : report["groups"]) EXPECT_GE(group.size(), 6u);
}

TEST(CliReduce, TheRestIsFreeForTheSampleAndKeyedWithRestKey) {
    // The sample project runs the default model (auto: the set has sil, so the rest is free) and
    // stores its result: sil rests, gets no key and maps to -1, the neutral face; its own model
    // reproduces the stored curve. --rest key makes the rest a key like any other again.
    TempDir dir("visemelab_cli_rest");
    const fs::path project = kSample / "sample.vlproj";
    const auto free =
        test::runCli("reduce --project " + project.string() + " --out " + (dir.path / "free").string());
    ASSERT_EQ(free.exitCode, 0) << free.output;
    const auto stored = readJson(project)["reduction"]["result"]["curve"];
    EXPECT_EQ(readJson(project)["reduction"]["rest"], "auto");
    const auto report = readJson(dir.path / "free" / "report.json");
    EXPECT_EQ(report["rest"]["model"], "free");
    EXPECT_EQ(report["rest"]["viseme"], "sil");
    ASSERT_EQ(report["cost_curve"].size(), stored.size());
    for (std::size_t p = 0; p < stored.size(); ++p)
        EXPECT_NEAR(report["cost_curve"][p].get<double>(), stored[p]["cost"].get<double>(),
                    1e-9 * stored[p]["cost"].get<double>())
            << "p=" << p + 1;
    const auto resting = report["rest"]["resting"].get<std::vector<std::string>>();
    EXPECT_NE(std::find(resting.begin(), resting.end(), "sil"), resting.end());
    EXPECT_EQ(report["groups"].size(), 10u); // ten keys besides the free rest
    for (const auto& group : report["groups"])
        for (const auto& member : group) EXPECT_NE(member, "sil");
    EXPECT_EQ(readJson(dir.path / "free" / "mapping.json")["visemes"]["sil"], -1);
    EXPECT_NE(free.output.find("Rest: free"), std::string::npos) << free.output;

    const auto keyed = test::runCli("reduce --project " + project.string() + " --rest key --out " +
                                    (dir.path / "key").string());
    ASSERT_EQ(keyed.exitCode, 0) << keyed.output;
    const auto keyedReport = readJson(dir.path / "key" / "report.json");
    EXPECT_EQ(keyedReport["rest"]["model"], "key");
    EXPECT_TRUE(keyedReport["rest"]["resting"].empty()) << keyedReport["rest"];
    EXPECT_EQ(keyedReport["groups"].size(), 10u);
    EXPECT_GE(readJson(dir.path / "key" / "mapping.json")["visemes"]["sil"].get<int>(), 0);
    EXPECT_NE(keyed.output.find("Rest: key"), std::string::npos) << keyed.output;
    // Resting cannot beat keying the same visemes at their mean: the keyed optimum with one key more
    // is at most the rest-free one.
    EXPECT_LE(keyedReport["cost_curve"][9].get<double>(), report["cost_curve"][8].get<double>() * (1 + 1e-9));

    const auto unknown = test::runCli("reduce --project " + project.string() + " --rest-viseme XX --out " +
                                      (dir.path / "bad").string());
    EXPECT_EQ(unknown.exitCode, 3) << unknown.output;
    EXPECT_EQ(test::runCli("reduce --project " + project.string() + " --rest maybe").exitCode, 2);
}
