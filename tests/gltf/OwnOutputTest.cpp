// VisemeLab reading its own output (core/gltf/OwnOutput.h), the merged target names it writes
// (core/gltf/MergedNames.h), and what `avatar inspect` says about such a file.
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/MergedNames.h"
#include "core/gltf/TargetNames.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GltfTestSupport.h"
#include "tests/gltf/KeyTableVersion1.h"

#include <gtest/gtest.h>

#include <set>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

bool validUtf8(const std::string& s) {
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (n == 0 || i + n > s.size()) return false;
        for (std::size_t j = 1; j < n; ++j)
            if ((static_cast<unsigned char>(s[i + j]) & 0xC0) != 0x80) return false;
        i += n;
    }
    return true;
}

struct Written {
    std::string glb;
    AvatarReduction reduction;
};

Written reduceGlb(const std::string& glb, int m, AvatarNames names, const std::string& pattern = "") {
    const GltfDocument in = parseGltfDocument(glb, "in.glb", {});
    const AvatarScan scan = scanAvatar(in, {pattern});
    const ReduceSettings settings = avatarReduceSettings(m); // as `avatar reduce`
    AvatarWriteOptions write;
    write.names = names;
    Written w;
    w.reduction = reduceAvatar(in, scan, uniformFrequencies(scan), settings, write);
    w.glb = w.reduction.glb;
    return w;
}

// Every target name of every mesh: at most 63 bytes of valid UTF-8, unique on its mesh.
void expectBlenderSafeNames(const GltfDocument& doc) {
    for (std::size_t m = 0; m < doc.model.meshes.size(); ++m) {
        std::set<std::string> seen;
        for (const TargetName& t : meshTargetNames(doc, static_cast<int>(m))) {
            EXPECT_LE(t.name.size(), kMaxTargetNameBytes) << t.name;
            EXPECT_TRUE(validUtf8(t.name)) << t.name;
            EXPECT_TRUE(seen.insert(t.name).second) << "twice on mesh " << m << ": " << t.name;
        }
    }
}

const Json& meshNamed(const GltfDocument& doc, const std::string& name) {
    for (const Json& m : doc.json["meshes"])
        if (m["name"] == name) return m;
    throw std::runtime_error("no mesh " + name);
}

// The key table the scan read for the mesh named `name`.
const OwnMesh& ownMeshNamed(const AvatarScan& scan, const GltfDocument& doc, const std::string& name) {
    for (const OwnMesh& m : scan.own.meshes)
        if (doc.json["meshes"][static_cast<std::size_t>(m.mesh)]["name"] == name) return m;
    throw std::runtime_error("no key table on mesh " + name);
}

// Every original viseme name resolves on the mesh, as a player resolves it (targetNames, the mesh's
// few aliases, the root key table): to its key's target, a resting viseme to its own zero target.
void expectEveryVisemeResolves(const AvatarScan& scan, const GltfDocument& doc, const std::string& mesh,
                               const std::vector<std::string>& visemes) {
    const OwnMesh& own = ownMeshNamed(scan, doc, mesh);
    const auto targetNames = meshNamed(doc, mesh)["extras"]["targetNames"].get<std::vector<std::string>>();
    for (const std::string& viseme : visemes) {
        ASSERT_TRUE(own.aliases.count(viseme)) << viseme;
        const std::string& at = targetNames[static_cast<std::size_t>(own.aliases.at(viseme))];
        const auto owner = std::find_if(scan.own.keys.begin(), scan.own.keys.end(), [&](const OwnKey& k) {
            return std::find(k.members.begin(), k.members.end(), viseme) != k.members.end();
        });
        EXPECT_EQ(at, owner == scan.own.keys.end() ? viseme : owner->name) << viseme;
    }
}

TEST(MergedNames, DropTheMembersSharedPrefixAfterTheFirst) {
    EXPECT_EQ(
        mergedTargetNames({{"viseme_PP", "viseme_FF", "viseme_TH"},
                           {"Fcl_MTH_A", "Fcl_MTH_E"},
                           {"viseme_aa"},
                           {"mouthA", "mouthB"},
                           {"V_", "V_A"}},
                          {}),
        (std::vector<std::string>{"viseme_PP+FF+TH", "Fcl_MTH_A+E", "viseme_aa", "mouthA+mouthB", "V_+V_A"}));
    // A name a kept target has is not reused.
    EXPECT_EQ(mergedTargetNames({{"viseme_PP", "viseme_FF"}}, {"viseme_PP+FF"}),
              std::vector<std::string>{"viseme_PP+FF~2"});
}

