// From a project to meshes and a reduction: the same outcome as the plain reduction API, and mesh
// errors that name the JSON path and the file.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"
#include "core/project/ProjectRun.h"

namespace vl {
namespace {

using test::ScratchDir;

// A 3x3-vertex grid patch and viseme shapes that move its vertices differently.
MeshData patch() {
    MeshData mesh;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            mesh.positions.emplace_back(i, j, 0);
            mesh.uvs.emplace_back(i / 2.0, j / 2.0);
        }
    for (std::uint32_t j = 0; j < 2; ++j)
        for (std::uint32_t i = 0; i < 2; ++i) {
            const std::uint32_t a = j * 3 + i;
            mesh.triangles.push_back({a, a + 1, a + 4});
            mesh.triangles.push_back({a, a + 4, a + 3});
        }
    return mesh;
}

MeshData shape(const MeshData& base, double seed) {
    MeshData mesh = base;
    for (std::size_t k = 0; k < mesh.positions.size(); ++k)
        mesh.positions[k][2] = std::sin(seed * static_cast<double>(k + 1)) * (k % 3 + 1);
    return mesh;
}

class ProjectRun : public ::testing::Test {
  protected:
    ProjectRun() : dir("run") {
        const MeshData base = patch();
        writeMesh(dir / "meshes" / "neutral.obj", base);
        project.path = dir / "face.vlproj";
        project.neutral.file = "meshes/neutral.obj";
        const char* names[] = {"sil", "aa", "E", "oh", "PP"};
        for (int i = 0; i < 5; ++i) {
            const std::string file = std::string("meshes/") + names[i] + (i % 2 ? ".ply" : ".wrl");
            writeMesh(dir / file, shape(base, 0.3 + i));
            project.visemes.push_back({names[i], file, {}});
            project.frequencies.visemeFrequencies.entries.emplace_back(names[i], 1.0 + i);
        }
        project.weights.mode = WeightMode::Area;
        project.reduction.target = 3;
    }
    ScratchDir dir;
    Project project;
};

TEST_F(ProjectRun, ReductionEqualsThePlainApiOnTheSameFiles) {
    saveProject(project.path, project);
    Project loaded = loadProject(project.path);
    const VisemeSet set = loadProjectVisemeSet(loaded);
    ASSERT_EQ(set.size(), 5u);

    std::vector<std::pair<std::string, std::filesystem::path>> files;
    for (const auto& v : project.visemes) files.emplace_back(v.name, dir / v.file);
    const VisemeSet direct = loadVisemeSet(dir / "meshes" / "neutral.obj", files);
    for (std::size_t i = 0; i < set.size(); ++i)
        EXPECT_EQ(set.visemes[i].positions, direct.visemes[i].positions);

    const ReduceOutcome outcome = reduceProject(loaded, set);
    ReduceSettings settings;
    settings.weightMode = WeightMode::Area;
    settings.target = 3;
    const ReduceOutcome expected = runReduction(direct, project.frequencies, settings);
    ASSERT_EQ(outcome.result.curve.size(), 3u);
    for (std::size_t p = 0; p < 3; ++p) {
        EXPECT_EQ(outcome.result.curve[p].cost, expected.result.curve[p].cost);
        EXPECT_EQ(outcome.result.curve[p].groups, expected.result.curve[p].groups);
    }

    // The result is stored and survives a save/load round trip exactly.
    storeReductionResult(loaded, outcome);
    saveProject(loaded.path, loaded);
    const Project reloaded = loadProject(loaded.path);
    EXPECT_TRUE(reloaded == loaded);
    EXPECT_EQ(reloaded.reduction.result->best().groups, expected.result.best().groups);
}

TEST_F(ProjectRun, TheProjectsRestModelRunsAndItsResultIsKeptOnlyForThatModel) {
    const VisemeSet set = loadProjectVisemeSet(project);
    // Keyed (a file without /reduction/rest): every viseme is in a key.
    const ReduceOutcome keyed = reduceProject(project, set);
    EXPECT_FALSE(keyed.result.restFree);
    EXPECT_TRUE(keyed.result.best().rest.empty());
    // Rest-free: sil rests by definition, as with the CLI's --rest free.
    Project free = project;
    free.reduction.rest = RestChoice::Free;
    const ReduceOutcome outcome = reduceProject(free, set);
    ReduceSettings settings = projectReduceSettings(free);
    settings.rest = RestChoice::Free;
    const ReduceOutcome expected = runReduction(set, free.frequencies, settings);
    EXPECT_TRUE(outcome.result.restFree);
    EXPECT_EQ(outcome.result, expected.result);
    EXPECT_EQ(outcome.result.best().groupOf()[0], kRestGroup);
    // The stored keyed result is not the rest-free project's model: it reduces afresh.
    storeReductionResult(free, keyed);
    EXPECT_EQ(projectReducedModel(free, set).resting, outcome.model.resting);
    EXPECT_FALSE(projectReducedModel(free, set).resting.empty());
    // A named rest viseme that the set lacks is refused at its JSON path.
    free.reduction.restViseme = "neutral";
    EXPECT_INPUT_ERROR(reduceProject(free, set),
                       "face.vlproj: /reduction/restViseme: the set has no viseme 'neutral'");
}

TEST_F(ProjectRun, EmbeddedMeshesGiveTheSameSet) {
    Project embedded = project;
    const VisemeSet fromFiles = loadProjectVisemeSet(project);
    embedded.neutral.file.clear();
    embedded.neutral.embedded = fromFiles.neutral;
    for (std::size_t i = 0; i < embedded.visemes.size(); ++i) {
        embedded.visemes[i].file.clear();
        embedded.visemes[i].positions = fromFiles.visemes[i].positions;
    }
    saveProject(embedded.path, embedded);
    const VisemeSet set = loadProjectVisemeSet(loadProject(embedded.path));
    EXPECT_EQ(set.neutral.positions, fromFiles.neutral.positions);
    EXPECT_EQ(set.neutral.uvs, fromFiles.neutral.uvs);
    EXPECT_EQ(set.neutral.triangles, fromFiles.neutral.triangles);
    for (std::size_t i = 0; i < set.size(); ++i)
        EXPECT_EQ(set.visemes[i].positions, fromFiles.visemes[i].positions);
}

TEST_F(ProjectRun, MeshErrorsNameTheJsonPathAndFile) {
    MeshData other = patch();
    other.triangles.pop_back();
    writeMesh(dir / "meshes" / "oh.ply", other);
    EXPECT_INPUT_ERROR(loadProjectVisemeSet(project),
                       "/visemes/3/file (meshes/oh.ply): not interpolable: 7 triangles");

    test::writeText(
        dir / "meshes" / "E.wrl",
        "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 nan ] } } }\n");
    EXPECT_INPUT_ERROR(loadProjectVisemeSet(project), "/visemes/2/file (meshes/E.wrl): ");

    std::filesystem::remove(dir / "meshes" / "neutral.obj");
    EXPECT_INPUT_ERROR(loadProjectVisemeSet(project), "/neutral/file (meshes/neutral.obj): ");

    Project none;
    EXPECT_INPUT_ERROR(loadProjectVisemeSet(none), "/neutral: the project has no neutral mesh");
}

TEST_F(ProjectRun, EmbeddedVisemeWithTheWrongVertexCount) {
    project.visemes[1].file.clear();
    project.visemes[1].positions.assign(4, Vec3(0, 0, 0));
    EXPECT_INPUT_ERROR(loadProjectVisemeSet(project), "/visemes/1/positions: not interpolable: 4 vertices");
}

TEST_F(ProjectRun, ReductionInputErrors) {
    const VisemeSet set = loadProjectVisemeSet(project);
    Project p = project;
    p.weights.mode = WeightMode::Painted;
    p.weights.painted = {1, 2};
    EXPECT_INPUT_ERROR(reduceProject(p, set),
                       "/weights/painted: expected 9 weights (one per vertex), found 2");
    p = project;
    p.reduction.target = 6;
    EXPECT_INPUT_ERROR(reduceProject(p, set), "/reduction/target: 6 is outside the allowed range 1..5");
    VisemeSet one = set;
    one.visemes.resize(1);
    EXPECT_INPUT_ERROR(reduceProject(project, one),
                       "/visemes: a reduction needs at least 2 visemes, found 1");
}

TEST_F(ProjectRun, ConstraintsOfTheProjectAreHonoured) {
    const VisemeSet set = loadProjectVisemeSet(project);
    Project p = project;
    p.reduction.target = 3;
    p.reduction.constraints.pinned = {p.visemes[0].name};
    p.reduction.constraints.together = {{p.visemes[1].name, p.visemes[4].name}};
    const ReduceOutcome outcome = reduceProject(p, set);
    const auto groupOf = outcome.result.groupOf();
    EXPECT_EQ(outcome.result.best().groups[static_cast<std::size_t>(groupOf[0])], std::vector<int>{0});
    EXPECT_EQ(groupOf[1], groupOf[4]);
    EXPECT_TRUE(outcome.result.best().optimal);
    p.reduction.target = 5;
    EXPECT_INPUT_ERROR(reduceProject(p, set),
                       "/reduction/constraints: no grouping into 5 groups satisfies the "
                       "constraints: the 'together' constraints leave 4 separable units");
    p.reduction.target = 3;
    p.reduction.constraints.together.emplace_back(p.visemes[0].name, p.visemes[2].name);
    EXPECT_INPUT_ERROR(reduceProject(p, set),
                       "/reduction/constraints: '" + p.visemes[0].name + "' is pinned");
}

// The bundled sample project: loads, its meshes are interpolable and its reduction runs.
TEST(SampleProject, LoadsAndReduces) {
    const std::filesystem::path file =
        std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no sample project at " << file;
    if (!std::filesystem::exists(file.parent_path() / "neutral.obj"))
        GTEST_SKIP() << "sample meshes not generated yet in " << file.parent_path();
    const Project project = loadProject(file);
    EXPECT_GE(project.visemes.size(), 15u);
    const VisemeSet set = loadProjectVisemeSet(project);
    const ReduceOutcome outcome = reduceProject(project, set);
    EXPECT_EQ(outcome.result.curve.size(), static_cast<std::size_t>(project.reduction.target));
    EXPECT_EQ(outcome.model.keys.size(), static_cast<std::size_t>(project.reduction.target));
    // The stored result is the one the reduction gives today (else: scripts/make-sample-project.sh).
    ASSERT_TRUE(project.reduction.result);
    ASSERT_EQ(project.reduction.result->curve.size(), outcome.result.curve.size());
    for (std::size_t p = 0; p < outcome.result.curve.size(); ++p) {
        EXPECT_EQ(project.reduction.result->curve[p].groups, outcome.result.curve[p].groups);
        EXPECT_NEAR(project.reduction.result->curve[p].cost, outcome.result.curve[p].cost,
                    1e-12 * (1 + outcome.result.curve[p].cost));
    }
}

} // namespace
} // namespace vl

namespace vl {
namespace {

// An avatar project reduces as `avatar reduce` does (the lips-closed viseme keeps a key); a project
// of mesh files leaves it to the optimiser, as `visemelab reduce` does.
TEST(ProjectSettings, AvatarProjectsKeepTheLipClosureRule) {
    Project meshes;
    EXPECT_TRUE(projectReduceSettings(meshes).closure.empty());
    Project avatar;
    avatar.avatar.file = "avatar.glb";
    EXPECT_EQ(projectReduceSettings(avatar).closure, kClosureAuto);
}

} // namespace
} // namespace vl
