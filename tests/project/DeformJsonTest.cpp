// The deformation section: the bundled face round-trips exactly (its geometry image by reference),
// and every field of the cascade is validated with its JSON path; the face's (u,v) mesh (version 2)
// round-trips, is validated, and a file without one stays version 1.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/io/JsonRead.h"
#include "core/project/BuiltinGeometry.h"
#include "core/project/FaceProject.h"

namespace vl {
namespace {

using test::ScratchDir;

Project faceProject(const std::filesystem::path& file, const DeformationCascade& cascade) {
    Project p;
    p.path = file;
    p.deformation.cascade = cascade;
    p.deformation.values = cascade.defaults();
    p.deformation.values[static_cast<std::size_t>(cascade.findParameter("jaw_open"))] = 0.5;
    p.deformation.visemes = oculusVisemes();
    return p;
}

TEST(DeformJson, BundledFaceRoundTripsExactlyWithItsGeometryByReference) {
    ScratchDir dir("face");
    for (const auto& cascade : {face::makeBundledFace(), face::makeRetargetFace()}) {
        const Project p = faceProject(dir / "face.vlproj", cascade);
        saveProject(p.path, p);
        const std::string text = readFileToString(p.path);
        EXPECT_LT(text.size(), 200'000u) << "the 257 x 257 geometry image should be written as a reference";
        EXPECT_NE(
            text.find("\"builtin\": \"" + std::string(cascade.name.substr(0, cascade.name.find(' '))) + "\""),
            std::string::npos);
        const Project loaded = loadProject(p.path);
        EXPECT_TRUE(loaded == p);
        EXPECT_EQ(loaded.deformation.cascade.evaluate(0.5, 0.3, loaded.deformation.values),
                  cascade.evaluate(0.5, 0.3, p.deformation.values));
        saveProject(p.path, loaded);
        EXPECT_EQ(readFileToString(p.path), text);
    }
}

TEST(DeformJson, AnEditedGeometryImageIsWrittenInFull) {
    ScratchDir dir("edited");
    DeformationCascade cascade = face::makeBundledFace();
    auto& grid = cascade.stages[0].field.sampled;
    grid = sampleGrid(9, 9, [&](double u, double v) { return grid.at(u, v); });
    grid.samples[40][2] += 1e-12; // any change, however small, means it is not the built-in image
    const Project p = faceProject(dir / "face.vlproj", cascade);
    saveProject(p.path, p);
    EXPECT_EQ(readFileToString(p.path).find("\"builtin\""), std::string::npos);
    EXPECT_TRUE(loadProject(p.path) == p);
}

class DeformValidation : public test::DocumentTest {
  protected:
    DeformValidation() : DocumentTest("deformvalid", kDocument) {}
    static constexpr std::string_view kDocument = R"({
          "format": "visemelab-project", "version": 1, "neutral": null, "visemes": [],
          "deformation": {
            "cascade": {
              "name": "test",
              "parameters": [{"name": "jaw", "min": 0, "max": 1, "default": 0},
                             {"name": "brow", "min": -0.5, "max": 1, "default": 0}],
              "stages": [
                {"kind": "constant", "name": "base", "field": {"sampled": {"width": 2, "height": 1, "samples": [[0, 0, 0], [1, 0, 0]]}, "influences": []}},
                {"kind": "addVector", "name": "jaw_field", "parameter": "jaw", "field": {"sampled": null, "influences": [
                  {"centre": [0.5, 0.3], "radii": [0.2, 0.1], "plateau": [0, 0], "rotation": 0, "direction": [0, -1, 0], "magnitude": 2, "falloff": "cosine"}]}}
              ]
            },
            "values": {"jaw": 0.25},
            "visemes": [{"name": "aa", "values": {"jaw": 1}}, {"name": "sil", "values": {}}]
          },
          "reduction": {"target": 1, "result": null}
        })";

