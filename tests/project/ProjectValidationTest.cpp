// Every validation error of the project loader, with the JSON path of the problem.
#include "ProjectTestUtil.h"

#include "core/io/JsonRead.h"

namespace vl {
namespace {

using test::ScratchDir;

class ProjectValidation : public test::DocumentTest {
  protected:
    ProjectValidation() : DocumentTest("validation", kDocument) {
        for (const char* name : {"neutral.obj", "sil.obj", "aa.obj", "E.obj", "oh.obj"})
            test::writeText(dir / name, "");
    }
    static constexpr std::string_view kDocument = R"({
          "format": "visemelab-project",
          "version": 1,
          "neutral": {"file": "neutral.obj"},
          "visemes": [{"name": "sil", "file": "sil.obj"}, {"name": "aa", "file": "aa.obj"},
                      {"name": "E", "file": "E.obj"}, {"name": "oh", "file": "oh.obj"}],
          "frequencies": {"phonemes": {"AA": 0.5, "EH": 0.3, "OW": 0.2}, "map": {"AA": "aa", "EH": "E", "OW": "oh"}},
          "weights": {"mode": "area"},
          "reduction": {"target": 2, "result": {"curve": [
              {"cost": 3.5, "groups": [["sil", "aa", "E", "oh"]]},
              {"cost": 1.25, "groups": [["sil"], ["aa", "E", "oh"]]}]}},
          "editor": {"selectedViseme": "aa"}
        })";
};

TEST_F(ProjectValidation, TheBaseDocumentLoads) {
    const Project p = load();
    ASSERT_EQ(p.visemes.size(), 4u);
    EXPECT_EQ(p.visemes[2].name, "E");
    EXPECT_EQ(p.visemes[2].file, "E.obj");
    EXPECT_EQ(p.neutral.file, "neutral.obj");
    EXPECT_TRUE(p.frequencies.isPhonemeBased());
    EXPECT_EQ(*p.frequencies.map.visemeOf("EH"), "E");
    EXPECT_EQ(p.weights.mode, WeightMode::Area);
    EXPECT_EQ(p.reduction.target, 2);
    ASSERT_TRUE(p.reduction.result);
    EXPECT_EQ(p.reduction.result->curve[1].groups, (std::vector<std::vector<int>>{{0}, {1, 2, 3}}));
    EXPECT_EQ(p.editor.selectedViseme, "aa");
}

TEST_F(ProjectValidation, MessagesStartWithTheProjectFile) {
    doc["visemes"][3]["file"] = "missing.obj";
    EXPECT_EQ(errorOf().rfind((dir / "p.vlproj").string() + ": /visemes/3/file: file not found", 0), 0u)
        << errorOf();
}

TEST_F(ProjectValidation, MissingFields) {
    doc.erase("visemes");
    EXPECT_LOAD_ERROR("/visemes: missing field");
}
TEST_F(ProjectValidation, MissingVisemeName) {
    doc["visemes"][1].erase("name");
    EXPECT_LOAD_ERROR("/visemes/1/name: missing field");
}
TEST_F(ProjectValidation, MissingVisemeFile) {
    doc["visemes"][2].erase("file");
    EXPECT_LOAD_ERROR("/visemes/2/file: missing field");
}
TEST_F(ProjectValidation, MissingFormatAndVersion) {
    doc.erase("version");
    EXPECT_LOAD_ERROR("/version: missing field");
    doc.erase("format");
    EXPECT_LOAD_ERROR("/format: missing field");
}
TEST_F(ProjectValidation, MissingTarget) {
    doc["reduction"].erase("target");
    EXPECT_LOAD_ERROR("/reduction/target: missing field");
}

