// Outputs never clobber inputs (exit code 2, or 3 for a folder output that holds them; inputs byte
// for byte unchanged), and folder outputs replace the previous run's as a set: stale files of earlier
// runs go, unrelated files stay.
#include "CliRunner.h"

#include "core/common/AtomicFile.h"
#include "core/common/OutputSet.h"
#include "core/io/MeshIO.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace vl {
namespace {

namespace fs = std::filesystem;

class CliOutput : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / (std::string("visemelab_cli_output_") +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "meshes");
        const ReducedModel shapes = test::randomModel(6, 5, 4, true, 7, 0.1);
        writeMesh(dir / "meshes" / "neutral.obj", shapes.neutral);
        std::string visemes;
        for (int v = 0; v < 4; ++v) {
            MeshData mesh = shapes.neutral;
            mesh.positions = shapes.keys[static_cast<std::size_t>(v)].positions;
            const std::string name = "v" + std::to_string(v);
            writeMesh(dir / "meshes" / (name + ".obj"), mesh);
            visemes += std::string(v ? "," : "") + R"({"name": ")" + name + R"(", "file": "meshes/)" + name +
                       R"(.obj"})";
        }
        std::ofstream(dir / "face.vlproj") << R"({"format": "visemelab-project", "version": 1,
            "neutral": {"file": "meshes/neutral.obj"}, "visemes": [)"
                                           << visemes << R"(],
            "frequencies": {"visemes": {"v0": 1, "v1": 2, "v2": 3, "v3": 4}},
            "reduction": {"target": 2, "result": null}})";
        neutralBefore = readFileToString(dir / "meshes" / "neutral.obj");
    }
    void TearDown() override { fs::remove_all(dir); }

    test::CliResult run(const std::string& arguments) const { return test::runCli(arguments); }
    std::string project() const { return (dir / "face.vlproj").string(); }
    std::vector<std::string> listing(const fs::path& folder) const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
    void expectInputsUnchanged() const {
        EXPECT_EQ(readFileToString(dir / "meshes" / "neutral.obj"), neutralBefore);
        for (const auto& name : listing(dir / "meshes")) EXPECT_FALSE(name.starts_with(".")) << name;
    }

    fs::path dir;
    std::string neutralBefore;
};

TEST_F(CliOutput, ExportOntoTheProjectsOwnMeshesIsRefused) {
    // The export writes neutral.obj: into the meshes folder that would overwrite the project's neutral,
    // and the folder output replaces the folder's contents: a folder holding inputs is refused.
    auto r = run("export " + project() + " --format obj --out " + (dir / "meshes").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("meshes: output folder holds"), std::string::npos) << r.output;
    expectInputsUnchanged();
    r = run("export " + project() + " --format glb --out " + (dir / "meshes" / "v1.obj").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = run("export " + project() + " --format runtime --out " + project());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(readFileToString(dir / "face.vlproj").find("visemelab-project"), std::string::npos);
    expectInputsUnchanged();
}

TEST_F(CliOutput, ReduceRefusesItsInputsAndInputFolder) {
    const std::string meshes = (dir / "meshes").string();
    auto r = run("reduce --visemes " + meshes + " --target 2 --out " + meshes);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("is the input folder"), std::string::npos) << r.output;
    r = run("reduce --visemes " + meshes + " --target 2 --out " + (dir / "out").string() + " --report " +
            meshes + "/v2.obj");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "mapping.json")); // refused before any output was written
    r = run("reduce --project " + project() + " --out " + (dir / "out").string() + " --report " + project());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = run("render " + meshes + "/v0.obj --out " + meshes + "/v0.obj");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    expectInputsUnchanged();
}

TEST_F(CliOutput, FolderOutputsReplaceTheLastRunAsASet) {
    const fs::path out = dir / "export";
    fs::create_directories(out);
    std::ofstream(out / "readme.txt") << "not ours";
    ASSERT_EQ(run("export " + project() + " --unreduced --format obj --out " + out.string()).exitCode, 0);
    EXPECT_EQ(listing(out).size(), 1u + 1u + 1u + 4u + 1u); // manifest, readme, neutral, 4 keys, mapping.json
    const auto r = run("export " + project() + " --format obj --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto files = listing(out);
    // The reduced export has 2 keys: the 4 unreduced ones of the first run are gone, readme.txt stays.
    EXPECT_EQ(files.size(), 1u + 1u + 1u + 2u + 1u) << ::testing::PrintToString(files);
    EXPECT_TRUE(std::count(files.begin(), files.end(), "readme.txt"));
    // mapping.json belongs to the set: it names the reduced key files of this run.
    const std::string mapping = readFileToString(out / "mapping.json");
    EXPECT_NE(mapping.find(files[4]), std::string::npos) << mapping;
    EXPECT_EQ(OutputSet::readManifest(OutputSet::manifestPath(out, "export-obj")).size(), 4u);
    for (const auto& name : files) EXPECT_EQ(name.find(".vltmp"), std::string::npos) << name;

    const fs::path reduced = dir / "reduced";
    ASSERT_EQ(run("reduce --project " + project() + " --target 3 --out " + reduced.string()).exitCode, 0);
    const auto three = listing(reduced).size();
    ASSERT_EQ(run("reduce --project " + project() + " --target 1 --out " + reduced.string()).exitCode, 0);
    EXPECT_EQ(listing(reduced).size(), three - 4); // two fewer merged meshes, OBJ and VRML each
    expectInputsUnchanged();
}

} // namespace
} // namespace vl