TEST(MergedNames, LongNamesFitIn63BytesWithoutCuttingACodePointAndStayUnique) {
    // 'Ö' is two bytes: cuts at 56 and 58 bytes fall inside or beside one in these names.
    const std::string l = "Kiefer_Öffnung_sehr_weit_nach_unten_und_außen_ÖÖÖÖÖÖÖÖ_Phonem_";
    std::vector<std::vector<std::string>> keys{{l + "1", l + "2"}, {l + "3", l + "4"}, {"jaw", "lip"}};
    std::vector<std::string> many;
    for (int i = 0; i < 12; ++i) many.push_back("Mund" + std::to_string(i) + "_breit");
    keys.push_back(many);
    keys.push_back({l + "5"}); // one member: its own name, whatever its length
    const auto names = mergedTargetNames(keys, {});
    ASSERT_EQ(names.size(), keys.size());
    std::set<std::string> unique(names.begin(), names.end());
    EXPECT_EQ(unique.size(), names.size());
    for (std::size_t k = 0; k + 1 < names.size(); ++k) {
        EXPECT_LE(names[k].size(), kMaxTargetNameBytes) << names[k];
        EXPECT_TRUE(validUtf8(names[k])) << names[k];
    }
    EXPECT_EQ(names[0].substr(names[0].size() - 7), "+1 more");
    EXPECT_EQ(names[1].substr(names[1].size() - 9), "+1 more~2"); // same shortened form as key 0
    EXPECT_EQ(names[2], "jaw+lip");
    EXPECT_EQ(names[3].rfind("Mund0_breit+Mund1_breit+", 0), 0u) << names[3];
    EXPECT_NE(names[3].find(" more"), std::string::npos);
    EXPECT_EQ(names[4], l + "5");
    for (std::size_t cut = 0; cut < 70; ++cut) EXPECT_TRUE(validUtf8(utf8Prefix(l, cut))) << cut;
}

TEST(OwnOutput, MergedReductionIsRecognisedWithItsKeysMembersAndRestingVisemes) {
    for (int m : {2, 6, 10}) {
        const Written w = reduceGlb(test::rpmLikeAvatar(), m, AvatarNames::Merged);
        const GltfDocument out = parseGltfDocument(w.glb, "out.glb", {});
        expectBlenderSafeNames(out);
        const AvatarScan scan = scanAvatar(out, {});
        const ReducedModel& model = w.reduction.outcome.model;
        ASSERT_TRUE(scan.own.recognised) << m;
        EXPECT_TRUE(scan.own.notes.empty()) << scan.own.notes.front();
        EXPECT_TRUE(scan.own.mergedNames);
        ASSERT_EQ(scan.own.keys.size(), static_cast<std::size_t>(m));
        EXPECT_EQ(scan.own.visemeCount(), 15u);
        EXPECT_EQ(scan.own.resting, model.resting);
        EXPECT_FALSE(scan.own.resting.empty()); // viseme_sil rests in the rest-free model
        EXPECT_EQ(scan.visemes.size(), static_cast<std::size_t>(m));
        for (std::size_t k = 0; k < scan.own.keys.size(); ++k) {
            EXPECT_EQ(scan.own.keys[k].members, model.keys[k].members);
            EXPECT_NE(std::find(scan.visemes.begin(), scan.visemes.end(), scan.own.keys[k].name),
                      scan.visemes.end());
        }
        // Every original name resolves: to its key's target, or to its zero target. The table is
        // written once, at the root (version 2): the head lists only its targets per key.
        expectEveryVisemeResolves(scan, out, "Wolf3D_Head", test::rpmVisemeNames());
        const Json& head = meshNamed(out, "Wolf3D_Head");
        EXPECT_EQ(out.json["extras"]["visemelab"]["version"], 2);
        EXPECT_EQ(head["extras"]["visemeKeys"].size(), static_cast<std::size_t>(m));
        EXPECT_FALSE(head["extras"].contains("phonemeToTarget"));
        EXPECT_FALSE(head["extras"].contains("targetAliases")) << head["extras"]["targetAliases"].dump();
        const std::string report = formatAvatarReport(scan);
        EXPECT_NE(report.find("reduced by VisemeLab: " + std::to_string(m) +
                              " keys from 15 visemes (names merged)"),
                  std::string::npos)
            << report;
        EXPECT_NE(report.find("Visemes: " + std::to_string(m) + " (keys of VisemeLab's reduction)"),
                  std::string::npos);
        EXPECT_NE(report.find("resting (the neutral face): viseme_sil"), std::string::npos) << report;
        const Json json = avatarReportJson(scan);
        EXPECT_EQ(json["visemelab"]["keys"].size(), static_cast<std::size_t>(m));
        EXPECT_EQ(json["visemelab"]["names"], "merged");
        EXPECT_EQ(json["visemelab"]["visemes"], 15);
        EXPECT_EQ(json["visemelab"]["resting"].get<std::vector<std::string>>(), model.resting);
        EXPECT_EQ(json["visemelab"]["version"], 2);
        // Every original name of the head resolves through the aliases the report lists.
        bool headAliases = false;
        const OwnMesh& ownHead = ownMeshNamed(scan, out, "Wolf3D_Head");
        for (const Json& mesh : json["visemelab"]["meshes"])
            if (mesh["mesh"] == ownHead.mesh) {
                headAliases = true;
                for (const std::string& viseme : test::rpmVisemeNames())
                    EXPECT_EQ(mesh["aliases"].value(viseme, -1), ownHead.aliases.at(viseme)) << viseme;
            }
        EXPECT_TRUE(headAliases);
    }
}