    Json& stage(std::size_t k) { return doc["deformation"]["cascade"]["stages"][k]; }
    Json& influence() { return stage(1)["field"]["influences"][0]; }
};

TEST_F(DeformValidation, TheBaseDocumentLoads) {
    const Project p = load();
    ASSERT_TRUE(p.deformation.isSet());
    EXPECT_EQ(p.deformation.values, (std::vector<double>{0.25, 0.0})); // brow keeps its default
    EXPECT_EQ(p.deformation.cascade.stages[1].parameter, 0u);
    EXPECT_EQ(p.deformation.cascade.stages[1].field.influences[0].falloff, Falloff::Cosine);
    EXPECT_EQ(p.deformation.visemes[0].values, (std::vector<std::pair<std::string, double>>{{"jaw", 1.0}}));
    EXPECT_EQ(p.deformation.cascade.evaluate(0.5, 0.3, p.deformation.values), Vec3(0.5, -0.5, 0));
}

TEST_F(DeformValidation, Parameters) {
    doc["deformation"]["cascade"]["parameters"][1]["default"] = 2;
    EXPECT_LOAD_ERROR("/deformation/cascade/parameters/1/default: default 2 is outside [-0.5, 1]");
    doc["deformation"]["cascade"]["parameters"][1]["default"] = 0;
    doc["deformation"]["cascade"]["parameters"][1]["max"] = -1;
    EXPECT_LOAD_ERROR("/deformation/cascade/parameters/1/max: max -1 is below min -0.5");
    doc["deformation"]["cascade"]["parameters"][1]["max"] = 1;
    doc["deformation"]["cascade"]["parameters"][1]["name"] = "jaw";
    EXPECT_LOAD_ERROR("/deformation/cascade/parameters/1/name: duplicate parameter name \"jaw\"");
}

TEST_F(DeformValidation, ValuesAndVisemeVectors) {
    doc["deformation"]["values"]["jaw"] = 1.5;
    EXPECT_LOAD_ERROR("/deformation/values/jaw: 1.5 is outside [0, 1]");
    doc["deformation"]["values"] = Json{{"chin", 0}};
    EXPECT_LOAD_ERROR("/deformation/values/chin: unknown parameter \"chin\"");
    doc["deformation"]["values"] = Json::object();
    doc["deformation"]["visemes"][0]["values"]["brow"] = -1;
    EXPECT_LOAD_ERROR("/deformation/visemes/0/values/brow: -1 is outside [-0.5, 1]");
    doc["deformation"]["visemes"][0]["values"].erase("brow");
    doc["deformation"]["visemes"][1]["name"] = "aa";
    EXPECT_LOAD_ERROR("/deformation/visemes/1/name: duplicate viseme name \"aa\"");
}

TEST_F(DeformValidation, Stages) {
    stage(1)["parameter"] = "chin";
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/parameter: unknown parameter \"chin\"");
    stage(1).erase("parameter");
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/parameter: missing field");
    stage(1)["parameter"] = "jaw";
    stage(1)["kind"] = "multiply";
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/kind: unknown stage kind \"multiply\"");
    stage(1)["kind"] = "addVector";
    stage(0)["kind"] = "addVector";
    stage(0)["parameter"] = "jaw";
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/0/kind: the first stage must be a constant stage");
    stage(0)["kind"] = "constant";
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/0/parameter: a constant stage has no parameter");
    doc["deformation"]["cascade"]["stages"] = Json::array();
    EXPECT_LOAD_ERROR("/deformation/cascade/stages: expected at least one stage");
}

TEST_F(DeformValidation, SampledGrids) {
    stage(0)["field"]["sampled"]["width"] = 3;
    EXPECT_LOAD_ERROR(
        "/deformation/cascade/stages/0/field/sampled/samples: expected 3 samples (width x height), found 2");
    stage(0)["field"]["sampled"]["width"] = 0;
    EXPECT_LOAD_ERROR(
        "/deformation/cascade/stages/0/field/sampled/width: 0 is outside the allowed range 1..4097");
    stage(0)["field"]["sampled"] = Json{{"builtin", "alien"}, {"width", 9}, {"height", 9}};
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/0/field/sampled/builtin: ");
    stage(0)["field"]["sampled"] = Json{{"builtin", "bundled"}, {"width", 9}, {"height", 8}};
    EXPECT_LOAD_ERROR(
        "/deformation/cascade/stages/0/field/sampled/height: a built-in geometry is a square grid");
    stage(0)["field"]["sampled"] = Json{{"builtin", "retarget"}, {"width", 9}, {"height", 9}};
    EXPECT_EQ(load().deformation.cascade.stages[0].field.sampled.samples,
              face::makeFaceGeometry(face::Individual::Retarget, 9).samples);
}

