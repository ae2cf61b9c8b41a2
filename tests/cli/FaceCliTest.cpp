// `visemelab face build` end to end on a face nobody here made (the MediaPipe canonical face from
// VISEMELAB_SHARED_DATA_DIR, skipped loudly when absent): the landmarks it says it found, the landmark
// file it writes read back as given ones, then visemes --project and refine --project on the
// project it wrote; refine --save stores the refined mesh in the project, which reopens with it and
// exports it (OBJ, glb, runtime); a mesh without (u,v) is a data error naming the file.
#include "core/common/AtomicFile.h"
#include "core/document/Document.h"
#include "core/import/GltfImport.h"
#include "core/io/MeshIO.h"
#include "core/project/Project.h"
#include "core/runtime/Package.h"
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
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

// Issue 15, point 3: the refined face mesh is saved in the project (it was lost before), and the own
// face's visemes on it go out through every export path with that mesh.
TEST(OwnFaceCli, RefineSaveStoresTheRefinedMeshAndTheVisemesExportOnIt) {
    if (!fs::exists(kMediaPipe))
        GTEST_SKIP() << "shared data missing: " << kMediaPipe << " (set VISEMELAB_SHARED_DATA_DIR)";
    const fs::path dir = fs::temp_directory_path() / "visemelab_face_cli_refine_save";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "mp.vlproj";
    auto r = test::runCli("face build " + kMediaPipe.string() + " --out " + file.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Project built = loadProject(file);
    // face build stores the (u,v) mesh its visemes were generated on.
    ASSERT_FALSE(built.deformation.domain.positions.empty());
    EXPECT_EQ(built.deformation.domain.uvs, built.neutral.embedded.uvs);

    r = test::runCli("refine --project " + file.string() + " --save --criterion contour --max-depth 5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("stored the refined mesh in"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("viseme meshes regenerated on it"), std::string::npos) << r.output;

    const Project refined = loadProject(file);
    EXPECT_EQ(projectVersionFor(refined), 2);
    const MeshData& domain = refined.deformation.domain;
    ASSERT_FALSE(domain.positions.empty());
    EXPECT_NE(domain.uvs, built.deformation.domain.uvs);
    // The visemes were regenerated on the refined mesh; names and parameters kept.
    EXPECT_EQ(refined.neutral.embedded.uvs, domain.uvs);
    EXPECT_EQ(refined.neutral.embedded.triangles, domain.triangles);
    ASSERT_EQ(refined.visemes.size(), built.visemes.size());
    EXPECT_EQ(refined.visemes[10].name, built.visemes[10].name);
    EXPECT_EQ(refined.visemes[10].positions.size(), domain.positions.size());
    EXPECT_EQ(refined.deformation.visemes, built.deformation.visemes);
    // Reopened (as the editor opens it), the face shows the refined mesh.
    const Document reopened = documentFromProject(refined).document;
    ASSERT_NE(reopened.face.domain, nullptr);
    EXPECT_EQ(reopened.face.domain->uvs, domain.uvs);
    EXPECT_EQ(reopened.face.domain->triangles, domain.triangles);

    // Export: every path carries the refined mesh.
    const std::size_t vertices = domain.positions.size();
    r = test::runCli("export " + file.string() + " --format obj --out " + (dir / "obj").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const MeshData objNeutral = readMesh(dir / "obj" / "neutral.obj");
    EXPECT_EQ(objNeutral.positions.size(), vertices);
    EXPECT_EQ(objNeutral.triangles.size(), domain.triangles.size());
    r = test::runCli("export " + file.string() + " --format glb --out " + (dir / "face.glb").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ReducedModel glb = readGltf(dir / "face.glb");
    EXPECT_EQ(glb.neutral.positions.size(), vertices);
    EXPECT_EQ(glb.keys.size(), static_cast<std::size_t>(refined.reduction.target));
    r = test::runCli("export " + file.string() + " --format runtime --out " + (dir / "face.vlrt").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    runtime::Package package;
    std::string error;
    ASSERT_TRUE(package.loadFile((dir / "face.vlrt").c_str(), error)) << error;
    EXPECT_EQ(package.vertexCount(), vertices);
    EXPECT_EQ(package.triangleCount(), domain.triangles.size());
    fs::remove_all(dir);
}

// The sample project's visemes are whole-head meshes read from files (skin, teeth, tongue, eyes): refine
// --save stores the refined face mesh but leaves those meshes alone (regenerating them on the skin's
// mesh would drop the parts).
TEST(OwnFaceCli, RefineSaveKeepsVisemeMeshesTheFaceDidNotGenerateOnItsMesh) {
    const fs::path dir = fs::temp_directory_path() / "visemelab_face_cli_refine_sample";
    fs::remove_all(dir);
    fs::copy(fs::path(VISEMELAB_ASSETS_DIR) / "sample", dir, fs::copy_options::recursive);
    const Project before = loadProject(dir / "sample.vlproj");
    ASSERT_TRUE(before.deformation.isSet());
    ASSERT_TRUE(before.deformation.domain.positions.empty());
    const auto r = test::runCli("refine --project " + (dir / "sample.vlproj").string() +
                                " --save --criterion depth --depth 2 --max-depth 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("its viseme meshes kept"), std::string::npos) << r.output;
    const Project after = loadProject(dir / "sample.vlproj");
    EXPECT_FALSE(after.deformation.domain.positions.empty());
    EXPECT_EQ(after.neutral.file, before.neutral.file);
    EXPECT_EQ(after.visemes, before.visemes);
    EXPECT_EQ(after.reduction.result, before.reduction.result);
    EXPECT_EQ(after.frequencies.map.entries, before.frequencies.map.entries);
    fs::remove_all(dir);
}

TEST(OwnFaceCli, RefineSaveNeedsAProjectAndRefineNeedsAnOutput) {
    auto r = test::runCli("refine --save --face bundled");
    EXPECT_EQ(r.exitCode, 2) << r.output; // a usage error, like every missing flag
    EXPECT_NE(r.output.find("--save stores the refined mesh in a project: give --project"), std::string::npos)
        << r.output;
    r = test::runCli("refine --face bundled");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--out is required"), std::string::npos) << r.output;
}

// A synthetic face nobody here modelled: a dome with a nose, two eye openings and, optionally, a mouth
// opening (a slit), as an OBJ with (u,v), scaled by `scale` and turned by 90 degrees about x (z up,
// as many tools write heads) when `zUp`.
void writeSyntheticFace(const fs::path& file, bool mouth, double scale, bool zUp) {
    const int n = 120;
    const auto z = [](double x, double y) {
        const double dome = 1.0 - (x / 9.0) * (x / 9.0) - (y / 11.0) * (y / 11.0);
        return 6.0 * std::sqrt(std::max(0.05, dome)) + 2.5 * std::exp(-(x * x + (y - 0.5) * (y - 0.5)) / 1.4);
    };
    const auto hole = [&](double x, double y) {
        for (const double side : {-1.0, 1.0}) {
            const double ex = (x - side * 3.2) / 1.3, ey = (y - 2.6) / 0.55;
            if (ex * ex + ey * ey < 1.0) return true;
        }
        const double mx = x / 2.6, my = (y + 3.4) / 0.35;
        return mouth && mx * mx + my * my < 1.0;
    };
    std::ofstream out(file);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double u = double(i) / n, v = double(j) / n;
            const double x = 16.0 * (u - 0.5), y = 20.0 * (v - 0.5), depth = z(x, y);
            if (zUp)
                out << "v " << scale * x << " " << -scale * depth << " " << scale * y << "\n";
            else
                out << "v " << scale * x << " " << scale * y << " " << scale * depth << "\n";
            out << "vt " << u << " " << v << "\n";
        }
    const auto at = [&](int i, int j) { return j * (n + 1) + i + 1; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = 16.0 * ((i + 0.5) / n - 0.5), y = 20.0 * ((j + 0.5) / n - 0.5);
            if (hole(x, y)) continue;
            for (const auto& [a, b, c] : {std::array{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                                          std::array{at(i, j), at(i + 1, j + 1), at(i, j + 1)}})
                out << "f " << a << "/" << a << " " << b << "/" << b << " " << c << "/" << c << "\n";
        }
}

// Issue 15: a face nobody here made builds through the CLI whatever its units and orientation, and the
// mouth found is where the mesh has it; without a mouth the build stops and says the mouth is only
// estimated, unless told to accept estimates.
TEST(OwnFaceCli, ASyntheticFaceBuildsInAnyUnitsAndAnEstimatedMouthIsRefused) {
    const fs::path dir = fs::temp_directory_path() / "visemelab_face_cli_synthetic";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& [scale, zUp] : {std::pair{1.0, false}, {0.01, true}, {10.0, true}}) {
        const fs::path mesh = dir / ("face_" + std::to_string(scale) + ".obj");
        writeSyntheticFace(mesh, true, scale, zUp);
        const auto r = test::runCli("face build " + mesh.string() + " --out " + (dir / "f.vlproj").string() +
                                    " --landmarks-out " + (dir / "l.json").string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("mouth_corner_right  geometry"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("eye_outer_left      geometry"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("mouth opening"), std::string::npos) << r.output;
        // The landmarks are where the mesh has them: the mouth corners at the ends of the slit (u = 0.5 -/+
        // 2.6/16, v = 0.5 - 3.4/20), the outer eye corners at the ends of the openings (u = 0.5 -/+ 4.5/16).
        const auto landmarks = nlohmann::json::parse(readFileToString(dir / "l.json"))["landmarks"];
        const double atScale = scale; // clang 14 (the sanitizer build) cannot capture a structured binding
        const auto expectUv = [&](const char* name, double u, double v) {
            EXPECT_NEAR(landmarks[name]["uv"][0].get<double>(), u, 0.02) << name << " at scale " << atScale;
            EXPECT_NEAR(landmarks[name]["uv"][1].get<double>(), v, 0.02) << name << " at scale " << atScale;
        };
        expectUv("mouth_corner_right", 0.5 - 2.6 / 16, 0.5 - 3.4 / 20);
        expectUv("mouth_corner_left", 0.5 + 2.6 / 16, 0.5 - 3.4 / 20);
        expectUv("eye_outer_right", 0.5 - 4.5 / 16, 0.5 + 2.6 / 20);
        expectUv("eye_outer_left", 0.5 + 4.5 / 16, 0.5 + 2.6 / 20);
        expectUv("nose_tip", 0.5, 0.5 + 0.5 / 20);
        const Project project = loadProject(dir / "f.vlproj");
        EXPECT_EQ(project.visemes.size(), 15u);
    }
    const fs::path closed = dir / "closed.obj";
    writeSyntheticFace(closed, false, 1.0, false);
    auto r = test::runCli("face build " + closed.string() + " --out " + (dir / "c.vlproj").string() +
                          " --landmarks-out " + (dir / "c.json").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("found no mouth"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--accept-estimates"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "c.vlproj"));
    EXPECT_TRUE(fs::exists(dir / "c.json")); // the guesses, to edit and give back
    r = test::runCli("face build " + closed.string() + " --accept-estimates --out " +
                     (dir / "c.vlproj").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("mouth_corner_right  estimate"), std::string::npos) << r.output;
    // Keep the files for a look when the test fails.
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
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