TEST(OwnOutput, ReducingAReductionSaysWhatWasReduced) {
    const Written twice =
        reduceGlb(reduceGlb(test::rpmLikeAvatar(), 6, AvatarNames::Merged).glb, 3, AvatarNames::Merged);
    const auto& notes = twice.reduction.summary.notes;
    EXPECT_NE(
        std::find(notes.begin(), notes.end(),
                  "in.glb: reduced by VisemeLab: 6 keys from 15 visemes (names merged); its key targets "
                  "were reduced as visemes"),
        notes.end());
    const AvatarScan scan = test::scanGlb(twice.glb);
    ASSERT_TRUE(scan.own.recognised);
    EXPECT_EQ(scan.own.keys.size(), 3u);
    EXPECT_EQ(scan.own.visemeCount(), 6u); // the first reduction's keys
}

TEST(OwnOutput, OriginalNamesKeepEveryVisemeAndAreRecognisedToo) {
    const Written w = reduceGlb(test::rpmLikeAvatar(), 6, AvatarNames::Original);
    const AvatarScan scan = test::scanGlb(w.glb);
    ASSERT_TRUE(scan.own.recognised);
    EXPECT_FALSE(scan.own.mergedNames);
    EXPECT_EQ(scan.visemes.size(), 15u);
    EXPECT_NE(formatAvatarReport(scan).find("reduced by VisemeLab: 6 keys from 15 visemes (names original)"),
              std::string::npos);
    // An avatar VisemeLab did not write says nothing about it.
    const AvatarScan plain = test::scanGlb(test::rpmLikeAvatar());
    EXPECT_FALSE(plain.own.recognised);
    EXPECT_EQ(formatAvatarReport(plain).find("VisemeLab"), std::string::npos);
    EXPECT_FALSE(avatarReportJson(plain).contains("visemelab"));
}

TEST(OwnOutput, VRoidMouthShapesMergedReadBackThroughTheirPattern) {
    for (bool vrm1 : {false, true}) {
        const Written w = reduceGlb(test::vroidLikeAvatar(vrm1), 3, AvatarNames::Merged, "Fcl_MTH_[AIUEO]");
        const AvatarScan scan = test::scanGlb(w.glb, "Fcl_MTH_[AIUEO]");
        ASSERT_TRUE(scan.own.recognised);
        EXPECT_EQ(scan.visemes.size(), 3u);
        for (const OwnKey& key : scan.own.keys)
            if (key.members.size() > 1) {
                EXPECT_EQ(key.name.find("+Fcl_MTH_"), std::string::npos) << key.name;
            }
        // A pattern that matches neither a key nor its members selects nothing.
        EXPECT_TRUE(test::scanGlb(w.glb, "Fcl_EYE_*").visemes.empty());
    }
}

