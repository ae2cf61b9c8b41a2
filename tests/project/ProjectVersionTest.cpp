// Versions: newer files are refused, unknown ones too, and version 0 (the flat pre-release layout)
// is migrated to the current layout.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"

namespace vl {
namespace {

using test::ScratchDir;

TEST(ProjectVersion, NewerVersionIsRefusedWithAClearMessage) {
    ScratchDir dir("newer");
    test::writeText(dir / "p.vlproj",
                    R"({"format": "visemelab-project", "version": 7, "whatever": {"new": true}})");
    EXPECT_INPUT_ERROR(loadProject(dir / "p.vlproj"),
                       "/version: project version 7 is newer than this VisemeLab (supports up to 5)");
}

TEST(ProjectVersion, UnknownVersionsAreRefused) {
    ScratchDir dir("unknown");
    test::writeText(dir / "p.vlproj", R"({"format": "visemelab-project", "version": -1})");
    EXPECT_INPUT_ERROR(loadProject(dir / "p.vlproj"),
                       "/version: unknown project version -1 (this VisemeLab reads versions 0..5)");
    test::writeText(dir / "p.vlproj", R"({"format": "visemelab-project", "version": 1.5})");
    EXPECT_INPUT_ERROR(loadProject(dir / "p.vlproj"), "/version: expected an integer, found 1.5");
    test::writeText(dir / "p.vlproj", R"({"format": "visemelab-project", "version": "1"})");
    EXPECT_INPUT_ERROR(loadProject(dir / "p.vlproj"), "/version: expected an integer, found string \"1\"");
}

class ProjectMigration : public ::testing::Test {
  protected:
    ProjectMigration() : dir("migration") {
        for (const char* name : {"neutral.obj", "sil.obj", "aa.obj", "oh.obj"})
            test::writeText(dir / "meshes" / name, "");
    }
    ScratchDir dir;
};

TEST_F(ProjectMigration, Version0PhonemeLayoutLoadsAsTheSameStateAsVersion1) {
    test::writeText(dir / "old.vlproj", R"({
      "format": "visemelab-project", "version": 0,
      "neutral": "meshes/neutral.obj",
      "visemes": {"sil": "meshes/sil.obj", "aa": "meshes/aa.obj", "oh": "meshes/oh.obj"},
      "phonemes": {"AA": 0.6, "OW": 0.3, "SIL": 0.1},
      "phoneme_map": {"AA": "aa", "OW": "oh", "SIL": "sil"},
      "weights": [1, 2, 0.5],
      "target": 2
    })");
    test::writeText(dir / "new.vlproj", R"({
      "format": "visemelab-project", "version": 1,
      "neutral": {"file": "meshes/neutral.obj"},
      "visemes": [{"name": "sil", "file": "meshes/sil.obj"}, {"name": "aa", "file": "meshes/aa.obj"},
                  {"name": "oh", "file": "meshes/oh.obj"}],
      "frequencies": {"phonemes": {"AA": 0.6, "OW": 0.3, "SIL": 0.1}, "map": {"AA": "aa", "OW": "oh", "SIL": "sil"}},
      "weights": {"mode": "painted", "painted": [1, 2, 0.5]},
      "reduction": {"target": 2, "result": null},
      "editor": {"selectedViseme": ""}
    })");
    Project migrated = loadProject(dir / "old.vlproj");
    const Project current = loadProject(dir / "new.vlproj");
    EXPECT_EQ(migrated.path, dir / "old.vlproj");
    migrated.path = current.path;
    EXPECT_TRUE(migrated == current);
    migrated.path = dir / "old.vlproj";

    // Saving writes the lowest version that holds it (1: no face (u,v) mesh); it loads back unchanged.
    saveProject(dir / "old.vlproj", migrated);
    EXPECT_NE(readFileToString(dir / "old.vlproj").find("\"version\": 1"), std::string::npos);
    EXPECT_TRUE(loadProject(dir / "old.vlproj") == migrated);
}

