// The reduction's rest model in project files (version 3): the choice, the rest viseme and resting
// visemes survive save and load; files without them load as the keyed model they ran; hostile values
// are refused with the file and element.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"

namespace vl {
namespace {

using test::ScratchDir;

// Three embedded visemes over a one-triangle neutral: enough for every rule of the section.
std::string projectText(int version, const std::string& reduction) {
    return R"({"format": "visemelab-project", "version": )" + std::to_string(version) + R"(,
      "neutral": {"positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]},
      "visemes": [{"name": "sil", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
                  {"name": "aa", "positions": [[0, 0, 1], [1, 0, 0], [0, 1, 0]]},
                  {"name": "PP", "positions": [[0, 0, 0], [1, 0, 1], [0, 1, 0]]}],
      "reduction": )" +
           reduction + "}";
}

Project loadText(const ScratchDir& dir, int version, const std::string& reduction) {
    test::writeText(dir / "p.vlproj", projectText(version, reduction));
    return loadProject(dir / "p.vlproj");
}

TEST(ProjectRest, RestModelAndRestingVisemesSurviveSaveAndLoad) {
    ScratchDir dir("rest_roundtrip");
    Project project = loadText(dir, 1, R"({"target": 1, "result": null})");
    project.reduction.rest = RestChoice::Free;
    project.reduction.restViseme = "PP";
    ReductionResult result;
    result.restFree = true;
    result.curve.push_back({2.5, 2.5, true, {{1}}, {0, 2}}); // aa is the key, sil and PP rest
    project.reduction.result = result;
    saveProject(project.path, project);
    const std::string text = readFileToString(project.path);
    EXPECT_NE(text.find("\"version\": 3"), std::string::npos);
    EXPECT_NE(text.find("\"rest\": \"free\""), std::string::npos);
    EXPECT_NE(text.find("\"restViseme\": \"PP\""), std::string::npos);
    EXPECT_NE(text.find("\"rests\": [\"sil\", \"PP\"]"), std::string::npos);
    EXPECT_NE(text.find("\"restFree\": true"), std::string::npos);
    const Project loaded = loadProject(project.path);
    EXPECT_TRUE(loaded == project);
    EXPECT_EQ(loaded.reduction.result->groupOf(), (std::vector<int>{kRestGroup, 0, kRestGroup}));
    saveProject(project.path, loaded); // saved again: byte-identical
    EXPECT_EQ(readFileToString(project.path), text);
}

TEST(ProjectRest, AutoIsWrittenSoItDoesNotTurnIntoKeyOnLoad) {
    ScratchDir dir("rest_auto");
    Project project = loadText(dir, 1, R"({"target": 2, "result": null})");
    project.reduction.rest = RestChoice::Auto;
    saveProject(project.path, project);
    EXPECT_NE(readFileToString(project.path).find("\"rest\": \"auto\""), std::string::npos);
    EXPECT_EQ(loadProject(project.path).reduction.rest, RestChoice::Auto);
}

TEST(ProjectRest, OldFilesLoadAsTheKeyedModelAndKeepTheirLayout) {
    ScratchDir dir("rest_old");
    const std::string reduction =
        R"({"target": 2, "result": {"curve": [{"cost": 3, "groups": [["sil", "aa", "PP"]]},
                                              {"cost": 1, "groups": [["sil", "PP"], ["aa"]]}]}})";
    for (const int version : {1, 2}) {
        const Project old = loadText(dir, version, reduction);
        EXPECT_EQ(old.reduction.rest, RestChoice::Key);
        EXPECT_TRUE(old.reduction.restViseme.empty());
        EXPECT_FALSE(old.reduction.result->restFree);
        saveProject(old.path, old); // nothing of version 3: written as version 1
        const std::string text = readFileToString(old.path);
        EXPECT_NE(text.find("\"version\": 1"), std::string::npos);
        EXPECT_EQ(text.find("rest"), std::string::npos);
    }
    // A version 3 file without the field ran the keyed model too.
    EXPECT_EQ(loadText(dir, 3, reduction).reduction.rest, RestChoice::Key);
}

TEST(ProjectRest, TheRestModelInAnOlderVersionIsRefused) {
    ScratchDir dir("rest_version");
    EXPECT_INPUT_ERROR(
        loadText(dir, 2, R"({"target": 1, "rest": "free"})"),
        "p.vlproj: /reduction/rest: the rest model needs project version 3 (this file says 2)");
    EXPECT_INPUT_ERROR(loadText(dir, 1, R"({"target": 1, "restViseme": "sil"})"),
                       "/reduction/restViseme: the rest model needs project version 3 (this file says 1)");
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 1,
            R"({"target": 1, "result": {"restFree": true, "curve": [{"cost": 0, "groups": [["aa", "PP", "sil"]]}]}})"),
        "/reduction/result/restFree: the rest model needs project version 3");
}

TEST(ProjectRest, HostileValuesNameTheFileAndElement) {
    ScratchDir dir("rest_hostile");
    EXPECT_INPUT_ERROR(loadText(dir, 3, R"({"target": 1, "rest": "sometimes"})"),
                       "p.vlproj: /reduction/rest: unknown rest model \"sometimes\" (expected \"free\", "
                       "\"key\" or \"auto\")");
    EXPECT_INPUT_ERROR(loadText(dir, 3, R"({"target": 1, "rest": 1})"),
                       "p.vlproj: /reduction/rest: expected");
    EXPECT_INPUT_ERROR(loadText(dir, 3, R"({"target": 1, "restViseme": "viseme_sil"})"),
                       "p.vlproj: /reduction/restViseme: unknown viseme \"viseme_sil\"");
    EXPECT_INPUT_ERROR(loadText(dir, 3, R"({"target": 1, "restViseme": ""})"),
                       "p.vlproj: /reduction/restViseme");
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 3,
            R"({"target": 1, "result": {"restFree": false, "curve": [{"cost": 0, "groups": [["aa", "PP", "sil"]]}]}})"),
        "p.vlproj: /reduction/result/restFree: expected true (or leave the key out)");
    // Resting visemes only in a rest-free result, each viseme exactly once in a key or at rest.
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 3,
            R"({"target": 1, "result": {"curve": [{"cost": 0, "groups": [["aa", "PP"]], "rests": ["sil"]}]}})"),
        "p.vlproj: /reduction/result/curve/0/rests: resting visemes need a rest-free result");
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 3,
            R"({"target": 1, "result": {"restFree": true, "curve": [{"cost": 0, "groups": [["aa"]], "rests": ["sil"]}]}})"),
        "p.vlproj: /reduction/result/curve/0/groups: viseme \"PP\" is in no group and does not rest");
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 3,
            R"({"target": 1, "result": {"restFree": true, "curve": [{"cost": 0, "groups": [["aa", "PP"]], "rests": ["sil", "aa"]}]}})"),
        "p.vlproj: /reduction/result/curve/0/rests/1: viseme \"aa\" is in more than one group");
    EXPECT_INPUT_ERROR(
        loadText(
            dir, 3,
            R"({"target": 1, "result": {"restFree": true, "curve": [{"cost": 0, "groups": [["aa", "PP"]], "rests": ["oh"]}]}})"),
        "p.vlproj: /reduction/result/curve/0/rests/0: unknown viseme \"oh\"");
}

} // namespace
} // namespace vl