// The rpm-like avatar with every viseme target renamed to a long name (over 63 bytes, non-ASCII).
std::string longNamedAvatar() {
    return test::editGlb(test::rpmLikeAvatar(), [](Json& json) {
        for (Json& mesh : json["meshes"]) {
            if (!mesh.contains("extras") || !mesh["extras"].contains("targetNames")) continue;
            for (Json& name : mesh["extras"]["targetNames"])
                if (const auto oculus = oculusVisemeOf(name.get<std::string>()))
                    name = "Kopf_Gesichtsausdruck_Mundform_für_das_Phonem_" + *oculus + "_Länge_ÄÖÜ";
        }
    });
}

TEST(OwnOutput, LongTargetNamesGiveMergedNamesWithin63BytesAndReadBack) {
    const std::string glb = longNamedAvatar();
    ASSERT_EQ(test::scanGlb(glb, "Kopf_*").visemes.size(), 15u);
    for (int m : {2, 4, 8}) {
        const Written w = reduceGlb(glb, m, AvatarNames::Merged, "Kopf_*");
        const GltfDocument out = parseGltfDocument(w.glb, "out.glb", {});
        for (std::size_t k = 0; k < w.reduction.outcome.model.keys.size(); ++k) {
            // A key of several members is named by its target (its one member's name: left out).
            const Json& key = out.json["extras"]["visemelab"]["keys"][k];
            if (w.reduction.outcome.model.keys[k].members.size() > 1) {
                ASSERT_TRUE(key.contains("name")) << key.dump();
                EXPECT_LE(key["name"].get<std::string>().size(), kMaxTargetNameBytes) << key["name"];
            } else {
                EXPECT_FALSE(key.contains("name")) << key.dump();
            }
        }
        for (std::size_t mesh = 0; mesh < out.model.meshes.size(); ++mesh) {
            std::set<std::string> seen;
            for (const TargetName& t : meshTargetNames(out, static_cast<int>(mesh))) {
                EXPECT_TRUE(validUtf8(t.name)) << t.name;
                EXPECT_TRUE(seen.insert(t.name).second) << t.name;
            }
        }
        const AvatarScan scan = scanAvatar(out, {"Kopf_*"});
        ASSERT_TRUE(scan.own.recognised);
        EXPECT_EQ(scan.visemes.size(), static_cast<std::size_t>(m));
        EXPECT_EQ(scan.own.visemeCount(), 15u);
        // The full member list is in the root table, and every long name resolves through it.
        expectEveryVisemeResolves(scan, out, "Wolf3D_Head", test::scanGlb(glb, "Kopf_*").visemes);
    }
}

// One hostile edit of a merged output's JSON, and the note it must give.
struct Hostile {
    const char* what;
    std::function<void(Json&)> edit;
    std::string note;
    bool recognised;
};

// The rpm-like avatar reduced to 4 keys with merged names, and its head mesh.
struct HostileBase {
    std::string glb;
    int head = -1;
    std::string headExtras;
    Json& headJson(Json& json) const { return json["meshes"][static_cast<std::size_t>(head)]; }
};

HostileBase hostileBase() {
    HostileBase base{reduceGlb(test::rpmLikeAvatar(), 4, AvatarNames::Merged).glb, -1, ""};
    const GltfDocument doc = parseGltfDocument(base.glb, "base.glb", {});
    for (std::size_t m = 0; m < doc.json["meshes"].size(); ++m)
        if (doc.json["meshes"][m]["name"] == "Wolf3D_Head") base.head = static_cast<int>(m);
    base.headExtras = "/meshes/" + std::to_string(base.head) + "/extras";
    return base;
}