TEST_F(ProjectMigration, Version0DirectFrequenciesAndNamedWeightMode) {
    test::writeText(dir / "old.vlproj", R"({"format": "visemelab-project", "version": 0,
      "neutral": "meshes/neutral.obj", "visemes": {"sil": "meshes/sil.obj", "aa": "meshes/aa.obj"},
      "frequencies": {"sil": 1, "aa": 3}, "weights": "area", "target": 1})");
    const Project p = loadProject(dir / "old.vlproj");
    ASSERT_EQ(p.visemes.size(), 2u);
    EXPECT_EQ(p.visemes[1].name, "aa");
    EXPECT_EQ(p.visemes[1].file, "meshes/aa.obj");
    EXPECT_FALSE(p.frequencies.isPhonemeBased());
    EXPECT_EQ(*p.frequencies.visemeFrequencies.find("aa"), 3.0);
    EXPECT_EQ(p.weights.mode, WeightMode::Area);
    EXPECT_EQ(p.reduction.target, 1);
    EXPECT_FALSE(p.reduction.result);
}

TEST_F(ProjectMigration, Version0ErrorsNameTheirPlace) {
    const std::string head =
        R"({"format": "visemelab-project", "version": 0, "neutral": "meshes/neutral.obj", )";
    test::writeText(dir / "old.vlproj", head + R"("visemes": ["meshes/sil.obj"], "target": 1})");
    EXPECT_INPUT_ERROR(loadProject(dir / "old.vlproj"), "/visemes: expected an object, found array");
    test::writeText(dir / "old.vlproj", head + R"("visemes": {"sil": 3}, "target": 1})");
    EXPECT_INPUT_ERROR(loadProject(dir / "old.vlproj"), "/visemes/sil: expected a string, found 3");
    test::writeText(dir / "old.vlproj", head + R"("visemes": {"sil": "meshes/sil.obj"}})");
    EXPECT_INPUT_ERROR(loadProject(dir / "old.vlproj"), "/target: missing field");
    test::writeText(dir / "old.vlproj",
                    head + R"("visemes": {"sil": "meshes/sil.obj"}, "target": 1, "extra": 0})");
    EXPECT_INPUT_ERROR(loadProject(dir / "old.vlproj"), "/extra: unknown field");
    // Value errors are found by the current reader, in the migrated layout, and say so.
    test::writeText(dir / "old.vlproj",
                    head + R"("visemes": {"sil": "meshes/sil.obj", "aa": "meshes/gone.obj"}, "target": 1})");
    EXPECT_INPUT_ERROR(
        loadProject(dir / "old.vlproj"),
        "in the version 0 project after migration to version 1: /visemes/1/file: file not found");
    test::writeText(dir / "old.vlproj",
                    head +
                        R"("visemes": {"sil": "meshes/sil.obj"}, "frequencies": {"sil": -1}, "target": 1})");
    EXPECT_INPUT_ERROR(loadProject(dir / "old.vlproj"),
                       "/frequencies/visemes/sil: expected a non-negative number");
}

} // namespace
} // namespace vl

namespace vl {
namespace {

TEST(ProjectFile, MissingEmptyOrForeignFilesAreRefused) {
    test::ScratchDir dir("files");
    EXPECT_INPUT_ERROR(loadProject(dir / "none.vlproj"), (dir / "none.vlproj").string() + ": file not found");
    test::writeText(dir / "empty.vlproj", "");
    EXPECT_INPUT_ERROR(loadProject(dir / "empty.vlproj"), (dir / "empty.vlproj").string() + ": invalid JSON");
    test::writeText(dir / "mesh.vlproj", "v 0 0 0\nf 1 2 3\n");
    EXPECT_INPUT_ERROR(loadProject(dir / "mesh.vlproj"), "invalid JSON: parse error at line 1, column 1");
    test::writeText(dir / "other.vlproj", R"({"asset": {"version": "2.0"}})");
    EXPECT_INPUT_ERROR(loadProject(dir / "other.vlproj"),
                       (dir / "other.vlproj").string() + ": /format: missing field");
}

} // namespace
} // namespace vl
