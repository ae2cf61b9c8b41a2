#include "core/gltf/TargetNames.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(TargetNames, OculusVisemesInEveryConventionTheToolsWrite) {
    EXPECT_EQ(oculusVisemeOf("viseme_aa"), "aa");
    EXPECT_EQ(oculusVisemeOf("VISEME_AA"), "aa");
    EXPECT_EQ(oculusVisemeOf("aa"), "aa");
    EXPECT_EQ(oculusVisemeOf("viseme_sil"), "sil");
    EXPECT_EQ(oculusVisemeOf("viseme_PP"), "PP");
    EXPECT_EQ(oculusVisemeOf("kk"), "kk");
    // Ready Player Me / TalkingHead spell ih, oh, ou as I, O, U.
    EXPECT_EQ(oculusVisemeOf("viseme_I"), "ih");
    EXPECT_EQ(oculusVisemeOf("viseme_O"), "oh");
    EXPECT_EQ(oculusVisemeOf("viseme_U"), "ou");
    EXPECT_EQ(oculusVisemeOf("viseme_ih"), "ih");
    EXPECT_EQ(oculusVisemeOf("OU"), "ou");
    EXPECT_EQ(oculusVisemeOf("e"), "E");
    for (const char* other : {"jawOpen", "viseme_", "viseme_X", "mouthSmile", "Fcl_MTH_A", "", "visemeaa"})
        EXPECT_FALSE(oculusVisemeOf(other)) << other;
    EXPECT_EQ(oculusVisemeNames().size(), 15u);
    for (const std::string& name : oculusVisemeNames()) EXPECT_EQ(oculusVisemeOf(name), name);
}

TEST(TargetNames, GlobMatchesWholeNamesWithoutRegardToCase) {
    EXPECT_TRUE(globMatch("Fcl_MTH_[AIUEO]", "Fcl_MTH_A"));
    EXPECT_TRUE(globMatch("Fcl_MTH_[AIUEO]", "fcl_mth_o"));
    EXPECT_FALSE(globMatch("Fcl_MTH_[AIUEO]", "Fcl_MTH_Close"));
    EXPECT_FALSE(globMatch("Fcl_MTH_[AIUEO]", "Fcl_MTH_"));
    EXPECT_TRUE(globMatch("viseme_*", "viseme_"));
    EXPECT_TRUE(globMatch("viseme_*", "viseme_aa"));
    EXPECT_FALSE(globMatch("viseme_*", "xviseme_aa"));
    EXPECT_TRUE(globMatch("*_?", "V_A"));
    EXPECT_FALSE(globMatch("*_?", "V_AB"));
    EXPECT_TRUE(globMatch("*a*b*c", "xxaYYbZZc"));
    EXPECT_FALSE(globMatch("*a*b*c", "xxaYYbZZcd"));
    EXPECT_TRUE(globMatch("[a-c]x", "Bx"));
    EXPECT_FALSE(globMatch("[!a-c]x", "bx"));
    EXPECT_TRUE(globMatch("[!a-c]x", "dx"));
    EXPECT_TRUE(globMatch("[]]", "]"));
    EXPECT_TRUE(globMatch("*", ""));
    // Worst case stays fast: no exponential backtracking.
    EXPECT_FALSE(globMatch("*a*a*a*a*a*a*a*a*b", std::string(5000, 'a')));
}

TEST(TargetNames, BadPatternsAreNamed) {
    test::expectInputError([] { checkGlobPattern("Fcl_[AIUEO", "--targets"); },
                           {"--targets", "unterminated"});
    test::expectInputError([] { checkGlobPattern("", "--targets"); }, {"--targets", "empty"});
    EXPECT_NO_THROW(checkGlobPattern("Fcl_MTH_[AIUEO]", "--targets"));
}

} // namespace
} // namespace vl