TEST(DeformJson, TheRetargetingChoiceIsReadBackFromTheSavedBaseGeometry) {
    ScratchDir dir("individual");
    for (const auto who : {face::Individual::Bundled, face::Individual::Retarget}) {
        const Project p = faceProject(dir / "face.vlproj", face::makeFaceCascade(who));
        saveProject(p.path, p);
        EXPECT_EQ(builtinIndividualOf(loadProject(p.path).deformation.cascade), who);
    }
    // Any other base geometry is no built-in individual.
    DeformationCascade custom = face::makeBundledFace();
    custom.stages[0].field.sampled.samples[0][2] += 1.0;
    EXPECT_EQ(builtinIndividualOf(custom), std::nullopt);
    EXPECT_EQ(builtinIndividualOf(DeformationCascade{}), std::nullopt);
}

TEST_F(DeformValidation, InfluenceRegions) {
    influence()["radii"] = Json::array({0.2, 0});
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/field/influences/0/radii: radii must be positive");
    influence()["radii"] = Json::array({0.2, 0.1});
    influence()["plateau"] = Json::array({0.3, 0.05});
    EXPECT_LOAD_ERROR(
        "/deformation/cascade/stages/1/field/influences/0/plateau: plateau radii must both be 0");
    influence()["plateau"] = Json::array({0, 0});
    influence()["direction"] = Json::array({0, 0, 0});
    EXPECT_LOAD_ERROR(
        "/deformation/cascade/stages/1/field/influences/0/direction: direction must not be the zero vector");
    influence()["direction"] = Json::array({0, 0});
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/field/influences/0/direction: expected an array of 3 "
                      "elements, found 2");
    influence()["direction"] = Json::array({0, 0, 1});
    influence()["falloff"] = "sharp";
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/field/influences/0/falloff: unknown falloff 'sharp'");
    influence()["falloff"] = "linear";
    influence().erase("magnitude");
    EXPECT_LOAD_ERROR("/deformation/cascade/stages/1/field/influences/0/magnitude: missing field");
}

TEST(DeformJson, InconsistentStateIsRefusedOnSave) {
    ScratchDir dir("deformsave");
    Project p = faceProject(dir / "p.vlproj", face::makeBundledFace());
    const std::string count = std::to_string(p.deformation.values.size());
    p.deformation.values.pop_back();
    EXPECT_INPUT_ERROR(saveProject(p.path, p), "/deformation/values: expected one value per parameter (" +
                                                   count + "), found " +
                                                   std::to_string(p.deformation.values.size()));
    p = faceProject(dir / "p.vlproj", face::makeBundledFace());
    p.deformation.values[0] = 7;
    EXPECT_INPUT_ERROR(saveProject(p.path, p), "/deformation/values/frontalis_l: 7 is outside [-0.5, 1]");
    EXPECT_FALSE(std::filesystem::exists(p.path));
}

} // namespace
} // namespace vl