TEST_F(ProjectValidation, WrongTypes) {
    doc["visemes"] = Json::object();
    EXPECT_LOAD_ERROR("/visemes: expected an array, found object");
}
TEST_F(ProjectValidation, WrongTypeOfWeightMode) {
    doc["weights"]["mode"] = 3;
    EXPECT_LOAD_ERROR("/weights/mode: expected a string, found 3");
}
TEST_F(ProjectValidation, WrongTypeOfTarget) {
    doc["reduction"]["target"] = "2";
    EXPECT_LOAD_ERROR("/reduction/target: expected an integer, found string \"2\"");
    doc["reduction"]["target"] = 2.5;
    EXPECT_LOAD_ERROR("/reduction/target: expected an integer, found 2.5");
}
TEST_F(ProjectValidation, WrongTypeOfRoot) {
    doc = Json::array();
    EXPECT_LOAD_ERROR("/: expected an object, found array");
}
TEST_F(ProjectValidation, WrongFormat) {
    doc["format"] = "something-else";
    EXPECT_LOAD_ERROR(
        "/format: expected \"visemelab-project\", found \"something-else\" (not a VisemeLab project)");
}

TEST_F(ProjectValidation, NegativeFrequency) {
    doc["frequencies"]["phonemes"]["AA"] = -0.5;
    EXPECT_LOAD_ERROR("/frequencies/phonemes/AA: expected a non-negative number, found -0.5");
}
TEST_F(ProjectValidation, NonNumericFrequency) {
    doc["frequencies"]["phonemes"]["EH"] = nullptr;
    EXPECT_LOAD_ERROR("/frequencies/phonemes/EH: expected a non-negative number, found null");
}
TEST_F(ProjectValidation, InfiniteFrequency) {
    const auto file = dir / "p.vlproj";
    std::string text = doc.dump();
    text.replace(text.find("0.3"), 3, "1e999");
    test::writeText(file, text);
    EXPECT_INPUT_ERROR(loadProject(file), "/frequencies/phonemes/EH: number out of range: 1e999");
}
TEST_F(ProjectValidation, NaNLiteralIsAJsonSyntaxError) {
    const auto file = dir / "p.vlproj";
    std::string text = doc.dump(2);
    text.replace(text.find("0.3"), 3, "NaN");
    test::writeText(file, text);
    EXPECT_INPUT_ERROR(loadProject(file), file.string() + ": invalid JSON: parse error at line");
}
TEST_F(ProjectValidation, NegativeDirectFrequencyAndUnknownViseme) {
    doc["frequencies"] = Json{{"visemes", Json{{"sil", 0.1}, {"aa", -2}}}};
    EXPECT_LOAD_ERROR("/frequencies/visemes/aa: expected a non-negative number, found -2");
    doc["frequencies"] = Json{{"visemes", Json{{"sil", 0.1}, {"zz", 2}}}};
    EXPECT_LOAD_ERROR("/frequencies/visemes/zz: unknown viseme \"zz\"");
}
TEST_F(ProjectValidation, MapErrors) {
    doc["frequencies"]["map"]["AA"] = "zz";
    EXPECT_LOAD_ERROR("/frequencies/map/AA: unknown viseme \"zz\"");
    doc["frequencies"]["map"]["AA"] = "aa";
    doc["frequencies"]["map"]["XX"] = "aa";
    EXPECT_LOAD_ERROR("/frequencies/map/XX: phoneme \"XX\" is not listed in /frequencies/phonemes");
    doc["frequencies"]["map"].erase("XX");
    doc["frequencies"]["map"].erase("OW");
    EXPECT_LOAD_ERROR("/frequencies/map: phoneme \"OW\" has no viseme");
    doc["frequencies"].erase("map");
    EXPECT_LOAD_ERROR("/frequencies/map: missing field");
}
TEST_F(ProjectValidation, DirectAndPhonemeFrequenciesTogether) {
    doc["frequencies"]["visemes"] = Json{{"aa", 1}};
    EXPECT_LOAD_ERROR("/frequencies: give either \"visemes\" or \"phonemes\" with \"map\", not both");
}

TEST_F(ProjectValidation, TargetOutOfRange) {
    doc["reduction"]["target"] = 5;
    EXPECT_LOAD_ERROR("/reduction/target: 5 is outside the allowed range 1..4");
    doc["reduction"]["target"] = 0;
    EXPECT_LOAD_ERROR("/reduction/target: 0 is outside the allowed range 1..4");
}

