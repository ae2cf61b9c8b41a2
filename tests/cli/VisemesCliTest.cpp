#include "core/face/FaceDomain.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

namespace vl {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    // The process id keeps concurrent runs (several build folders, ctest -j) apart.
    const auto dir = fs::temp_directory_path() / ("visemelab_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

TEST(CliVisemes, WritesAnInterpolableSetAndItsParameterVectors) {
    const auto dir = freshDir("cli_visemes");
    const auto r =
        test::runCli("visemes --face retarget --resolution 14 --density uniform --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto files = listVisemeFolder(dir, dir / "neutral.obj");
    ASSERT_EQ(files.size(), 15u);
    const VisemeSet set = loadVisemeSet(dir / "neutral.obj", files);
    // The skin (the face domain's triangles) comes first, then the head's parts (eyeballs, teeth,
    // tongue, mouth cavity) with their (u,v) in tiles right of the face domain.
    const auto skin = face::faceDomainMesh(14);
    ASSERT_GT(set.neutral.triangles.size(), skin.triangles.size());
    EXPECT_TRUE(std::equal(skin.triangles.begin(), skin.triangles.end(), set.neutral.triangles.begin()));
    for (std::size_t i = skin.positions.size(); i < set.vertexCount(); ++i)
        EXPECT_NE(face::headTileOf(set.neutral.uvs[i][0]), face::HeadTile::Skin) << i;
    std::ifstream in(dir / "visemes.json");
    const auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["face"], "retarget");
    EXPECT_EQ(j["visemes"].size(), 15u);
    EXPECT_EQ(j["visemes"][10]["name"], "aa");
    EXPECT_EQ(j["visemes"][10]["parameters"]["jaw_open"], 1.0);
    EXPECT_EQ(j["vertices"], set.vertexCount());
    // Coordinates are rounded to --decimals (6 by default).
    for (const auto& p : set.neutral.positions)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k] * 1e6, std::round(p[k] * 1e6), 1e-6);
    fs::remove_all(dir);
}

TEST(CliVisemes, ReadsEditedParameterVectors) {
    const auto dir = freshDir("cli_viseme_file");
    fs::create_directories(dir);
    const auto file = dir / "mine.json";
    std::ofstream(file) << R"({"visemes": [{"name": "open", "parameters": {"jaw_open": 0.5}},
                                           {"name": "smile", "parameters": {"zygomatic_l": 1, "zygomatic_r": 1}}]})";
    const auto r = test::runCli("visemes --resolution 12 --viseme-file " + file.string() + " --out " +
                                (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "out" / "open.obj"));
    EXPECT_TRUE(fs::exists(dir / "out" / "smile.obj"));
    EXPECT_FALSE(fs::exists(dir / "out" / "aa.obj"));
    // The written visemes.json reads back as a viseme file.
    const auto again =
        test::runCli("visemes --resolution 12 --viseme-file " + (dir / "out" / "visemes.json").string() +
                     " --out " + (dir / "again").string());
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(readMesh(dir / "again" / "smile.obj").positions, readMesh(dir / "out" / "smile.obj").positions);

    std::ofstream(file) << R"({"visemes": [{"name": "open", "parameters": {"jaw": 0.5}}, {"name": "b"}]})";
    const auto bad =
        test::runCli("visemes --viseme-file " + file.string() + " --out " + (dir / "bad").string());
    EXPECT_EQ(bad.exitCode, 3);
    EXPECT_NE(bad.output.find("/visemes/0/parameters/jaw: unknown parameter 'jaw'"), std::string::npos)
        << bad.output;
    std::ofstream(file) << R"({"visemes": [{"name": "open", "parameters": {"jaw_open": 2}}, {"name": "b"}]})";
    const auto range =
        test::runCli("visemes --viseme-file " + file.string() + " --out " + (dir / "bad").string());
    EXPECT_EQ(range.exitCode, 3);
    EXPECT_NE(range.output.find("jaw_open: value 2 is outside [0, 1]"), std::string::npos) << range.output;
    fs::remove_all(dir);
}