// The root table's hostile edits: the same in both versions.
std::vector<Hostile> hostileRootCases() {
    return {
        {"root not an object", [](Json& j) { j["extras"]["visemelab"] = 42; },
         "/extras/visemelab: not an object", false},
        {"names", [](Json& j) { j["extras"]["visemelab"]["names"] = 7; }, "/extras/visemelab/names", false},
        {"keys not an array", [](Json& j) { j["extras"]["visemelab"]["keys"] = "x"; },
         "/extras/visemelab/keys", false},
        {"members of numbers",
         [](Json& j) {
             j["extras"]["visemelab"]["keys"][0]["members"] = Json::array({1, 2});
         },
         "/extras/visemelab/keys/0/members", false},
        {"a member in two keys",
         [](Json& j) {
             j["extras"]["visemelab"]["keys"][1]["members"] = j["extras"]["visemelab"]["keys"][0]["members"];
         },
         "/extras/visemelab/keys/1/members", false},
        {"too many keys",
         [](Json& j) {
             j["extras"]["visemelab"]["keys"] = Json::array();
             for (int i = 0; i < 100000; ++i)
                 j["extras"]["visemelab"]["keys"].push_back({{"members", {"v" + std::to_string(i)}}});
         },
         "at most 64 keys", false},
        {"resting of the wrong type",
         [](Json& j) {
             j["extras"]["visemelab"]["resting"] = Json::array({3, "viseme_sil"});
         },
         "/extras/visemelab/resting/0", true},
        {"key tables of no mesh",
         [](Json& j) {
             for (Json& m : j["meshes"])
                 if (m.contains("extras")) m["extras"]["visemeKeys"] = Json::object();
         },
         "no mesh lists its keys", false},
        {"a key named unlike its target",
         [](Json& j) { j["extras"]["visemelab"]["keys"][0]["name"] = "nothing"; }, "'nothing'", true},
        {"a version this VisemeLab does not know", [](Json& j) { j["extras"]["visemelab"]["version"] = 3; },
         "/extras/visemelab/version", false},
        {"a version that is no number", [](Json& j) { j["extras"]["visemelab"]["version"] = "2"; },
         "/extras/visemelab/version", false},
    };
}

// The root cases and the head's edits that mean the same in both versions: an entry copied onto
// another (version 2: its targets claimed twice; version 1: its key listed twice), aliases out of range.
std::vector<Hostile> hostileCommonCases(const HostileBase& base) {
    std::vector<Hostile> cases = hostileRootCases();
    const std::string& at = base.headExtras;
    cases.push_back({"an entry copied onto another",
                     [&base](Json& j) {
                         Json& keys = base.headJson(j)["extras"]["visemeKeys"];
                         keys[2] = keys[1];
                     },
                     at + "/visemeKeys/2", true});
    cases.push_back(
        {"aliases out of range",
         [&base](Json& j) {
             base.headJson(j)["extras"]["targetAliases"] = {{"viseme_aa", 1000000000}, {"x", "y"}};
         },
         at + "/targetAliases/viseme_aa", true});
    return cases;
}

// Every common case and `meshCases` on `glb` (the base, or another version of it).
void expectHostileCases(const std::string& glb, const HostileBase& base,
                        const std::vector<Hostile>& meshCases) {
    std::vector<Hostile> cases = hostileCommonCases(base);
    cases.insert(cases.end(), meshCases.begin(), meshCases.end());
    for (const Hostile& h : cases) {
        const std::string edited = test::editGlb(glb, h.edit);
        AvatarScan scan;
        ASSERT_NO_THROW(scan = test::scanGlb(edited)) << h.what;
        EXPECT_EQ(scan.own.recognised, h.recognised) << h.what;
        EXPECT_LE(scan.own.notes.size(), 14u) << h.what;
        std::string notes;
        for (const std::string& n : scan.own.notes) notes += n + "\n";
        EXPECT_NE(notes.find(h.note), std::string::npos) << h.what << ":\n" << notes;
        const std::string report = formatAvatarReport(scan);
        EXPECT_NE(report.find(h.note), std::string::npos) << h.what;
        EXPECT_NO_THROW(avatarReportJson(scan).dump()) << h.what;
    }
}

TEST(OwnOutput, HostileExtrasAreIgnoredWithANoteNamingTheElementNeverACrash) {
    const HostileBase base = hostileBase();
    const std::string& at = base.headExtras;
    expectHostileCases(
        base.glb, base,
        {{"targets out of range",
          [&](Json& j) {
              base.headJson(j)["extras"]["visemeKeys"][0] = Json::array({999, -1, "a"});
          },
          at + "/visemeKeys/0: not a target", true},
         {"an entry that is no array", [&](Json& j) { base.headJson(j)["extras"]["visemeKeys"][1] = "x"; },
          at + "/visemeKeys/1", true},
         {"more entries than keys",
          [&](Json& j) {
              for (int i = 0; i < 100000; ++i) base.headJson(j)["extras"]["visemeKeys"].push_back({0});
          },
          at + "/visemeKeys/4", true},
         {"aliases not an object", [&](Json& j) { base.headJson(j)["extras"]["targetAliases"] = 3; },
          at + "/targetAliases: not an object", true},
         {"targetNames of the wrong type",
          [&](Json& j) {
              base.headJson(j)["extras"]["targetNames"] = Json::array({1, nullptr});
          },
          "", true}});
}