TEST_F(ProjectValidation, ReductionConstraints) {
    Json constraints = Json::object();
    constraints["pin"] = Json::array({"aa"});
    constraints["apart"] = Json::array({Json::array({"sil", "oh"})});
    constraints["together"] = Json::array({Json::array({"E", "oh"})});
    doc["reduction"]["constraints"] = constraints;
    const Project p = load();
    EXPECT_EQ(p.reduction.constraints.pinned, std::vector<std::string>{"aa"});
    EXPECT_EQ(p.reduction.constraints.apart,
              (std::vector<std::pair<std::string, std::string>>{{"sil", "oh"}}));
    EXPECT_EQ(p.reduction.constraints.together,
              (std::vector<std::pair<std::string, std::string>>{{"E", "oh"}}));
    doc["reduction"]["constraints"]["pin"][0] = "PP";
    EXPECT_LOAD_ERROR("/reduction/constraints/pin/0: unknown viseme \"PP\"");
    doc["reduction"]["constraints"]["pin"][0] = "aa";
    doc["reduction"]["constraints"]["apart"][0] = Json{"sil"};
    EXPECT_LOAD_ERROR("/reduction/constraints/apart/0: expected an array of 2 elements");
    doc["reduction"]["constraints"]["apart"][0] = Json{"oh", "oh"};
    EXPECT_LOAD_ERROR("/reduction/constraints/apart/0: \"oh\" is paired with itself");
    doc["reduction"]["constraints"]["apart"][0] = Json{"oh", "aa"};
    doc["reduction"]["constraints"]["keep"] = Json::array();
    EXPECT_LOAD_ERROR("/reduction/constraints/keep: unknown field");
}

TEST_F(ProjectValidation, ResultCertificates) {
    auto& curve = doc["reduction"]["result"]["curve"];
    curve[0] = Json{{"infeasible", true}};
    curve[1]["optimal"] = false;
    curve[1]["lowerBound"] = 1.0;
    const Project p = load();
    EXPECT_FALSE(p.reduction.result->curve[0].feasible());
    EXPECT_FALSE(p.reduction.result->curve[1].optimal);
    EXPECT_EQ(p.reduction.result->curve[1].lowerBound, 1.0);
    curve[1]["lowerBound"] = 2.0;
    EXPECT_LOAD_ERROR(
        "/reduction/result/curve/1/lowerBound: the lower bound exceeds the cost of the grouping");
    curve[1]["lowerBound"] = 1.0;
    curve[0]["infeasible"] = false;
    EXPECT_LOAD_ERROR("/reduction/result/curve/0/infeasible: expected true");
}

TEST_F(ProjectValidation, MissingMeshFile) {
    doc["visemes"][3]["file"] = "nope.obj";
    EXPECT_LOAD_ERROR("/visemes/3/file: file not found (" + (dir / "nope.obj").string() + ")");
    doc["visemes"][3]["file"] = "oh.obj";
    doc["neutral"]["file"] = "sub/neutral.obj";
    EXPECT_LOAD_ERROR("/neutral/file: file not found");
}
TEST_F(ProjectValidation, MeshFileThatIsAFolder) {
    std::filesystem::create_directories(dir / "folder.obj");
    doc["visemes"][0]["file"] = "folder.obj";
    EXPECT_LOAD_ERROR("/visemes/0/file: file not found");
}
TEST_F(ProjectValidation, EmptyFileName) {
    doc["visemes"][0]["file"] = "";
    EXPECT_LOAD_ERROR("/visemes/0/file: expected a non-empty string");
}

TEST_F(ProjectValidation, VisemeNames) {
    doc["visemes"][2]["name"] = "aa";
    EXPECT_LOAD_ERROR("/visemes/2/name: duplicate viseme name \"aa\"");
    doc["visemes"][2]["name"] = "";
    EXPECT_LOAD_ERROR("/visemes/2/name: expected a non-empty string");
}
TEST_F(ProjectValidation, FileAndPositionsTogether) {
    doc["visemes"][1]["positions"] = Json::array({Json::array({0, 0, 0})});
    EXPECT_LOAD_ERROR("/visemes/1: give either \"file\" or \"positions\", not both");
}
TEST_F(ProjectValidation, UnknownFields) {
    doc["frequncies"] = Json::object();
    EXPECT_LOAD_ERROR("/frequncies: unknown field");
    doc.erase("frequncies");
    doc["visemes"][0]["colour"] = "red";
    EXPECT_LOAD_ERROR("/visemes/0/colour: unknown field");
}
TEST_F(ProjectValidation, NeutralRequiredWithVisemes) {
    doc["neutral"] = nullptr;
    EXPECT_LOAD_ERROR("/neutral: a neutral mesh is required when visemes are listed");
}

