// `visemelab avatar ...` as a user runs it: exit codes 0 / 2 (usage) / 3 (bad file, named).
#include "core/common/AtomicFile.h"
#include "tests/cli/CliRunner.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>

namespace vl {
namespace {

class AvatarCli : public ::testing::Test {
  protected:
    // One folder per test: ctest runs the tests of this fixture in parallel.
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                (std::string("visemelab_avatar_cli_") +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
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

TEST_F(AvatarCli, ReduceWritesTheAvatarAndAReportWithTheKeysOfReduce) {
    const auto r = test::runCli("avatar reduce " + path("rpm.glb") + " --target 6 --out " + path("out.glb") +
                                " --report " + path("report.json") + " --weights area");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Reduced 15 visemes to 6"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bundled en-us phoneme table + map oculus"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("has frequency 0"), std::string::npos) << r.output; // silence is counted too
    const auto report = nlohmann::json::parse(readFileToString(dir / "report.json"));
    for (const char* key :
         {"n", "m", "weights", "cost", "groups", "cost_curve", "timing_ms", "meshes", "avatar"})
        EXPECT_TRUE(report.contains(key)) << key;
    EXPECT_EQ(report["n"], 15);
    EXPECT_EQ(report["m"], 6);
    EXPECT_EQ(report["weights"], "area");
    EXPECT_EQ(report["meshes"].size(), 4u);
    EXPECT_EQ(report["phoneme_to_key"].size(), 40u); // the ARPAbet phonemes and sil of the Oculus map
    const AvatarScan out = scanAvatar(loadGltfDocument(dir / "out.glb"), {});
    EXPECT_EQ(out.visemes.size(), 15u); // --names original: every viseme name is still there

    // Merged names with a cap that fits; a cap that does not fit is refused with exit 3. The resting
    // visemes (the rest is free) keep their targets, moving nothing: 6 kept + 4 resting + 4 keys.
    const auto merged = test::runCli("avatar reduce " + path("rpm.glb") +
                                     " -m 4 --names merged --max-targets 14 --out " + path("merged.glb"));
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    const auto capped =
        test::runCli("avatar reduce " + path("rpm.glb") + " -m 4 --max-targets 8 --out " + path("x.glb"));
    EXPECT_EQ(capped.exitCode, 3) << capped.output;
    EXPECT_NE(capped.output.find("--names merged"), std::string::npos) << capped.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.glb"));

    // VRoid names need a pattern; frequencies then default to equal.
    const auto vroid = test::runCli("avatar reduce " + path("vroid.vrm") +
                                    " -m 3 --targets 'Fcl_MTH_[AIUEO]' --out " + path("vroid_out.vrm"));
    ASSERT_EQ(vroid.exitCode, 0) << vroid.output;
    EXPECT_NE(vroid.output.find("frequencies: equal"), std::string::npos) << vroid.output;
    const auto none = test::runCli("avatar reduce " + path("vroid.vrm") + " -m 3 --out " + path("v.vrm"));
    EXPECT_EQ(none.exitCode, 3) << none.output;
    EXPECT_NE(none.output.find("needs at least 2 visemes"), std::string::npos) << none.output;
}

TEST_F(AvatarCli, TheRestIsFreeSoSilenceMovesNothingAndKeepsItsTarget) {
    const auto r = test::runCli("avatar reduce " + path("rpm.glb") + " -m 6 --out " + path("out.glb") +
                                " --report " + path("report.json"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("viseme_sil moves 0 mm (rests"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("viseme_PP moves"), std::string::npos) << r.output;
    const auto report = nlohmann::json::parse(readFileToString(dir / "report.json"));
    EXPECT_EQ(report["rest"]["model"], "free");
    EXPECT_EQ(report["rest"]["viseme"], "viseme_sil");
    EXPECT_EQ(report["groups"].size(), 6u); // six keys besides the free rest
    bool silReported = false;
    for (const auto& motion : report["viseme_motion"])
        if (motion["viseme"] == "viseme_sil") {
            silReported = true;
            EXPECT_TRUE(motion["key"].is_null());
            EXPECT_EQ(motion["after_mm"], 0.0);
        }
    EXPECT_TRUE(silReported) << report["viseme_motion"].dump();
    // --names original: viseme_sil's target is still there by name, and it moves no vertex.
    const AvatarScan out = scanAvatar(loadGltfDocument(dir / "out.glb"), {});
    const int sil = out.set.find("viseme_sil");
    ASSERT_GE(sil, 0);
    const auto& shape = out.set.visemes[static_cast<std::size_t>(sil)].positions;
    ASSERT_EQ(shape.size(), out.set.neutral.positions.size());
    for (std::size_t v = 0; v < shape.size(); ++v) EXPECT_EQ(shape[v], out.set.neutral.positions[v]) << v;

    // Lip closure: viseme_PP keeps a key of its own by default, so it moves as far as it did.
    EXPECT_EQ(report["closure"]["viseme"], "viseme_PP") << report["closure"].dump();
    bool ppReported = false;
    for (const auto& motion : report["viseme_motion"])
        if (motion["viseme"] == "viseme_PP") {
            ppReported = true;
            EXPECT_EQ(motion["key"], "viseme_PP") << motion.dump();
            EXPECT_NEAR(motion["after_mm"].get<double>(), motion["before_mm"].get<double>(), 1e-6);
            EXPECT_GT(motion["before_mm"].get<double>(), 1.0);
        }
    EXPECT_TRUE(ppReported) << report["viseme_motion"].dump();
    // --closure none: the optimiser alone rests the fixture's small closure motion.
    const auto free = test::runCli("avatar reduce " + path("rpm.glb") + " -m 6 --closure none --out " +
                                   path("free.glb") + " --report " + path("free.json"));
    ASSERT_EQ(free.exitCode, 0) << free.output;
    const auto freeReport = nlohmann::json::parse(readFileToString(dir / "free.json"));
    EXPECT_FALSE(freeReport.contains("closure"));
    EXPECT_LE(freeReport["cost"].get<double>(), report["cost"].get<double>());
    const auto unknown = test::runCli("avatar reduce " + path("rpm.glb") +
                                      " -m 6 --closure viseme_MBP --out " + path("u.glb"));
    EXPECT_EQ(unknown.exitCode, 3) << unknown.output;
    EXPECT_NE(unknown.output.find("viseme_MBP"), std::string::npos) << unknown.output;

    // --rest key: the model before issue 29, silence in a key.
    const auto keyed = test::runCli("avatar reduce " + path("rpm.glb") + " -m 6 --rest key --out " +
                                    path("keyed.glb") + " --report " + path("keyed.json"));
    ASSERT_EQ(keyed.exitCode, 0) << keyed.output;
    const auto keyedReport = nlohmann::json::parse(readFileToString(dir / "keyed.json"));
    EXPECT_EQ(keyedReport["rest"]["model"], "key");
    EXPECT_TRUE(keyedReport["rest"]["resting"].empty());
    EXPECT_EQ(test::runCli("avatar reduce " + path("rpm.glb") + " -m 6 --rest none --out " + path("n.glb"))
                  .exitCode,
              2);
}

TEST_F(AvatarCli, ConstraintsAndMaxErrorAsInReduce) {
    // --pin and --apart hold in the avatar's reduction.
    const auto pinned =
        test::runCli("avatar reduce " + path("rpm.glb") + " -m 4 --pin viseme_aa --apart " +
                     "viseme_PP,viseme_FF --out " + path("pinned.glb") + " --report " + path("pinned.json"));
    ASSERT_EQ(pinned.exitCode, 0) << pinned.output;
    const auto report = nlohmann::json::parse(readFileToString(dir / "pinned.json"));
    bool aaAlone = false;
    for (const auto& group : report["groups"]) {
        const auto has = [&](const char* name) {
            return std::find(group.begin(), group.end(), name) != group.end();
        };
        if (has("viseme_aa")) aaAlone = group.size() == 1;
        EXPECT_FALSE(has("viseme_PP") && has("viseme_FF")) << group.dump();
    }
    EXPECT_TRUE(aaAlone) << report["groups"].dump();
    EXPECT_EQ(report["viseme_errors"]["unit"], "mm");
    ASSERT_EQ(report["viseme_errors"]["visemes"].size(), 15u);

    // --max-error-mm: the fewest keys that keep every viseme within the bound, proved; every viseme's
    // reported max error is within it, and one key fewer is not enough.
    const auto largest = [](const nlohmann::json& r) {
        double worst = 0;
        for (const auto& v : r["viseme_errors"]["visemes"]) worst = std::max(worst, v["max"].get<double>());
        return worst;
    };
    const double bound = 0.5 * largest(report);
    const auto within =
        test::runCli("avatar reduce " + path("rpm.glb") + " --max-error-mm " + std::to_string(bound) +
                     " --out " + path("within.glb") + " --report " + path("within.json"));
    ASSERT_EQ(within.exitCode, 0) << within.output;
    EXPECT_NE(within.output.find("is the fewest that keep every viseme within it (proved)"),
              std::string::npos)
        << within.output;
    const auto w = nlohmann::json::parse(readFileToString(dir / "within.json"));
    EXPECT_LE(largest(w), bound * (1 + 1e-9)) << w["viseme_errors"].dump();
    EXPECT_TRUE(w["max_error"]["certified"].get<bool>());
    const int keys = w["max_error"]["keys"].get<int>();
    EXPECT_EQ(w["groups"].size(), static_cast<std::size_t>(keys));
    if (keys > 1) {
        const auto fewer =
            test::runCli("avatar reduce " + path("rpm.glb") + " -m " + std::to_string(keys - 1) + " --out " +
                         path("fewer.glb") + " --report " + path("fewer.json"));
        ASSERT_EQ(fewer.exitCode, 0) << fewer.output;
        EXPECT_GT(largest(nlohmann::json::parse(readFileToString(dir / "fewer.json"))), bound);
    }
    EXPECT_EQ(
        test::runCli("avatar reduce " + path("rpm.glb") + " -m 3 --max-error-mm 1 --out " + path("x.glb"))
            .exitCode,
        2);
}

TEST_F(AvatarCli, ReduceRefusesToOverwriteItsInputAndChecksItsFlags) {
    const std::string before = readFileToString(dir / "rpm.glb");
    for (const std::string& args :
         {"-m 6 --out " + path("rpm.glb"), "-m 6 --out " + path("o.glb") + " --report " + path("rpm.glb"),
          "-m 6 --out " + path("o.gltf"), "-m 6 --out " + path("o.glb") + " --names short",
          "-m 6 --out " + path("o.glb") + " --weights painted", "--out " + path("o.glb")}) {
        const auto r = test::runCli("avatar reduce " + path("rpm.glb") + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    }
    EXPECT_EQ(readFileToString(dir / "rpm.glb"), before);
    // A frequency table in the bundled files' spelling applies to Ready Player Me's names.
    writeFileAtomically(dir / "freq.csv",
                        "viseme,frequency\nsil,5\nPP,1\nFF,1\nTH,1\nDD,1\nkk,1\nCH,1\nSS,1\nnn,1\n"
                        "RR,1\naa,3\nE,2\nih,2\noh,1\nou,1\n");
    const auto r = test::runCli("avatar reduce " + path("rpm.glb") + " -m 5 --freq-file " + path("freq.csv") +
                                " --out " + path("f.glb"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto bad = test::runCli("avatar reduce " + path("rpm.glb") + " -m 16 --out " + path("f.glb"));
    EXPECT_EQ(bad.exitCode, 3) << bad.output;
}

} // namespace
} // namespace vl
