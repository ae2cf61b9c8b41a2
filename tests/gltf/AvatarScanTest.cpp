#include "core/gltf/AvatarScan.h"
#include "core/gltf/AvatarReport.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace vl {
namespace {

using test::FixtureStorage;

std::string fixture(FixtureStorage storage) {
    test::AvatarFixtureOptions options;
    options.storage = storage;
    return test::rpmLikeAvatar(options);
}

const AvatarMesh& meshNamed(const AvatarScan& scan, const std::string& name) {
    for (const AvatarMesh& m : scan.meshes)
        if (m.name == name) return m;
    throw std::runtime_error("no mesh " + name);
}

// The vertices of one mesh inside the concatenated set.
std::vector<Vec3> meshVertices(const AvatarScan& scan, const std::string& name,
                               const std::vector<Vec3>& positions) {
    const AvatarMesh& m = meshNamed(scan, name);
    std::vector<Vec3> out;
    for (const AvatarPrimitive& p : m.primitives)
        out.insert(out.end(), positions.begin() + static_cast<long>(p.firstVertex),
                   positions.begin() + static_cast<long>(p.firstVertex + p.vertices));
    return out;
}

double energy(const AvatarScan& scan, std::size_t viseme) {
    double sum = 0;
    for (std::size_t v = 0; v < scan.set.vertexCount(); ++v)
        sum += (scan.set.visemes[viseme].positions[v] - scan.set.neutral.positions[v]).sqrnorm();
    return sum;
}

TEST(AvatarScan, ReadyPlayerMeLikeAvatarGivesOneSetOfFifteenVisemesOverFourMeshes) {
    const AvatarScan scan = test::scanGlb(fixture(FixtureStorage::Plain));
    EXPECT_EQ(scan.visemes, test::rpmVisemeNames());
    EXPECT_TRUE(scan.oculusNames);
    EXPECT_EQ(scan.visemeKeys.front(), "sil");
    EXPECT_EQ(scan.visemeKeys[12], "ih");
    ASSERT_EQ(scan.set.size(), 15u);
    std::vector<std::string> carriers;
    std::size_t vertices = 0;
    for (const AvatarMesh& m : scan.meshes)
        if (m.carriesVisemes) {
            carriers.push_back(m.name);
            for (const auto& p : m.primitives) vertices += p.vertices;
        }
    EXPECT_EQ(carriers, (std::vector<std::string>{"EyeLeft", "EyeRight", "Wolf3D_Head", "Wolf3D_Teeth"}));
    EXPECT_EQ(scan.set.vertexCount(), vertices);
    EXPECT_EQ(meshNamed(scan, "Wolf3D_Body").note, "no morph targets");
    const AvatarMesh& head = meshNamed(scan, "Wolf3D_Head");
    EXPECT_EQ(head.skin, 0);
    ASSERT_EQ(head.targets.size(), test::rpmHeadTargetNames().size());
    EXPECT_EQ(head.targets[1].name, "jawOpen");
    EXPECT_EQ(head.targets[1].viseme, -1);
    EXPECT_EQ(head.targets[1].ignored, "not an Oculus viseme name");
    EXPECT_EQ(head.targets[2].viseme, 0);
    // Every viseme but sil moves the head; eyes never move.
    for (std::size_t i = 1; i < 15; ++i) EXPECT_GT(energy(scan, i), 0.0) << scan.visemes[i];
    EXPECT_EQ(energy(scan, 0), 0.0);
    const std::string report = formatAvatarReport(scan);
    EXPECT_NE(report.find("Visemes: 15 (Oculus viseme names)"), std::string::npos) << report;
    EXPECT_NE(report.find("kept as they are (not an Oculus viseme name): browInnerUp jawOpen mouthSmileLeft"),
              std::string::npos)
        << report;
    const auto json = avatarReportJson(scan);
    EXPECT_EQ(json["meshes"][0]["name"], "Wolf3D_Body");
    EXPECT_EQ(json["meshes"][0]["carries_visemes"], false);
}

TEST(AvatarScan, EyesPlacedByMatricesUnderAScaledArmatureLandWhereTRSNodesPutThem) {
    // Plain: eyes are children of the Head joint (armature rotated 90 degrees, scaled 0.01) placed
    // by a matrix; quantised: root nodes whose TRS also dequantises. Same world positions.
    const AvatarScan plain = test::scanGlb(fixture(FixtureStorage::Plain));
    const AvatarScan quantised = test::scanGlb(fixture(FixtureStorage::Quantised));
    for (const char* eye : {"EyeLeft", "EyeRight"}) {
        const auto a = meshVertices(plain, eye, plain.set.neutral.positions);
        const auto b = meshVertices(quantised, eye, quantised.set.neutral.positions);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i)
            ASSERT_LT((a[i] - b[i]).norm(), 2e-5) << eye << " vertex " << i;
    }
    const auto eye = meshVertices(plain, "EyeLeft", plain.set.neutral.positions);
    EXPECT_GT(eye[0][0], 0.015);
    EXPECT_GT(eye[0][1], 1.6);
}

