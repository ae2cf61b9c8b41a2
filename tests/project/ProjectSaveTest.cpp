// Saving: atomic (a failed save leaves the previous file untouched), validated, and relative mesh
// paths follow the project when it is saved into another folder.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/project/ProjectRun.h"

#include <cmath>
#include <csignal>
#include <sys/resource.h>

namespace vl {
namespace {

using test::ScratchDir;

Project smallProject(const std::filesystem::path& file) {
    Project p;
    p.path = file;
    p.neutral.embedded.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.neutral.embedded.triangles = {{0, 1, 2}};
    p.visemes = {{"a", {}, {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}}, {"b", {}, {{0, 0, 2}, {1, 0, 2}, {0, 1, 2}}}};
    p.frequencies.visemeFrequencies.entries = {{"a", 0.25}, {"b", 0.75}};
    return p;
}

std::size_t filesIn(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

TEST(ProjectSave, EmptyNewProjectSavesAndLoads) {
    ScratchDir dir("empty");
    Project empty;
    saveProject(dir / "new.vlproj", empty);
    Project loaded = loadProject(dir / "new.vlproj");
    EXPECT_EQ(loaded.path, dir / "new.vlproj");
    loaded.path.clear();
    EXPECT_TRUE(loaded == empty);
}

TEST(ProjectSave, InvalidStateIsRefusedWithItsPathAndTheOldFileStays) {
    ScratchDir dir("invalid");
    const auto file = dir / "p.vlproj";
    Project p = smallProject(file);
    saveProject(file, p);
    const std::string before = readFileToString(file);

    p.frequencies.visemeFrequencies.entries[1].second = std::nan("");
    EXPECT_INPUT_ERROR(saveProject(file, p),
                       "cannot save " + file.string() +
                           ": /frequencies/visemes/b: expected a non-negative number, found null");
    p = smallProject(file);
    p.frequencies.visemeFrequencies.entries[1].first = "a";
    EXPECT_INPUT_ERROR(saveProject(file, p), "/frequencies/visemes/a: duplicate viseme");
    p = smallProject(file);
    p.reduction.target = 3;
    EXPECT_INPUT_ERROR(saveProject(file, p), "/reduction/target: 3 is outside the allowed range 1..2");
    p = smallProject(file);
    p.visemes[0].file = "a.obj";
    EXPECT_INPUT_ERROR(saveProject(file, p), "/visemes/0: has both a file and embedded positions");
    p = smallProject(file);
    p.reduction.result = ReductionResult{{Grouping{.cost = 0.0, .groups = {{1}, {0}}}}};
    EXPECT_INPUT_ERROR(saveProject(file, p), "/reduction/result/curve/0/groups: expected 1 groups");
    p.reduction.result =
        ReductionResult{{Grouping{.cost = 0.0, .groups = {{1, 0}}}}}; // members not ascending
    EXPECT_INPUT_ERROR(saveProject(file, p), "does not survive a save/load round trip");

    EXPECT_EQ(readFileToString(file), before);
    EXPECT_EQ(filesIn(dir.path), 1u); // no temporary files left behind
}

TEST(ProjectSave, UnwritableDestinationFailsCleanly) {
    ScratchDir dir("unwritable");
    test::writeText(dir / "not-a-folder", "x");
    EXPECT_INPUT_ERROR(saveProject(dir / "not-a-folder" / "p.vlproj", smallProject(dir / "p.vlproj")),
                       (dir / "not-a-folder" / "p.vlproj").string());
    // A folder where the file should go cannot be replaced.
    std::filesystem::create_directories(dir / "taken.vlproj");
    EXPECT_INPUT_ERROR(saveProject(dir / "taken.vlproj", smallProject(dir / "p.vlproj")),
                       "taken.vlproj: is a folder; cannot write a file there");
    EXPECT_TRUE(std::filesystem::is_directory(dir / "taken.vlproj"));
    EXPECT_EQ(filesIn(dir.path), 2u);
}

// A full disk, simulated with a file-size limit (works as root, unlike a read-only folder): the write
// of the temporary file fails and the previous project file is unchanged.
TEST(ProjectSave, FailedWriteLeavesThePreviousFile) {
    ScratchDir dir("diskfull");
    const auto file = dir / "p.vlproj";
    Project p = smallProject(file);
    saveProject(file, p);
    const std::string before = readFileToString(file);

    p.weights.mode = WeightMode::Painted;
    p.weights.painted.assign(3, 1.0);
    p.visemes[0].positions.assign(3, Vec3(1.0 / 3.0, 2.0 / 3.0, 1.0 / 7.0));
    p.neutral.embedded.positions.assign(3, Vec3(0.1, 0.2, 0.3));
    const std::string text = projectToJsonText(p);
    ASSERT_GT(text.size(), before.size() + 16);

    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = old;
    limited.rlim_cur = before.size() + 8;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
    const std::string message = test::inputErrorOf([&] { saveProject(file, p); });
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, previousHandler);

    EXPECT_NE(message.find("write failed"), std::string::npos) << message;
    EXPECT_EQ(readFileToString(file), before);
    EXPECT_EQ(filesIn(dir.path), 1u);
    saveProject(file, p); // with the limit lifted the same save works
    EXPECT_EQ(readFileToString(file), text);
}

TEST(ProjectSave, SavingElsewhereRebasesRelativeMeshPaths) {
    ScratchDir dir("rebase");
    test::writeText(dir / "a" / "meshes" / "n.obj", "");
    test::writeText(dir / "a" / "meshes" / "v.obj", "");
    test::writeText(dir / "w.obj", "");
    Project p;
    p.path = dir / "a" / "p.vlproj";
    p.neutral.file = "meshes/n.obj";
    p.visemes = {{"v", "meshes/v.obj", {}}, {"w", dir / "w.obj", {}}};
    saveProject(p.path, p);

    const auto moved = dir / "b" / "c" / "q.vlproj";
    saveProject(moved, loadProject(p.path));
    const Project q = loadProject(moved);
    EXPECT_EQ(q.neutral.file, "../../a/meshes/n.obj");
    EXPECT_EQ(q.visemes[0].file, "../../a/meshes/v.obj");
    EXPECT_EQ(q.visemes[1].file, "../../w.obj");
    EXPECT_EQ(resolveProjectFile(q, q.visemes[0].file), (dir / "a" / "meshes" / "v.obj").lexically_normal());
    EXPECT_TRUE(rebaseProject(q, p.path) == loadProject(p.path));
}

std::string triangleObj(double z) {
    const std::string zs = std::to_string(z);
    return "v 0 0 " + zs + "\nv 1 0 " + zs + "\nv 0 1 " + zs + "\nf 1 2 3\n";
}

// Absolute paths (as the editor holds them after loading a folder or the bundled sample) are stored
// relative to the project file, so the project folder can be moved or copied as a whole.
TEST(ProjectSave, AbsoluteMeshPathsAreStoredRelativeAndSurviveMovingTheFolder) {
    ScratchDir dir("relative");
    const auto home = dir / "home";
    test::writeText(home / "meshes" / "neutral.obj", triangleObj(0));
    test::writeText(home / "meshes" / "aa.obj", triangleObj(1));
    test::writeText(home / "oh.obj", triangleObj(2));
    Project p; // untitled, as after File > Load sample
    p.neutral.file = home / "meshes" / "neutral.obj";
    p.visemes = {{"aa", home / "meshes" / "aa.obj", {}}, {"oh", home / "oh.obj", {}}};
    saveProject(home / "project.vlproj", p);

    const std::string text = readFileToString(home / "project.vlproj");
    EXPECT_EQ(text.find(home.string()), std::string::npos) << "no absolute path in the file:\n" << text;
    const Project saved = loadProject(home / "project.vlproj");
    EXPECT_EQ(saved.neutral.file, "meshes/neutral.obj");
    EXPECT_EQ(saved.visemes[0].file, "meshes/aa.obj");
    EXPECT_EQ(saved.visemes[1].file, "oh.obj");

    const auto moved = dir / "elsewhere" / "renamed";
    std::filesystem::create_directories(moved.parent_path());
    std::filesystem::rename(home, moved);
    const Project reopened = loadProject(moved / "project.vlproj");
    const VisemeSet set = loadProjectVisemeSet(reopened);
    ASSERT_EQ(set.visemes.size(), 2u);
    EXPECT_EQ(set.visemes[1].positions[0][2], 2.0);
    EXPECT_EQ(set.neutralSource, (moved / "meshes" / "neutral.obj").lexically_normal());

    // Saving the moved project again writes the same text: the paths are still relative.
    saveProject(moved / "project.vlproj", reopened);
    EXPECT_EQ(readFileToString(moved / "project.vlproj"), text);
}

} // namespace
} // namespace vl
