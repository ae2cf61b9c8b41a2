#include "core/adaptive/CascadeSurface.h"
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"
#include "core/project/Project.h"
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace vl {
namespace {

namespace fs = std::filesystem;

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
}

TEST(CliRefine, WritesTheMeshAndAReport) {
    const auto dir = fs::temp_directory_path() / "visemelab_cli_refine";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto r = test::runCli("refine --criterion depth --depth 2 --out " + (dir / "d.ply").string() +
                                " --report " + (dir / "d.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const MeshData mesh = readMesh(dir / "d.ply");
    const auto report = readJson(dir / "d.json");
    EXPECT_EQ(report["triangles"], mesh.triangles.size());
    EXPECT_EQ(report["vertices"], mesh.positions.size());
    EXPECT_EQ(report["triangles"], 4 * report["base_triangles"].get<int>());
    EXPECT_EQ(report["max_level"], 2);
    EXPECT_EQ(report["settings"]["criterion"], "depth");
    EXPECT_GT(report["contour_error"]["maximum"].get<double>(),
              report["contour_error"]["average"].get<double>());
    EXPECT_GE(report["timing_ms"].get<double>(), 0.0);
    EXPECT_TRUE(mesh.hasUVs());

    const auto c = test::runCli("refine --face retarget --criterion contour --avg-error 0.05 --max-error 0.2 "
                                "--param jaw_open=0.8 --out " +
                                (dir / "c.obj").string() + " --report " + (dir / "c.json").string());
    ASSERT_EQ(c.exitCode, 0) << c.output;
    const auto contour = readJson(dir / "c.json");
    EXPECT_EQ(contour["parameters"]["jaw_open"], 0.8);
    EXPECT_EQ(contour["face"], "retarget");
    EXPECT_EQ(readMesh(dir / "c.obj").triangles.size(), contour["triangles"]);
    fs::remove_all(dir);
}

TEST(CliRefine, UsesTheFaceOfAProject) {
    const auto dir = fs::temp_directory_path() / "visemelab_cli_refine_project";
    fs::remove_all(dir);
    fs::create_directories(dir);
    Project project;
    project.path = dir / "face.vlproj";
    project.deformation.cascade = face::makeRetargetFace();
    project.deformation.values = project.deformation.cascade.defaults();
    project.deformation
        .values[static_cast<std::size_t>(project.deformation.cascade.findParameter("jaw_open"))] = 0.5;
    saveProject(project.path, project);
    const auto r = test::runCli("refine --project " + project.path.string() + " --criterion contour --out " +
                                (dir / "p.obj").string() + " --report " + (dir / "p.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = readJson(dir / "p.json");
    EXPECT_EQ(report["parameters"]["jaw_open"], 0.5);
    EXPECT_EQ(report["face"], project.path.string());

    Project empty; // no deformable face
    empty.path = dir / "empty.vlproj";
    saveProject(empty.path, empty);
    const auto e =
        test::runCli("refine --project " + empty.path.string() + " --out " + (dir / "e.obj").string());
    EXPECT_EQ(e.exitCode, 3);
    EXPECT_NE(e.output.find("no deformable face"), std::string::npos) << e.output;
    fs::remove_all(dir);
}

TEST(CliVisemesAdaptive, WritesTheSetOnOneAdaptiveMesh) {
    const auto dir = fs::temp_directory_path() / "visemelab_cli_visemes_adaptive";
    fs::remove_all(dir);
    const auto r = test::runCli(
        "visemes --skin-only --criterion contour --avg-error 0.08 --max-error 0.32 --decimals -1 --out " +
        dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const VisemeSet set = loadVisemeSet(dir / "neutral.obj", listVisemeFolder(dir, dir / "neutral.obj"));
    EXPECT_EQ(set.size(), 15u);
    // The same mesh as refining for neutral + every viseme directly.
    const DeformationCascade cascade = face::makeBundledFace();
    std::vector<std::vector<double>> poses{cascade.defaults()};
    for (const auto& v : oculusVisemes()) poses.push_back(parameterVector(cascade, v));
    CriterionSettings s;
    s.kind = CriterionKind::Contour;
    s.contour.averageError = 0.08;
    s.contour.maximumError = 0.32;
    const MeshData expected = refineFaceMesh(cascade, 10, s, poses);
    EXPECT_EQ(set.neutral.triangles, expected.triangles);
    EXPECT_EQ(set.neutral.uvs, expected.uvs);
    EXPECT_EQ(readJson(dir / "visemes.json")["criterion"], "contour");
    fs::remove_all(dir);
}

TEST(CliRefine, RejectsBadOptionsWithTheFlagName) {
    const std::string out = " --out " + (fs::temp_directory_path() / "visemelab_refine_bad.obj").string();
    auto r = test::runCli("refine --criterion curvature" + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.output.find("--criterion"), std::string::npos) << r.output;
    r = test::runCli("refine --param jaw_open=7" + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.output.find("jaw_open"), std::string::npos) << r.output;
    r = test::runCli("refine --param nose=1" + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(test::runCli("refine --max-depth 99" + out).exitCode, 3);
    EXPECT_EQ(test::runCli("refine --out x.xyz").exitCode, 3);
    EXPECT_EQ(test::runCli("refine --depth abc" + out).exitCode, 2);
    EXPECT_EQ(test::runCli("refine").exitCode, 2);
}

} // namespace
} // namespace vl