TEST(AvatarScan, SkinnedHeadIsMeasuredInTheStoredPoseByLinearBlendSkinning) {
    // The fixture's Head joint is turned 8 degrees about the vertical in the stored pose, against
    // the bind pose of its inverse bind matrices; the quantised variant is unskinned (bind pose).
    const AvatarScan plain = test::scanGlb(fixture(FixtureStorage::Plain));
    const AvatarScan bind = test::scanGlb(fixture(FixtureStorage::Quantised));
    const auto posed = meshVertices(plain, "Wolf3D_Head", plain.set.neutral.positions);
    const auto rest = meshVertices(bind, "Wolf3D_Head", bind.set.neutral.positions);
    ASSERT_EQ(posed.size(), rest.size());
    const Vec3 joint(0, 1.56, 0);
    std::size_t turned = 0;
    for (std::size_t i = 0; i < posed.size(); ++i) {
        if (rest[i][1] < 1.565) continue; // below the blend line: 0.7 Head + 0.3 Neck
        EXPECT_NEAR(posed[i][1], rest[i][1], 2e-5);
        EXPECT_NEAR((posed[i] - joint).norm(), (rest[i] - joint).norm(), 2e-5);
        const double angle = std::atan2(rest[i][0] - joint[0], rest[i][2] - joint[2]) -
                             std::atan2(posed[i][0] - joint[0], posed[i][2] - joint[2]);
        if (std::hypot(rest[i][0], rest[i][2]) > 0.02) {
            EXPECT_NEAR(std::remainder(std::abs(angle), 2 * M_PI), 8.0 * M_PI / 180.0, 1e-3) << i;
            ++turned;
        }
    }
    EXPECT_GT(turned, posed.size() / 3);
}

TEST(AvatarScan, CompressedSparseAndQuantisedStorageReadTheSameVisemes) {
    const AvatarScan plain = test::scanGlb(fixture(FixtureStorage::Plain));
    const AvatarScan sparse = test::scanGlb(fixture(FixtureStorage::Sparse));
    const AvatarScan meshopt = test::scanGlb(fixture(FixtureStorage::Meshopt));
    const AvatarScan draco = test::scanGlb(fixture(FixtureStorage::Draco));
    ASSERT_EQ(sparse.set.vertexCount(), plain.set.vertexCount());
    ASSERT_EQ(meshopt.set.vertexCount(), plain.set.vertexCount());
    ASSERT_EQ(draco.set.vertexCount(), plain.set.vertexCount());
    EXPECT_EQ(sparse.set.neutral.triangles, plain.set.neutral.triangles);
    // meshopt's index codec may rotate a triangle's corners (same winding).
    const auto rotated = [](std::vector<Triangle> ts) {
        for (Triangle& t : ts) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        return ts;
    };
    EXPECT_EQ(rotated(meshopt.set.neutral.triangles), rotated(plain.set.neutral.triangles));
    for (std::size_t i = 0; i < plain.set.size(); ++i) {
        for (std::size_t v = 0; v < plain.set.vertexCount(); ++v) {
            ASSERT_EQ(sparse.set.visemes[i].positions[v], plain.set.visemes[i].positions[v]);
            // The fixture's deltas went through meshoptimizer 0.18's 15-bit exponential filter
            // (measured: up to 0.3% of a component).
            ASSERT_LT((meshopt.set.visemes[i].positions[v] - plain.set.visemes[i].positions[v]).norm(), 5e-5);
        }
        // Draco reorders the head's vertices: compare what does not depend on order.
        EXPECT_NEAR(energy(draco, i), energy(plain, i), 1e-9 + 1e-6 * energy(plain, i)) << plain.visemes[i];
    }
    EXPECT_EQ(draco.set.neutral.triangles.size(), plain.set.neutral.triangles.size());
    const AvatarMesh& head = meshNamed(draco, "Wolf3D_Head");
    EXPECT_EQ(head.primitives[0].storage, std::vector<std::string>{"Draco"});
    EXPECT_EQ(meshNamed(meshopt, "Wolf3D_Head").primitives[0].storage, std::vector<std::string>{"meshopt"});
    EXPECT_EQ(meshNamed(sparse, "Wolf3D_Head").primitives[0].storage,
              std::vector<std::string>{"sparse targets"});
    const AvatarScan quantised = test::scanGlb(fixture(FixtureStorage::Quantised));
    EXPECT_EQ(meshNamed(quantised, "Wolf3D_Teeth").primitives[0].storage,
              std::vector<std::string>{"quantised"});
    for (std::size_t i = 1; i < 15; ++i)
        EXPECT_NEAR(energy(quantised, i), energy(plain, i), 0.02 * energy(plain, i)) << plain.visemes[i];
}

