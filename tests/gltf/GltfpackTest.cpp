// Re-compressing a reduced avatar with gltfpack (core/gltf/Gltfpack.h): the real tool (the npm
// package, installed into the build folder by the gltfpack_install test; these tests skip loudly
// without it), its output read back by VisemeLab's own reader and checked by the Khronos validator.
#include "core/gltf/Gltfpack.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "tests/cli/CliRunner.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace vl {
namespace {

#define REQUIRE_GLTFPACK()                                                                                   \
    const std::filesystem::path gltfpack = findGltfpack();                                                   \
    if (gltfpack.empty())                                                                                    \
    GTEST_SKIP() << "SKIPPED LOUDLY: gltfpack not found (" << kGltfpackHint                                  \
                 << "; ctest installs it with the gltfpack_install test)"

std::filesystem::path outputDir() {
    const auto dir = std::filesystem::path(VISEMELAB_BUILD_DIR) / "gltfpack-outputs";
    std::filesystem::create_directories(dir);
    return dir;
}

AvatarReduction reduced(const GltfDocument& doc, const AvatarScan& scan, AvatarNames names, int m = 6) {
    ReduceSettings settings;
    settings.target = m;
    AvatarWriteOptions options;
    options.names = names;
    return reduceAvatar(doc, scan, uniformFrequencies(scan), settings, options);
}

const nlohmann::ordered_json* meshNamed(const nlohmann::ordered_json& json, const std::string& name) {
    for (const auto& mesh : json["meshes"])
        if (mesh.value("name", std::string()) == name) return &mesh;
    return nullptr;
}

TEST(Gltfpack, ReducedAvatarIsRecompressedWithItsNamesAndPhonemeMaps) {
    REQUIRE_GLTFPACK();
    std::vector<std::string> written;
    for (auto storage : {test::FixtureStorage::Plain, test::FixtureStorage::Meshopt}) {
        test::AvatarFixtureOptions fixture;
        fixture.storage = storage;
        const GltfDocument doc = parseGltfDocument(test::rpmLikeAvatar(fixture), "rpm.glb", {});
        const AvatarScan scan = scanAvatar(doc, {""});
        for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
            const std::string what =
                std::string(storage == test::FixtureStorage::Plain ? "plain" : "meshopt") + "_" +
                toString(names);
            const AvatarReduction r = reduced(doc, scan, names);
            const Recompressed packed = recompressWithGltfpack(r.glb, gltfpack, {""});
            EXPECT_LT(packed.glb.size(), r.glb.size()) << what;
            ASSERT_FALSE(packed.notes.empty());
            EXPECT_NE(packed.notes.front().find("re-compressed with gltfpack"), std::string::npos);

            const GltfDocument before = parseGltfDocument(r.glb, "reduced.glb", {});
            const GltfDocument after = parseGltfDocument(packed.glb, "packed.glb", {});
            const auto& used = after.model.extensionsUsed;
            EXPECT_NE(std::find(used.begin(), used.end(), "EXT_meshopt_compression"), used.end()) << what;
            // The key table, and on every mesh its name, targets and phoneme map, as written before.
            EXPECT_EQ(after.json["extras"]["visemelab"], before.json["extras"]["visemelab"]) << what;
            for (const auto& mesh : before.json["meshes"]) {
                const auto* same = meshNamed(after.json, mesh["name"]);
                ASSERT_NE(same, nullptr) << what << ": mesh " << mesh["name"];
                EXPECT_EQ(same->value("extras", nlohmann::ordered_json()),
                          mesh.value("extras", nlohmann::ordered_json()))
                    << what << ": " << mesh["name"];
            }
            EXPECT_EQ(after.model.skins.size(), before.model.skins.size());
            EXPECT_EQ(after.model.materials.size(), before.model.materials.size());
            EXPECT_EQ(after.model.animations.size(), before.model.animations.size());
            // Read back, the same visemes over the same geometry, up to gltfpack's quantisation.
            const AvatarScan a = scanAvatar(after, {""}), b = scanAvatar(before, {""});
            ASSERT_EQ(a.visemes, b.visemes) << what;
            ASSERT_EQ(a.set.vertexCount(), b.set.vertexCount()) << what;
            const auto file = outputDir() / ("rpm_" + what + "_gltfpack.glb");
            writeFileAtomically(file, packed.glb);
            written.push_back(file.string());
        }
    }
    // The Khronos validator: 0 errors (exit 77: it could not be installed, reported as a skip).
    std::string command = std::string(VISEMELAB_SOURCE_DIR) + "/scripts/gltf-validate.sh " +
                          VISEMELAB_BUILD_DIR + "/gltf-validator";
    for (const std::string& file : written) command += " " + file;
    const int status =
        std::system((command + " > " + (outputDir() / "validator.txt").string() + " 2>&1").c_str());
    ASSERT_TRUE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 77)
        GTEST_SKIP() << "SKIPPED LOUDLY: the Khronos validator could not be installed";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "see " << (outputDir() / "validator.txt");
}

