// `visemelab export` end to end on a small project written here.
#include "core/common/AtomicFile.h"
#include "core/import/GltfImport.h"
#include "core/import/XfaceImport.h"
#include "core/io/MeshIO.h"
#include "core/runtime/Package.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace vl {
namespace {

class ExportCli : public ::testing::Test {
  protected:
    void SetUp() override {
        // One folder per test: ctest runs the tests of this fixture in parallel.
        dir = std::filesystem::temp_directory_path() /
              (std::string("visemelab_export_cli_") +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir / "meshes");
        const ReducedModel shapes = test::randomModel(8, 6, 4, true, 91, 0.1);
        writeMesh(dir / "meshes" / "neutral.obj", shapes.neutral);
        std::string visemes, frequencies;
        const char* names[] = {"aa", "oh", "ff", "th"};
        for (int v = 0; v < 4; ++v) {
            MeshData mesh = shapes.neutral;
            mesh.positions = shapes.keys[static_cast<std::size_t>(v)].positions;
            writeMesh(dir / "meshes" / (std::string(names[v]) + ".obj"), mesh);
            visemes += std::string(v ? "," : "") + "{\"name\": \"" + names[v] + "\", \"file\": \"meshes/" +
                       names[v] + ".obj\"}";
        }
        std::ofstream(dir / "face.vlproj") << R"({"format": "visemelab-project", "version": 1,
            "neutral": {"file": "meshes/neutral.obj"}, "visemes": [)"
                                           << visemes << R"(],
            "frequencies": {"phonemes": {"AA": 0.3, "OW": 0.2, "F": 0.1, "V": 0.1, "TH": 0.3},
                            "map": {"AA": "aa", "OW": "oh", "F": "ff", "V": "ff", "TH": "th"}},
            "reduction": {"target": 2, "result": null}})";
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    int run(const std::string& arguments) const {
        const std::string command = std::string(VISEMELAB_CLI) + " export " + (dir / "face.vlproj").string() +
                                    " " + arguments + " > " + (dir / "out.txt").string() + " 2>&1";
        const int status = std::system(command.c_str());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::filesystem::path dir;
};

TEST_F(ExportCli, EveryFormat) {
    ASSERT_EQ(run("--format glb --out " + (dir / "face.glb").string()), 0);
    const ReducedModel glb = readGltf(dir / "face.glb");
    ASSERT_EQ(glb.keys.size(), 2u);
    EXPECT_EQ(glb.phonemeToKey.size(), 5u);

    ASSERT_EQ(run("--format runtime --quantise --out " + (dir / "face.vlrt").string()), 0);
    runtime::Package package;
    std::string error;
    ASSERT_TRUE(package.loadFile((dir / "face.vlrt").c_str(), error)) << error;
    EXPECT_TRUE(package.quantised());
    EXPECT_EQ(package.keyCount(), 2u);
    EXPECT_EQ(package.phonemeCount(), 5u);
    // F and V share a viseme, so they share a key.
    EXPECT_EQ(package.keyOfPhoneme(package.findPhoneme("F")), package.keyOfPhoneme(package.findPhoneme("V")));

    ASSERT_EQ(run("--format vrml --out " + (dir / "xface").string()), 0);
    const XfaceFace face = loadXfaceFace(dir / "xface" / "face.fdp");
    EXPECT_EQ(face.set.visemes.size(), 2u);
    EXPECT_EQ(face.dictionary.entries.size(), 5u);
    EXPECT_EQ(face.restPhonemes.size(), 2u); // the pauses # and _ show the neutral

    ASSERT_EQ(run("--format obj --out " + (dir / "obj").string()), 0);
    EXPECT_TRUE(std::filesystem::exists(dir / "obj" / "neutral.obj"));

    // mapping.json beside every format: every original viseme and phoneme -> key.
    for (const auto& mapping :
         {dir / "face.mapping.json", dir / "xface" / "mapping.json", dir / "obj" / "mapping.json"}) {
        ASSERT_TRUE(std::filesystem::exists(mapping)) << mapping;
        const auto json = nlohmann::json::parse(readFileToString(mapping));
        EXPECT_EQ(json["format"], "visemelab-mapping");
        EXPECT_EQ(json["visemes"].size(), 4u);
        EXPECT_EQ(json["phonemes"].size(), 5u);
        EXPECT_EQ(json["reduced"].size(), 2u);
        EXPECT_EQ(json["phonemes"]["F"], json["visemes"]["ff"]);
        EXPECT_EQ(json["reduced"][0].contains("file"), mapping.parent_path() != dir) << mapping;
    }
    EXPECT_TRUE(std::filesystem::exists(dir / "face.mapping.json")); // face.glb and face.vlrt share a stem

    ASSERT_EQ(run("--unreduced --format runtime --out " + (dir / "full.vlrt").string()), 0);
    ASSERT_TRUE(package.loadFile((dir / "full.vlrt").c_str(), error)) << error;
    EXPECT_EQ(package.keyCount(), 4u);
}

TEST_F(ExportCli, BadArgumentsAndInput) {
    EXPECT_EQ(run("--format fbx --out x"), 3);
    EXPECT_EQ(run("--format glb"), 2);
    EXPECT_EQ(run("--format obj --quantise --out x"), 3);
    std::filesystem::remove(dir / "meshes" / "oh.obj");
    EXPECT_EQ(run("--format glb --out " + (dir / "face.glb").string()), 3);
}

} // namespace
} // namespace vl