TEST(AvatarScan, VRoidMouthShapesNeedAPatternAndAreReadFromPrimitiveExtras) {
    const std::string glb = test::vroidLikeAvatar();
    const AvatarScan none = test::scanGlb(glb);
    EXPECT_TRUE(none.visemes.empty());
    EXPECT_EQ(suggestedPatterns(none), std::vector<std::string>{"Fcl_MTH_[AIUEO]"});
    EXPECT_NE(formatAvatarReport(none).find("--targets 'Fcl_MTH_[AIUEO]'"), std::string::npos);
    const AvatarScan scan = test::scanGlb(glb, "Fcl_MTH_[AIUEO]");
    EXPECT_EQ(scan.visemes,
              (std::vector<std::string>{"Fcl_MTH_A", "Fcl_MTH_I", "Fcl_MTH_U", "Fcl_MTH_E", "Fcl_MTH_O"}));
    EXPECT_FALSE(scan.oculusNames);
    const AvatarMesh& face = meshNamed(scan, "Face.baked");
    ASSERT_EQ(face.primitives.size(), 2u);
    EXPECT_EQ(scan.set.vertexCount(), face.primitives[0].vertices + face.primitives[1].vertices);
    EXPECT_EQ(face.targets[9].ignored, "does not match 'Fcl_MTH_[AIUEO]'");
    EXPECT_GT(energy(scan, 0), 0.0);
}

// ARKit blendshapes (jawOpen, mouthSmileLeft, ...) are left alone by default and become the set only
// when a pattern selects them; a shape on several meshes (jawOpen: head and teeth) is one viseme.
TEST(AvatarScan, ARKitShapesAreVisemesOnlyWhenAPatternSelectsThem) {
    const std::string glb = fixture(FixtureStorage::Plain);
    const AvatarScan scan = test::scanGlb(glb, "[jm]*");
    EXPECT_EQ(scan.visemes, (std::vector<std::string>{"jawOpen", "mouthSmileLeft", "mouthSmileRight"}));
    EXPECT_FALSE(scan.oculusNames);
    std::vector<std::string> carriers;
    for (const AvatarMesh& m : scan.meshes)
        if (m.carriesVisemes) carriers.push_back(m.name);
    EXPECT_EQ(carriers, (std::vector<std::string>{"Wolf3D_Head", "Wolf3D_Teeth"}));
    const AvatarMesh& head = meshNamed(scan, "Wolf3D_Head");
    EXPECT_EQ(head.targets[2].name, "viseme_sil");
    EXPECT_EQ(head.targets[2].ignored, "does not match '[jm]*'");
    EXPECT_EQ(head.targets[0].ignored, "does not match '[jm]*'"); // browInnerUp
    EXPECT_GT(energy(scan, 0), 0.0);
    // The teeth lack the smiles: zero displacement there, as for a viseme a mesh lacks.
    const auto teeth = meshVertices(scan, "Wolf3D_Teeth", scan.set.visemes[1].positions);
    EXPECT_EQ(teeth, meshVertices(scan, "Wolf3D_Teeth", scan.set.neutral.positions));
}

TEST(AvatarScan, VisemesJoinAcrossMeshesByMeaningNotSpelling) {
    // The teeth spell ih/oh as the Oculus SDK does, the head as Ready Player Me does.
    const std::string glb = test::editGlb(fixture(FixtureStorage::Plain), [](nlohmann::ordered_json& j) {
        for (auto& mesh : j["meshes"])
            if (mesh["name"] == "Wolf3D_Teeth")
                for (auto& name : mesh["extras"]["targetNames"]) {
                    if (name == "viseme_I") name = "ih";
                    if (name == "viseme_O") name = "OH";
                }
    });
    const AvatarScan scan = test::scanGlb(glb);
    EXPECT_EQ(scan.visemes, test::rpmVisemeNames());
    const AvatarMesh& teeth = meshNamed(scan, "Wolf3D_Teeth");
    EXPECT_EQ(teeth.targets[13].name, "ih");
    EXPECT_EQ(teeth.targets[13].viseme, 12);
    EXPECT_EQ(teeth.targets[14].viseme, 13);
}

TEST(AvatarScan, ADuplicateVisemeOnOneMeshIsReportedAndIgnored) {
    const std::string glb = test::editGlb(fixture(FixtureStorage::Plain), [](nlohmann::ordered_json& j) {
        for (auto& mesh : j["meshes"])
            if (mesh["name"] == "Wolf3D_Head")
                mesh["extras"]["targetNames"][1] = "AA"; // jawOpen -> a second aa
    });
    const AvatarScan scan = test::scanGlb(glb);
    const AvatarMesh& head = meshNamed(scan, "Wolf3D_Head");
    EXPECT_EQ(head.targets[1].viseme, 10);
    EXPECT_EQ(head.targets[12].viseme, -1);
    EXPECT_EQ(head.targets[12].ignored, "same viseme as target 1 ('AA')");
}

TEST(AvatarScan, UnnamedTargetsAreReportedAsSuch) {
    const std::string glb = test::editGlb(fixture(FixtureStorage::Plain), [](nlohmann::ordered_json& j) {
        for (auto& mesh : j["meshes"]) mesh.erase("extras");
    });
    const AvatarScan scan = test::scanGlb(glb);
    EXPECT_TRUE(scan.visemes.empty());
    EXPECT_EQ(meshNamed(scan, "Wolf3D_Head").targets[0].name, "target0");
    EXPECT_EQ(meshNamed(scan, "Wolf3D_Head").targets[0].ignored,
              "no name (the file has no extras.targetNames)");
}

} // namespace
} // namespace vl
