// `visemelab avatar ...` as a user runs it: exit codes 0 / 2 (usage) / 3 (bad file, named).
#include "core/common/AtomicFile.h"
#include "tests/app/CliRunner.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

class AvatarCli : public ::testing::Test {
  protected:
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "visemelab_avatar_cli";
    void SetUp() override {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        writeFileAtomically(dir / "rpm.glb", test::rpmLikeAvatar());
        writeFileAtomically(dir / "vroid.vrm", test::vroidLikeAvatar());
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string path(const char* name) const { return (dir / name).string(); }
};

TEST_F(AvatarCli, InspectReportsTheVisemesAndWritesJson) {
    const auto r = test::runCli("avatar inspect " + path("rpm.glb") + " --json " + path("report.json"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Visemes: 15 (Oculus viseme names)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("one set over 4 meshes"), std::string::npos) << r.output;
    const auto json = nlohmann::json::parse(readFileToString(dir / "report.json"));
    EXPECT_EQ(json["visemes"].size(), 15u);
    const auto vroid = test::runCli("avatar inspect " + path("vroid.vrm") + " --targets 'Fcl_MTH_[AIUEO]'");
    ASSERT_EQ(vroid.exitCode, 0) << vroid.output;
    EXPECT_NE(vroid.output.find("Fcl_MTH_A Fcl_MTH_I Fcl_MTH_U Fcl_MTH_E Fcl_MTH_O"), std::string::npos)
        << vroid.output;
}

TEST_F(AvatarCli, BadFilesExitWith3NamingFileAndElementAndUsageErrorsWith2) {
    const std::string sparse =
        test::editGlb(test::rpmLikeAvatar({test::FixtureStorage::Sparse}), [](auto& j) {
            for (auto& mesh : j["meshes"])
                if (mesh["name"] == "Wolf3D_Head")
                    j["accessors"][mesh["primitives"][0]["targets"][5]["POSITION"]
                                       .template get<std::size_t>()]["sparse"]["indices"]["componentType"] =
                        5126;
        });
    writeFileAtomically(dir / "hostile.glb", sparse);
    const auto bad = test::runCli("avatar inspect " + path("hostile.glb"));
    EXPECT_EQ(bad.exitCode, 3) << bad.output;
    EXPECT_NE(bad.output.find("hostile.glb"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("sparse indices"), std::string::npos) << bad.output;
    const auto missing = test::runCli("avatar inspect " + path("missing.glb"));
    EXPECT_EQ(missing.exitCode, 3) << missing.output;
    const auto same = test::runCli("avatar inspect " + path("rpm.glb") + " --json " + path("rpm.glb"));
    EXPECT_EQ(same.exitCode, 2) << same.output;
    const auto pattern = test::runCli("avatar inspect " + path("rpm.glb") + " --targets 'viseme_[aa'");
    EXPECT_EQ(pattern.exitCode, 3) << pattern.output;
    EXPECT_NE(pattern.output.find("--targets"), std::string::npos) << pattern.output;
    EXPECT_EQ(test::runCli("avatar").exitCode, 2);
}

} // namespace
} // namespace vl