TEST(Gltfpack, AVrmIsRefusedNamingTheExtension) {
    const GltfDocument doc = parseGltfDocument(test::vroidLikeAvatar(), "vroid.vrm", {});
    const AvatarScan scan = scanAvatar(doc, {"Fcl_MTH_[AIUEO]"});
    const AvatarReduction r = reduced(doc, scan, AvatarNames::Original, 3);
    try {
        recompressWithGltfpack(r.glb, "/bin/true", {"Fcl_MTH_[AIUEO]"});
        FAIL() << "a VRM was re-compressed";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("gltfpack drops the VRM extension"), std::string::npos)
            << e.what();
    }
}

TEST(Gltfpack, WithoutGltfpackTheErrorSaysHowToGetIt) {
    const GltfDocument doc = parseGltfDocument(test::rpmLikeAvatar(), "rpm.glb", {});
    const AvatarReduction r = reduced(doc, scanAvatar(doc, {""}), AvatarNames::Original);
    for (const std::filesystem::path& missing :
         {std::filesystem::path(), std::filesystem::path("/nonexistent/gltfpack")}) {
        try {
            recompressWithGltfpack(r.glb, missing, {""});
            FAIL() << "no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("npm install -g gltfpack"), std::string::npos) << e.what();
        }
    }
    // A tool that fails: its exit status in the message, nothing written.
    try {
        recompressWithGltfpack(r.glb, "/bin/false", {""});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("exit status 1"), std::string::npos) << e.what();
    }
}

TEST(Gltfpack, CliRecompressesOnRequestAndSaysHowWhenCompressedInputIsWrittenUncompressed) {
    const auto dir = outputDir() / "cli";
    std::filesystem::create_directories(dir);
    test::AvatarFixtureOptions fixture;
    fixture.storage = test::FixtureStorage::Meshopt;
    writeFileAtomically(dir / "in.glb", test::rpmLikeAvatar(fixture));
    const std::string in = (dir / "in.glb").string(), out = (dir / "out.glb").string();
    // Without --gltfpack: the note says how to re-compress.
    const auto plain = test::runCli("avatar reduce " + in + " --target 5 --out " + out);
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_NE(plain.output.find("--gltfpack"), std::string::npos) << plain.output;
    // With --gltfpack but none to run: exit 3, how to get it, nothing written.
    const auto refused = test::runCliWith("VISEMELAB_GLTFPACK=/nonexistent/gltfpack ",
                                          "avatar reduce " + in + " --target 5 --gltfpack --out " +
                                              (dir / "none.glb").string());
    EXPECT_EQ(refused.exitCode, 3) << refused.output;
    EXPECT_NE(refused.output.find("npm install -g gltfpack"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "none.glb"));
    REQUIRE_GLTFPACK();
    const auto packed = test::runCli("avatar reduce " + in + " --target 5 --gltfpack --out " + out);
    ASSERT_EQ(packed.exitCode, 0) << packed.output;
    EXPECT_NE(packed.output.find("re-compressed with gltfpack"), std::string::npos) << packed.output;
    const auto inspect = test::runCli("avatar inspect " + out);
    EXPECT_NE(inspect.output.find("Visemes: 15"), std::string::npos) << inspect.output;
    EXPECT_NE(inspect.output.find("Wolf3D_Head"), std::string::npos) << inspect.output;
}

} // namespace
} // namespace vl