namespace vl {
namespace {

// A refined-looking (u,v) mesh: the face domain with one triangle split at an edge midpoint.
MeshData splitDomain() {
    MeshData mesh = face::faceDomainMesh(10, face::DomainDensity::MouthFocused);
    const Triangle t = mesh.triangles.front();
    const Vec2 mid = 0.5 * (mesh.uvs[t[0]] + mesh.uvs[t[1]]);
    mesh.uvs.push_back(mid);
    mesh.positions.emplace_back(mid[0], mid[1], 0.0);
    const auto m = static_cast<std::uint32_t>(mesh.uvs.size() - 1);
    mesh.triangles.front() = {t[0], m, t[2]};
    mesh.triangles.push_back({m, t[1], t[2]});
    return mesh;
}

TEST(DeformJson, TheFaceMeshRoundTripsAsVersion2AndAFileWithoutOneStaysVersion1) {
    ScratchDir dir("domain");
    Project p = faceProject(dir / "face.vlproj", face::makeBundledFace());
    saveProject(p.path, p);
    EXPECT_NE(readFileToString(p.path).find("\"version\": 1,"), std::string::npos);
    EXPECT_EQ(readFileToString(p.path).find("\"domain\""), std::string::npos);

    p.deformation.domain = projectDomainMesh(splitDomain());
    saveProject(p.path, p);
    const std::string text = readFileToString(p.path);
    EXPECT_NE(text.find("\"version\": 2,"), std::string::npos);
    EXPECT_NE(text.find("\"domain\""), std::string::npos);
    const Project loaded = loadProject(p.path);
    EXPECT_TRUE(loaded == p);
    EXPECT_EQ(loaded.deformation.domain.uvs.size(), splitDomain().uvs.size());
    EXPECT_EQ(loaded.deformation.domain.triangles, splitDomain().triangles);
    saveProject(p.path, loaded);
    EXPECT_EQ(readFileToString(p.path), text);
}

TEST(DeformJson, ProjectDomainMeshKeepsUvAndTrianglesAndFlattensPositions) {
    MeshData mesh = splitDomain();
    for (auto& position : mesh.positions) position = Vec3(3.0, -2.0, 7.0); // a posed face
    const MeshData stored = projectDomainMesh(mesh);
    EXPECT_EQ(stored.uvs, mesh.uvs);
    EXPECT_EQ(stored.triangles, mesh.triangles);
    ASSERT_EQ(stored.positions.size(), mesh.uvs.size());
    EXPECT_EQ(stored.positions[5], Vec3(mesh.uvs[5][0], mesh.uvs[5][1], 0.0));
}

TEST_F(DeformValidation, TheFaceMeshNeedsVersion2AndIsChecked) {
    doc["deformation"]["domain"] =
        Json{{"uvs", Json::array({Json::array({0, 0}), Json::array({1, 0}), Json::array({0, 1})})},
             {"triangles", Json::array({Json::array({0, 1, 2})})}};
    EXPECT_LOAD_ERROR("/deformation/domain: a face (u,v) mesh needs project version 2 (this file says 1)");
    doc["version"] = 2;
    const Project p = load();
    EXPECT_EQ(p.deformation.domain.uvs.size(), 3u);
    EXPECT_EQ(p.deformation.domain.positions[1], Vec3(1, 0, 0));
    doc["deformation"]["domain"]["uvs"][2] = Json::array({0, 1.5});
    EXPECT_LOAD_ERROR("/deformation/domain/uvs/2: (u,v) outside the unit square: (0, 1.5)");
    doc["deformation"]["domain"]["uvs"][2] = Json::array({0, 1});
    doc["deformation"]["domain"]["triangles"][0] = Json::array({0, 1, 3});
    EXPECT_LOAD_ERROR("/deformation/domain/triangles/0/2: 3 is outside the allowed range 0..2");
    doc["deformation"]["domain"]["triangles"][0] = Json::array({0, 1, 1});
    EXPECT_LOAD_ERROR("/deformation/domain/triangles/0: a triangle repeats a vertex index");
    doc["deformation"]["domain"]["triangles"] = Json::array();
    EXPECT_LOAD_ERROR("/deformation/domain/triangles: expected at least one triangle");
    doc["deformation"]["domain"].erase("triangles");
    EXPECT_LOAD_ERROR("/deformation/domain/triangles: missing field");
    doc["deformation"]["domain"]["positions"] = Json::array();
    EXPECT_LOAD_ERROR("/deformation/domain/positions: unknown field");
}

TEST(DeformJson, AFaceMeshOutsideTheUnitSquareIsRefusedOnSave) {
    ScratchDir dir("domainsave");
    Project p = faceProject(dir / "p.vlproj", face::makeBundledFace());
    p.deformation.domain = projectDomainMesh(splitDomain());
    p.deformation.domain.uvs[3] = Vec2(-0.25, 0.5);
    EXPECT_INPUT_ERROR(saveProject(p.path, p),
                       "/deformation/domain/uvs/3: (u,v) outside the unit square: (-0.25, 0.5)");
    EXPECT_FALSE(std::filesystem::exists(p.path));
}

} // namespace
} // namespace vl