TEST_F(ProjectValidation, WeightErrors) {
    doc["weights"]["mode"] = "heavy";
    EXPECT_LOAD_ERROR("/weights/mode: unknown weight mode \"heavy\" (expected uniform, area or painted)");
    doc["weights"]["mode"] = "painted";
    EXPECT_LOAD_ERROR("/weights/painted: missing field");
    doc["weights"]["painted"] = Json::array({1.0, -1.0});
    EXPECT_LOAD_ERROR("/weights/painted/1: expected a non-negative number, found -1.0");
    doc["weights"]["painted"] = Json::array({0, 0.0});
    EXPECT_LOAD_ERROR("/weights/painted: all weights are zero");
}

TEST_F(ProjectValidation, ResultErrors) {
    auto& curve = doc["reduction"]["result"]["curve"];
    curve[1]["groups"] = Json::array({Json::array({"sil", "aa", "E", "oh"})});
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/groups: expected 2 groups");
    curve[1]["groups"] = Json::array({Json::array({"sil", "aa"}), Json::array({"aa", "E", "oh"})});
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/groups/1/0: viseme \"aa\" is in more than one group");
    curve[1]["groups"] = Json::array({Json::array({"sil"}), Json::array({"E", "oh"})});
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/groups: viseme \"aa\" is in no group");
    curve[1]["groups"] = Json::array({Json::array({"sil"}), Json::array({"aa", "E", "ohh"})});
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/groups/1/2: unknown viseme \"ohh\"");
    curve[1]["groups"] = Json::array({Json::array({"sil", "aa", "E", "oh"}), Json::array()});
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/groups/1: empty group");
    curve[1]["groups"] = Json::array({Json::array({"sil"}), Json::array({"aa", "E", "oh"})});
    curve[1]["cost"] = -1;
    EXPECT_LOAD_ERROR("/reduction/result/curve/1/cost: expected a non-negative number, found -1");
    curve = Json::array();
    EXPECT_LOAD_ERROR("/reduction/result/curve: expected 1..4 entries");
}
TEST_F(ProjectValidation, ResultGroupsAreCanonicalised) {
    doc["reduction"]["result"]["curve"][1]["groups"] =
        Json::array({Json::array({"oh", "E", "aa"}), Json::array({"sil"})});
    const Project p = load();
    EXPECT_EQ(p.reduction.result->curve[1].groups, (std::vector<std::vector<int>>{{0}, {1, 2, 3}}));
}

TEST_F(ProjectValidation, Refinement) {
    doc["refinement"] = parseJsonStrict(R"({"criterion": "contour", "maxDepth": 8,
        "normals": {"dihedralAngleDeg": 15, "normalAngleDeg": 25},
        "contour": {"averageError": 0.01, "maximumError": 0.05, "samplesPerSide": 6}})",
                                        "r");
    const Project p = load();
    EXPECT_EQ(p.refinement.kind, CriterionKind::Contour);
    EXPECT_EQ(p.refinement.maxDepth, 8);
    EXPECT_EQ(p.refinement.depth.depth, CriterionSettings{}.depth.depth); // section absent: default
    EXPECT_EQ(p.refinement.normals.normalAngleDeg, 25.0);
    EXPECT_EQ(p.refinement.contour.samplesPerSide, 6);

    doc["refinement"]["criterion"] = "curvature";
    EXPECT_LOAD_ERROR(
        "/refinement/criterion: unknown criterion 'curvature' (expected depth, normals or contour)");
    doc["refinement"]["criterion"] = "normals";
    doc["refinement"]["maxDepth"] = 31;
    EXPECT_LOAD_ERROR("/refinement/maxDepth: 31 is outside the allowed range 0..30");
    doc["refinement"]["maxDepth"] = 5;
    doc["refinement"]["normals"]["dihedralAngleDeg"] = -3;
    EXPECT_LOAD_ERROR("/refinement/normals/dihedralAngleDeg: expected a non-negative number, found -3");
    doc["refinement"]["normals"]["dihedralAngleDeg"] = 3;
    doc["refinement"]["contour"]["samplesPerSide"] = 0;
    EXPECT_LOAD_ERROR("/refinement/contour/samplesPerSide: 0 is outside the allowed range 1..32");
    doc["refinement"]["contour"]["samplesPerSide"] = 2;
    doc["refinement"]["depth"] = Json{{"depth", -1}};
    EXPECT_LOAD_ERROR("/refinement/depth/depth: -1 is outside the allowed range");
    doc["refinement"].erase("depth");
    doc["refinement"].erase("maxDepth");
    EXPECT_LOAD_ERROR("/refinement/maxDepth: missing field");
}