TEST(OwnOutput, HostileVersion1ExtrasAreIgnoredWithANoteToo) {
    const HostileBase base = hostileBase();
    const std::string& at = base.headExtras;
    expectHostileCases(
        test::withKeyTableVersion1(base.glb), base,
        {{"targets out of range",
          [&](Json& j) {
              base.headJson(j)["extras"]["visemeKeys"][0]["targets"] = Json::array({999, -1, "a"});
          },
          at + "/visemeKeys/0/targets", true},
         {"key index out of range", [&](Json& j) { base.headJson(j)["extras"]["visemeKeys"][1]["key"] = 99; },
          at + "/visemeKeys/1", true}});
}

// A file VisemeLab wrote before key table version 2 reads as the same reduction, in both name modes.
TEST(OwnOutput, Version1FilesReadAsTheirVersion2Equivalents) {
    for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
        const std::string v2 = reduceGlb(test::rpmLikeAvatar(), 5, names).glb;
        const std::string v1 = test::withKeyTableVersion1(v2);
        const AvatarScan a = test::scanGlb(v2), b = test::scanGlb(v1);
        ASSERT_TRUE(a.own.recognised && b.own.recognised) << toString(names);
        EXPECT_TRUE(b.own.notes.empty()) << b.own.notes.front();
        EXPECT_EQ(a.own.version, 2);
        EXPECT_EQ(b.own.version, 1);
        EXPECT_EQ(a.own.mergedNames, b.own.mergedNames);
        EXPECT_EQ(a.visemes, b.visemes);
        EXPECT_EQ(a.own.resting, b.own.resting);
        ASSERT_EQ(a.own.keys.size(), b.own.keys.size());
        for (std::size_t k = 0; k < a.own.keys.size(); ++k) {
            EXPECT_EQ(a.own.keys[k].name, b.own.keys[k].name);
            EXPECT_EQ(a.own.keys[k].members, b.own.keys[k].members);
            EXPECT_EQ(a.own.keys[k].frequency, b.own.keys[k].frequency);
        }
        ASSERT_EQ(a.own.meshes.size(), b.own.meshes.size());
        for (std::size_t m = 0; m < a.own.meshes.size(); ++m) {
            EXPECT_EQ(a.own.meshes[m].mesh, b.own.meshes[m].mesh);
            EXPECT_EQ(a.own.meshes[m].keyTargets, b.own.meshes[m].keyTargets);
            for (const auto& [name, target] : b.own.meshes[m].aliases)
                EXPECT_EQ(a.own.meshes[m].aliases.count(name) ? a.own.meshes[m].aliases.at(name) : -1, target)
                    << toString(names) << " mesh " << a.own.meshes[m].mesh << " " << name;
        }
        EXPECT_EQ(formatAvatarReport(a).find("extras.visemelab:"), std::string::npos)
            << formatAvatarReport(a);
    }
}

// Frequencies are written to 4 significant digits, names only where they are not the members joined.
TEST(OwnOutput, TheRootTableIsCompact) {
    const Written w = reduceGlb(test::rpmLikeAvatar(), 5, AvatarNames::Original);
    const Json root = test::glbJson(w.glb)["extras"]["visemelab"];
    const ReducedModel& model = w.reduction.outcome.model;
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        EXPECT_FALSE(root["keys"][k].contains("name")); // original names: the members joined with '+'
        EXPECT_NEAR(root["keys"][k]["frequency"].get<double>(), model.keys[k].frequency,
                    model.keys[k].frequency * 5e-4);
        EXPECT_LE(root["keys"][k]["frequency"].dump().size(), 9u) << root["keys"][k]["frequency"].dump();
    }
    EXPECT_FALSE(root.contains("meshes")); // each mesh's visemeKeys say which meshes carry keys
}

} // namespace
} // namespace vl