TEST(CliVisemes, ArpabetSetReducesWithTheBundledTableDirectly) {
    // --set arpabet: sil and the 39 ARPAbet phonemes, named as the bundled en-us table, so that table
    // weights the reduction without a map; a small m is proved optimal (issue 10's CI check).
    const auto dir = freshDir("cli_visemes_arpabet");
    const auto r = test::runCli("visemes --set arpabet --resolution 14 --density uniform --out " +
                                (dir / "set").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto files = listVisemeFolder(dir / "set", dir / "set" / "neutral.obj");
    ASSERT_EQ(files.size(), 40u);
    std::set<std::string> names;
    for (const auto& [name, file] : files) names.insert(name);
    for (const char* phoneme : {"sil", "AA", "AH", "B", "DH", "ER", "NG", "OY", "UW", "ZH"})
        EXPECT_TRUE(names.count(phoneme)) << phoneme;
    const auto table = fs::path(VISEMELAB_ASSETS_DIR) / "phonemes" / "en-us_frequencies.csv";
    // Two maps used as groupings: a 3-group one (closed lips / rounded / the rest) and Rhubarb's 9.
    const auto threeGroups = dir / "three.csv";
    {
        std::ofstream map(threeGroups);
        map << "phoneme,viseme\n";
        for (const auto& name : names)
            map << name << ","
                << (name == "P" || name == "B" || name == "M" || name == "sil" ? "closed"
                    : name == "UW" || name == "W" || name == "OW"              ? "round"
                                                                               : "open")
                << "\n";
    }
    const auto rhubarb = fs::path(VISEMELAB_ASSETS_DIR) / "phonemes" / "map_rhubarb.csv";
    const auto reduced =
        test::runCli("reduce --visemes " + (dir / "set").string() + " --freq-file " + table.string() +
                     " -m 5 --time-limit 120 --out " + (dir / "reduced").string() + " --compare-map " +
                     threeGroups.string() + " --compare-map " + rhubarb.string());
    ASSERT_EQ(reduced.exitCode, 0) << reduced.output;
    EXPECT_NE(reduced.output.find("Reduced 40 visemes to 5"), std::string::npos) << reduced.output;
    std::ifstream in(dir / "reduced" / "report.json");
    const auto report = nlohmann::json::parse(in);
    EXPECT_EQ(report["optimal"], true) << reduced.output;
    EXPECT_EQ(report["gap"], 0.0);
    EXPECT_EQ(report["groups"].size(), 5u);
    ASSERT_EQ(report["groups_curve"].size(), 5u);
    EXPECT_EQ(report["groups_curve"][4], report["groups"]);
    EXPECT_EQ(report["groups_curve"][0].size(), 1u);
    // The set has sil: the rest is free by default, so one key holds every viseme that does not rest.
    EXPECT_EQ(report["rest"]["model"], "free");
    EXPECT_EQ(report["groups_curve"][0][0].size() + report["rest_curve"][0].size(), 40u);
    // The maps' groupings, costed under the same objective: never below the optimum for as many
    // groups (compared when the run solved that p), and Rhubarb's 9 groups beyond m = 5.
    ASSERT_EQ(report["compared_maps"].size(), 2u) << report.dump();
    const auto& three = report["compared_maps"][0];
    EXPECT_EQ(three["groups"], 3);
    EXPECT_EQ(three["grouping"]["closed"], nlohmann::json::array({"B", "M", "P", "sil"}));
    EXPECT_EQ(three["optimal_cost"], report["cost_curve"][2]);
    EXPECT_GE(three["cost"].get<double>(), three["optimal_cost"].get<double>());
    EXPECT_GE(three["excess"].get<double>(), 0.0);
    const auto& blair = report["compared_maps"][1];
    EXPECT_EQ(blair["groups"], 9);
    EXPECT_GT(blair["cost"].get<double>(), 0.0);
    EXPECT_FALSE(blair.contains("optimal_cost"));
    EXPECT_NE(reduced.output.find("as a grouping: 3 groups"), std::string::npos) << reduced.output;
    // A map that leaves visemes out cannot group the set.
    std::ofstream(dir / "partial.csv") << "phoneme,viseme\nP,closed\nB,closed\n";
    const auto partial = test::runCli("reduce --visemes " + (dir / "set").string() + " --freq-file " +
                                      table.string() + " -m 2 --out " + (dir / "partial").string() +
                                      " --compare-map " + (dir / "partial.csv").string());
    EXPECT_EQ(partial.exitCode, 3) << partial.output;
    EXPECT_NE(partial.output.find("used as a grouping, it does not map these visemes: AA, AE"),
              std::string::npos)
        << partial.output;
    // The bilabials share a key.
    const auto mapping = nlohmann::json::parse(std::ifstream(dir / "reduced" / "mapping.json"));
    EXPECT_EQ(mapping["visemes"]["P"], mapping["visemes"]["B"]) << mapping.dump();
    EXPECT_EQ(mapping["visemes"]["P"], mapping["visemes"]["M"]) << mapping.dump();
    fs::remove_all(dir);
}

TEST(CliVisemes, RejectsAnUnknownSetListingTheValidOnes) {
    const auto r = test::runCli("visemes --set ipa --out /tmp/x");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.output.find("--set: unknown viseme set 'ipa' (valid: oculus, arpabet)"), std::string::npos)
        << r.output;
    const auto both = test::runCli("visemes --set arpabet --viseme-file x.json --out /tmp/x");
    EXPECT_EQ(both.exitCode, 2) << both.output;
}

