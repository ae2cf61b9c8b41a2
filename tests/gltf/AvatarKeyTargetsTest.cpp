// Which target carries which key, read back from a reduced avatar in both name modes.
#include "core/gltf/AvatarKeyTargets.h"
#include "core/common/Error.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/MergedNames.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/KeyTableVersion1.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

AvatarReduction reduced(AvatarNames names) {
    const std::string glb = test::rpmLikeAvatar();
    const GltfDocument doc = parseGltfDocument(glb, "in.glb", {});
    const AvatarScan scan = scanAvatar(doc, {});
    FrequencySource frequencies;
    for (std::size_t i = 0; i < scan.visemes.size(); ++i)
        frequencies.visemeFrequencies.entries.emplace_back(scan.visemes[i], 1.0 + static_cast<double>(i % 3));
    ReduceSettings settings;
    settings.target = 4;
    settings.rest = RestChoice::Free;
    AvatarWriteOptions write;
    write.names = names;
    return reduceAvatar(doc, scan, frequencies, settings, write);
}

std::string joined(const std::vector<std::string>& names, const std::string& before,
                   const std::string& between) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? before : between) + name + "'";
    return text;
}

TEST(AvatarKeyTargets, OriginalNamesListEveryMembersTargetOnTheHeadAndTeeth) {
    const AvatarReduction r = reduced(AvatarNames::Original);
    const auto keys = avatarKeyTargets(r.glb, "out.glb");
    const auto& model = r.outcome.model;
    ASSERT_EQ(keys.size(), model.keys.size());
    const auto lines = formatAvatarKeyTargets(keys);
    for (std::size_t g = 0; g < keys.size(); ++g) {
        EXPECT_EQ(keys[g].key, static_cast<int>(g));
        EXPECT_EQ(keys[g].name, model.keys[g].name);
        // Every member keeps its target, which now holds the key.
        const std::string targets = joined(model.keys[g].members, "'", ", '");
        EXPECT_EQ(lines[g].rfind("key " + std::to_string(g) + " (" + model.keys[g].name + "): target", 0), 0u)
            << lines[g];
        EXPECT_NE(lines[g].find(targets + " on "), std::string::npos) << lines[g];
        EXPECT_NE(lines[g].find("Wolf3D_Head"), std::string::npos) << lines[g];
    }
}

TEST(AvatarKeyTargets, MergedNamesGiveOneTargetPerKeyNamedByItsMembers) {
    const AvatarReduction r = reduced(AvatarNames::Merged);
    const auto lines = formatAvatarKeyTargets(avatarKeyTargets(r.glb, "out.glb"));
    const auto& model = r.outcome.model;
    ASSERT_EQ(lines.size(), model.keys.size());
    std::vector<std::vector<std::string>> members;
    for (const KeyMesh& key : model.keys) members.push_back(key.members);
    const std::vector<std::string> targetNames = mergedTargetNames(members, {});
    bool merged = false;
    for (std::size_t g = 0; g < lines.size(); ++g) {
        // The target is named by the merged-name rule (core/gltf/MergedNames), within 63 bytes.
        EXPECT_NE(lines[g].find(": target '" + targetNames[g] + "' on "), std::string::npos) << lines[g];
        EXPECT_NE(lines[g].find("Wolf3D_Head"), std::string::npos) << lines[g];
        merged = merged || model.keys[g].members.size() > 1;
    }
    EXPECT_TRUE(merged); // some key has several members, so its name is a '+' join
}

// A file of key table version 1 (every mesh repeating the table) lists the same.
TEST(AvatarKeyTargets, Version1FilesListTheSame) {
    for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
        const AvatarReduction r = reduced(names);
        EXPECT_EQ(formatAvatarKeyTargets(avatarKeyTargets(test::withKeyTableVersion1(r.glb), "v1.glb")),
                  formatAvatarKeyTargets(avatarKeyTargets(r.glb, "v2.glb")))
            << toString(names);
    }
}

TEST(AvatarKeyTargets, BytesThatAreNoGlbAreRefusedNamingTheSource) {
    try {
        avatarKeyTargets("not a glb at all", "out.glb");
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("out.glb"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace vl
