// `visemelab face build` end to end on a face nobody here made (the MediaPipe canonical face from
// VISEMELAB_SHARED_DATA_DIR, skipped loudly when absent): the landmarks it says it found, the landmark
// file it writes read back as given ones, then visemes --project and refine --project on the
// project it wrote; a mesh without (u,v) is a data error naming the file.
#include "core/io/MeshIO.h"
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace vl {
namespace {

namespace fs = std::filesystem;

const fs::path kMediaPipe =
    fs::path(VISEMELAB_SHARED_DATA_DIR) / "mediapipe-canonical-face" / "canonical_face_model.obj";

TEST(OwnFaceCli, BuildThenVisemesAndRefineOnTheProject) {
    if (!fs::exists(kMediaPipe))
        GTEST_SKIP() << "shared data missing: " << kMediaPipe << " (set VISEMELAB_SHARED_DATA_DIR)";
    const fs::path dir = fs::temp_directory_path() / "visemelab_face_cli";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path project = dir / "mp.vlproj";
    auto r = test::runCli("face build " + kMediaPipe.string() + " --out " + project.string() +
                          " --landmarks-out " + (dir / "landmarks.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("recognised MediaPipe's canonical face topology"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("nose_tip            layout   sure"), std::string::npos) << r.output;
    ASSERT_TRUE(fs::exists(project));

    // The landmarks written read back: a second build from them says they were given.
    r = test::runCli("face build " + kMediaPipe.string() + " --landmarks " +
                     (dir / "landmarks.json").string() + " --out " + (dir / "again.vlproj").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("nose_tip            file"), std::string::npos) << r.output;

    r = test::runCli("visemes --project " + project.string() + " --out " + (dir / "visemes").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "visemes" / "aa.obj"));
    EXPECT_TRUE(fs::exists(dir / "visemes" / "neutral.obj"));

    r = test::runCli("refine --project " + project.string() + " --criterion contour --out " +
                     (dir / "refined.obj").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(readMesh(dir / "refined.obj").positions.size(), 100u);
    fs::remove_all(dir);
}

TEST(OwnFaceCli, MeshWithoutTextureCoordinatesIsADataError) {
    const fs::path dir = fs::temp_directory_path() / "visemelab_face_cli_nouv";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const auto r = test::runCli("face build " + (dir / "flat.obj").string() + " --out " +
                                (dir / "flat.vlproj").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("flat.obj"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "flat.vlproj"));
    fs::remove_all(dir);
}

} // namespace
} // namespace vl