TEST_F(ProjectValidation, EditorSelection) {
    doc["editor"]["selectedViseme"] = "zz";
    EXPECT_LOAD_ERROR("/editor/selectedViseme: unknown viseme \"zz\"");
}

TEST_F(ProjectValidation, EmbeddedMeshErrors) {
    doc["neutral"] = Json{
        {"positions", Json::array({Json::array({0, 0, 0}), Json::array({1, 0, 0}), Json::array({0, 1, 0})})},
        {"triangles", Json::array({Json::array({0, 1, 2})})}};
    doc["visemes"][0] = Json{{"name", "sil"}, {"positions", doc["neutral"]["positions"]}};
    EXPECT_NO_THROW(load());

    doc["neutral"]["triangles"][0][2] = 3;
    EXPECT_LOAD_ERROR("/neutral/triangles/0/2: 3 is outside the allowed range 0..2");
    doc["neutral"]["triangles"][0] = Json::array({0, 1, 1});
    EXPECT_LOAD_ERROR("/neutral/triangles/0: a triangle repeats a vertex index");
    doc["neutral"]["triangles"][0] = Json::array({0, 1});
    EXPECT_LOAD_ERROR("/neutral/triangles/0: expected an array of 3 elements, found 2");
    doc["neutral"]["triangles"][0] = Json::array({0, 1, 2});
    doc["neutral"]["uvs"] = Json::array({Json::array({0, 0})});
    EXPECT_LOAD_ERROR("/neutral/uvs: expected 3 (u,v) pairs, one per vertex, found 1");
    doc["neutral"].erase("uvs");
    doc["neutral"]["positions"][1][0] = "x";
    EXPECT_LOAD_ERROR("/neutral/positions/1/0: expected a number, found string \"x\"");
    doc["neutral"]["positions"][1][0] = 1;
    doc["visemes"][0]["positions"].erase(2);
    EXPECT_LOAD_ERROR("/visemes/0/positions: expected 3 vertices (as the neutral mesh), found 2");
    doc["visemes"][0]["positions"] = Json::array();
    EXPECT_LOAD_ERROR("/visemes/0/positions: expected at least one vertex");
    doc["visemes"][0]["positions"] = doc["neutral"]["positions"];
    doc["weights"] = Json{{"mode", "painted"}, {"painted", Json::array({1, 2})}};
    EXPECT_LOAD_ERROR("/weights/painted: expected 3 weights (one per vertex), found 2");
}

// Found by fuzz_project: validation errors of projects parsed from memory named only the JSON path.
TEST(ProjectText, ErrorsNameTheFileItStandsFor) {
    const std::string text = R"({"format": "visemelab-project", "version": 0, "neutral": "n.obj",
        "visemes": {"aa": "aa.obj"}, "wekghts": [1], "target": 1})";
    EXPECT_INPUT_ERROR(projectFromJsonText(text, "/nowhere/typo.vlproj", false),
                       "/nowhere/typo.vlproj: /wekghts: unknown field");
    EXPECT_INPUT_ERROR(projectFromJsonText("[1, 2", "/nowhere/cut.vlproj", false), "/nowhere/cut.vlproj: ");
}

} // namespace
} // namespace vl
