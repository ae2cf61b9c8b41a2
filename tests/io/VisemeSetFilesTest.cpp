#include "core/io/VisemeSetFiles.h"
#include "core/common/Error.h"
#include "core/io/MeshIO.h"
#include "tests/reduce/InputErrorText.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace vl;
using vl::test::errorOf;

namespace {

MeshData quadMesh(double z) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, z), Vec3(1, 0, z), Vec3(1, 1, z), Vec3(0, 1, z)};
    mesh.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
    return mesh;
}

struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

} // namespace

TEST(VisemeSetFiles, LoadsInterpolableSetAndKeepsOrder) {
    TempDir dir("visemelab_set_ok");
    writeMesh(dir.path / "neutral.obj", quadMesh(0));
    writeMesh(dir.path / "b.obj", quadMesh(2));
    writeMesh(dir.path / "a.ply", quadMesh(1));
    const auto files = listVisemeFolder(dir.path, dir.path / "neutral.obj");
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0].first, "a");
    EXPECT_EQ(files[1].first, "b");
    const auto set = loadVisemeSet(dir.path / "neutral.obj", files);
    EXPECT_EQ(set.size(), 2u);
    EXPECT_EQ(set.visemes[1].positions[2], Vec3(1, 1, 2));
    EXPECT_EQ(set.find("b"), 1);
    EXPECT_EQ(set.meshOf(0).positions[0], Vec3(0, 0, 1));
}

TEST(VisemeSetFiles, NonInterpolableMeshesAreNamed) {
    TempDir dir("visemelab_set_bad");
    writeMesh(dir.path / "neutral.obj", quadMesh(0));
    auto fewer = quadMesh(1);
    fewer.positions.pop_back();
    fewer.triangles.pop_back();
    writeMesh(dir.path / "fewer.obj", fewer);
    auto flipped = quadMesh(1);
    flipped.triangles[1] = Triangle{0, 3, 2};
    writeMesh(dir.path / "flipped.obj", flipped);
    writeMesh(dir.path / "ok.obj", quadMesh(1));

    auto msg = errorOf([&] {
        loadVisemeSet(dir.path / "neutral.obj", {{"ok", dir.path / "ok.obj"}, {"f", dir.path / "fewer.obj"}});
    });
    EXPECT_NE(msg.find("fewer.obj: not interpolable: 3 vertices"), std::string::npos) << msg;
    msg = errorOf([&] {
        loadVisemeSet(dir.path / "neutral.obj",
                      {{"ok", dir.path / "ok.obj"}, {"f", dir.path / "flipped.obj"}});
    });
    EXPECT_NE(msg.find("flipped.obj: not interpolable: triangle 1 is (0 3 2) but (0 2 3)"), std::string::npos)
        << msg;
    msg = errorOf([&] { loadVisemeSet(dir.path / "neutral.obj", {{"ok", dir.path / "ok.obj"}}); });
    EXPECT_NE(msg.find("at least 2 visemes"), std::string::npos) << msg;
    msg = errorOf([&] {
        loadVisemeSet(dir.path / "neutral.obj", {{"x", dir.path / "ok.obj"}, {"x", dir.path / "ok.obj"}});
    });
    EXPECT_NE(msg.find("duplicate viseme name 'x'"), std::string::npos) << msg;
    msg = errorOf([&] {
        loadVisemeSet(dir.path / "neutral.obj",
                      {{"x", dir.path / "ok.obj"}, {"y", dir.path / "missing.obj"}});
    });
    EXPECT_NE(msg.find("missing.obj: file not found"), std::string::npos) << msg;
}

TEST(VisemeSetFiles, OneNeutralRuleExactNameFirstThenContainingAndAmbiguityNamed) {
    TempDir dir("visemelab_set_neutral");
    writeMesh(dir.path / "aa.obj", quadMesh(1));
    EXPECT_NE(errorOf([&] { findNeutralMesh(dir.path); }).find("no neutral mesh in the folder"),
              std::string::npos);
    writeMesh(dir.path / "face_neutral_v2.obj", quadMesh(0));
    EXPECT_EQ(findNeutralMesh(dir.path), dir.path / "face_neutral_v2.obj"); // contains "neutral"
    writeMesh(dir.path / "Neutral.PLY", quadMesh(0));
    EXPECT_EQ(findNeutralMesh(dir.path), dir.path / "Neutral.PLY"); // the exact stem wins, any case
    writeMesh(dir.path / "neutral.obj", quadMesh(0));
    const std::string msg = errorOf([&] { findNeutralMesh(dir.path); });
    EXPECT_NE(msg.find("several meshes could be the neutral (Neutral.PLY, neutral.obj)"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find(dir.path.string()), std::string::npos) << msg;
    std::filesystem::remove(dir.path / "Neutral.PLY");
    std::filesystem::remove(dir.path / "face_neutral_v2.obj");
    std::filesystem::create_directory(dir.path / "neutral.d"); // not a mesh file: ignored
    EXPECT_EQ(findNeutralMesh(dir.path), dir.path / "neutral.obj");
}

TEST(VisemeSetFiles, ValueErrorsNameTheFileTheVisemeWasReadFrom) {
    // The set does not record where a viseme came from: the loader passes the files to the check.
    TempDir dir("visemelab_set_values");
    writeMesh(dir.path / "neutral.obj", quadMesh(0));
    writeMesh(dir.path / "ok.obj", quadMesh(1));
    auto huge = quadMesh(1);
    huge.positions[2][1] = 1e31;
    writeMesh(dir.path / "huge.obj", huge);
    const std::string msg = errorOf([&] {
        loadVisemeSet(dir.path / "neutral.obj", {{"ok", dir.path / "ok.obj"}, {"h", dir.path / "huge.obj"}});
    });
    EXPECT_NE(msg.find("huge.obj: vertex 3: coordinate"), std::string::npos) << msg;

    // Without files (generated or embedded shapes) the error names the set and the viseme.
    VisemeSet set;
    set.neutral = quadMesh(0);
    set.visemes = {{"ok", quadMesh(1).positions}, {"h", huge.positions}};
    const std::string embedded = errorOf([&] { checkVisemeSetValues(set, "arrays"); });
    EXPECT_NE(embedded.find("arrays: viseme h: vertex 3"), std::string::npos) << embedded;
    const std::vector<std::filesystem::path> files{"", "given.ply"};
    const std::string given = errorOf([&] { checkVisemeSetValues(set, "arrays", files); });
    EXPECT_NE(given.find("given.ply: vertex 3"), std::string::npos) << given;
}