TEST(CliVisemes, SkinOnlyLeavesOutTheHeadsParts) {
    const auto dir = freshDir("cli_visemes_skin");
    const auto r =
        test::runCli("visemes --skin-only --resolution 14 --density uniform --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const VisemeSet set = loadVisemeSet(dir / "neutral.obj", listVisemeFolder(dir, dir / "neutral.obj"));
    EXPECT_EQ(set.neutral.triangles, face::faceDomainMesh(14).triangles);
    fs::remove_all(dir);
}

TEST(CliVisemes, RejectsBadOptions) {
    EXPECT_EQ(test::runCli("visemes --face alien --out /tmp/x").exitCode, 3);
    EXPECT_EQ(test::runCli("visemes --resolution 3 --out /tmp/x").exitCode, 3);
    EXPECT_EQ(test::runCli("visemes --density foo --out /tmp/x").exitCode, 3);
    EXPECT_EQ(test::runCli("visemes --resolution abc").exitCode, 2);
}

TEST(CliRender, WritesAPngOfAMesh) {
    const auto dir = freshDir("cli_render");
    ASSERT_EQ(test::runCli("visemes --resolution 12 --out " + dir.string()).exitCode, 0);
    const auto png = dir / "aa.png";
    const auto r = test::runCli("render " + (dir / "aa.obj").string() + " --out " + png.string() +
                                " --size 64x48 --wireframe --face-colours --yaw 20");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(fs::file_size(png), 100u);
    const auto sheet = dir / "sheet.png";
    ASSERT_EQ(test::runCli("render " + (dir / "aa.obj").string() + " " + (dir / "ou.obj").string() + " " +
                           (dir / "PP.obj").string() + " --columns 2 --size 30x20 --out " + sheet.string())
                  .exitCode,
              0);
    int w = 0, h = 0, n = 0;
    ASSERT_TRUE(stbi_info(sheet.c_str(), &w, &h, &n));
    EXPECT_EQ(w, 60);
    EXPECT_EQ(h, 40);
    EXPECT_EQ(test::runCli("render " + (dir / "aa.obj").string() + " --out x.png --size 64").exitCode, 3);
    EXPECT_EQ(test::runCli("render " + (dir / "missing.obj").string() + " --out x.png").exitCode, 3);
    EXPECT_EQ(test::runCli("render").exitCode, 2);
    // --focus: a close-up of the mouth at one scale; a bad sphere is refused.
    const auto close = dir / "close.png";
    const auto focused = test::runCli("render " + (dir / "aa.obj").string() +
                                      " --focus 0,-3,5,2 --size 40x30 --out " + close.string());
    ASSERT_EQ(focused.exitCode, 0) << focused.output;
    ASSERT_TRUE(stbi_info(close.c_str(), &w, &h, &n));
    EXPECT_EQ(w, 40);
    for (const auto* bad : {"0,0,0", "0,0,0,0", "0,0,x,1"}) {
        const auto r2 = test::runCli("render " + (dir / "aa.obj").string() + " --focus " + bad + " --out " +
                                     close.string());
        EXPECT_EQ(r2.exitCode, 3) << bad << ": " << r2.output;
        EXPECT_NE(r2.output.find("--focus"), std::string::npos) << r2.output;
    }
    fs::remove_all(dir);
}

TEST(CliFaceMouth, MeasuresVisemeMeshesAgainstTheNeutral) {
    const auto dir = freshDir("cli_face_mouth");
    ASSERT_EQ(test::runCli("visemes --resolution 20 --out " + dir.string()).exitCode, 0);
    const auto json = dir / "mouth.json";
    const auto r = test::runCli("face mouth --neutral " + (dir / "neutral.obj").string() + " " +
                                (dir / "PP.obj").string() + " " + (dir / "aa.obj").string() + " " +
                                (dir / "ou.obj").string() + " --json " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // A Markdown table: header, rule, the neutral and one row per mesh.
    EXPECT_NE(r.output.find("| mesh | opening |"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| (neutral) |"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| aa |"), std::string::npos) << r.output;
    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j["meshes"].size(), 3u);
    const auto& pp = j["meshes"][0];
    const auto& aa = j["meshes"][1];
    const auto& ou = j["meshes"][2];
    EXPECT_EQ(aa["name"], "aa");
    EXPECT_LT(pp["relative_to_neutral"]["upper_lip_forward"].get<double>(), 0.0); // pressed, rolled in
    EXPECT_LT(pp["relative_to_neutral"]["opening"].get<double>(), 0.0);           // closed
    EXPECT_LT(std::abs(pp["opening"].get<double>()), 0.02);
    EXPECT_GT(aa["opening"].get<double>(), 1.0);
    EXPECT_GT(aa["lower_teeth_seen"].get<double>(), 0.0);
    EXPECT_EQ(pp["lower_teeth_seen"].get<double>(), 0.0);
    EXPECT_LT(ou["relative_to_neutral"]["width_ratio"].get<double>(), 1.0);
    EXPECT_GT(ou["relative_to_neutral"]["upper_lip_forward"].get<double>(), 0.0);
    EXPECT_TRUE(aa["lower_lip_to_upper_teeth"].is_number());
    // Without parts (--skin-only) there are no teeth to measure; a mesh of no face domain is refused.
    ASSERT_EQ(test::runCli("visemes --resolution 12 --skin-only --out " + (dir / "skin").string()).exitCode,
              0);
    const auto skin =
        test::runCli("face mouth " + (dir / "skin" / "aa.obj").string() + " --json " + json.string());
    ASSERT_EQ(skin.exitCode, 0) << skin.output;
    std::ifstream again(json);
    EXPECT_TRUE(nlohmann::json::parse(again)["meshes"][0]["lower_lip_to_upper_teeth"].is_null());
    std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const auto bad = test::runCli("face mouth " + (dir / "tri.obj").string());
    EXPECT_EQ(bad.exitCode, 3) << bad.output;
    EXPECT_NE(bad.output.find("tri.obj"), std::string::npos) << bad.output;
    EXPECT_EQ(test::runCli("face mouth").exitCode, 2);
    fs::remove_all(dir);
}

} // namespace
} // namespace vl
