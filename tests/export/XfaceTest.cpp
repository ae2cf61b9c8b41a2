#include "core/export/Xface.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/import/XfaceImport.h"
#include "tests/export/TestModels.h"
#include "tests/io/MeshIOTestUtil.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

const std::filesystem::path kAlice =
    std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) / "xface-alice" / "alice.fdp";

TEST(Xface, DictionaryPausesShowTheKeySilenceWasMergedInto) {
    ReducedModel model = test::randomModel(4, 4, 3, false, 82);
    model.phonemeToKey.emplace_back("sil", 1);
    const PhonemeVisemeMap dic = parseXfaceDictionary(formatXfaceDictionary(model), "face.dic");
    const std::vector<std::string> aliases = xfaceAliases(model);
    ASSERT_GE(dic.entries.size(), 2u);
    EXPECT_EQ(*dic.visemeOf("#"), aliases[1]);
    EXPECT_EQ(*dic.visemeOf("_"), aliases[1]);
    // A map that already names a pause phoneme keeps its own line.
    model.phonemeToKey.emplace_back("#", 2);
    const PhonemeVisemeMap own = parseXfaceDictionary(formatXfaceDictionary(model), "face.dic");
    EXPECT_EQ(*own.visemeOf("#"), aliases[2]);
    EXPECT_EQ(*own.visemeOf("_"), aliases[1]);
}

TEST(Xface, ExportThenImportRoundTrips) {
    ReducedModel model = test::randomModel(6, 5, 3, true, 81);
    model.keys[2].name = "oh ooh"; // white space is not allowed in an alias
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_xface_test";
    std::filesystem::remove_all(dir);
    const auto files = writeXfaceFace(dir, model, "face");
    EXPECT_EQ(files.back(), "face.dic");
    EXPECT_EQ(files[files.size() - 2], "face.fdp");
    EXPECT_TRUE(std::filesystem::exists(dir / "reduced_0_key0.wrl"));

    const XfaceFace face = loadXfaceFace(dir / "face.fdp");
    // Key meshes are written as float32 (docs/export.md).
    test::expectSameFloat32Positions(model.neutral.positions, face.set.neutral.positions);
    EXPECT_EQ(face.set.neutral.triangles, model.neutral.triangles);
    ASSERT_EQ(face.set.visemes.size(), 3u);
    EXPECT_EQ(face.set.visemes[0].name, "key0");
    EXPECT_EQ(face.set.visemes[1].name, "key1+m1");
    EXPECT_EQ(face.set.visemes[2].name, "oh_ooh");
    for (std::size_t k = 0; k < 3; ++k)
        test::expectSameFloat32Positions(model.keys[k].positions, face.set.visemes[k].positions);
    // Every phoneme maps to the alias of its merged viseme; pauses (# and _) show the neutral face.
    // (the pauses the .dic shows with the neutral are listed apart: they are not visemes).
    ASSERT_EQ(face.dictionary.entries.size(), model.phonemeToKey.size());
    EXPECT_EQ(face.restPhonemes, (std::vector<std::string>{"#", "_"}));
    for (std::size_t p = 0; p < model.phonemeToKey.size(); ++p) {
        EXPECT_EQ(face.dictionary.entries[p].first, model.phonemeToKey[p].first);
        EXPECT_EQ(face.dictionary.entries[p].second,
                  face.set.visemes[static_cast<std::size_t>(model.phonemeToKey[p].second)].name);
    }
    const FdpDocument doc = parseFdp(readFileToString(dir / "face.fdp"), "face.fdp");
    EXPECT_EQ(doc.fileVersion, "0.2");
    ASSERT_EQ(doc.entities.size(), 4u);
    EXPECT_EQ(doc.entities[0].alias, "Rest");
    EXPECT_EQ(doc.entities[0].category, "Expression");
    EXPECT_EQ(doc.entities[1].category, "Viseme");
    EXPECT_EQ(doc.entities[1].meshFormats[0], "wrl");
    std::filesystem::remove_all(dir);
}

TEST(Xface, ParsesAliceEntitiesAndAliases) {
    if (!std::filesystem::exists(kAlice)) GTEST_SKIP() << "shared data not present: " << kAlice;
    const FdpDocument doc = parseFdp(readFileToString(kAlice), kAlice.string());
    EXPECT_EQ(doc.fileVersion, "0.2");
    ASSERT_EQ(doc.fapu.size(), 5u);
    EXPECT_EQ(doc.fapu[1], (std::pair<std::string, double>{"ES0", 69}));
    ASSERT_EQ(doc.entities.size(), 29u);
    std::vector<std::string> visemes;
    for (const FdpEntity& e : doc.entities)
        if (e.category == "Viseme") visemes.push_back(e.alias);
    const std::vector<std::string> expected{"aah", "b", "bigaah", "ch", "d", "ee", "eh", "f",
                                            "i",   "k", "n",      "oh", "q", "r",  "th", "w"};
    EXPECT_EQ(visemes, expected);
    const FdpEntity& rest = doc.entities[3];
    EXPECT_EQ(rest.alias, "Rest");
    EXPECT_EQ(rest.meshFiles, std::vector<std::string>{"alice.wrl"});
    EXPECT_EQ(rest.line, 31);
    EXPECT_EQ(doc.entities[14].meshFiles[0], "alice_PhonemeB,M,P.wrl");
}

TEST(Xface, ImportOfAliceReportsTheMissingVrml) {
    if (!std::filesystem::exists(kAlice)) GTEST_SKIP() << "shared data not present: " << kAlice;
    try {
        loadXfaceFace(kAlice);
        FAIL() << "alice's VRML meshes are not shipped; the import must fail";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("alice.fdp:31: entity 'Rest': mesh file 'alice.wrl' not found"),
                  std::string::npos)
            << message;
    }
}

TEST(Xface, MalformedFdpNamesTheLine) {
    try {
        parseFdp("<?xml version=\"1.0\"?>\n<xfdp>\n<source>\n<entity alias=\"x\">\n</source>\n", "bad.fdp");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.fdp:"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseFdp("<other/>", "x.fdp"), InputError);
    try {
        parseFdp("<xfdp>\n<source>\n<entity alias=\"a\" category=\"Viseme\"/>\n</source></xfdp>",
                 "nomesh.fdp");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("nomesh.fdp:3: entity 'a' has no <mesh>"), std::string::npos)
            << e.what();
    }
}

TEST(Xface, DictionaryInXfaceFormat) {
    // As Xface's own italian.dic: the language, then "phoneme viseme"; '#' is a phoneme (pause).
    std::string language;
    const PhonemeVisemeMap map = parseXfaceDictionary("italian\n# Rest\nE1 ee\n\nm b\n", "it.dic", &language);
    EXPECT_EQ(language, "italian");
    ASSERT_EQ(map.entries.size(), 3u);
    EXPECT_EQ(*map.visemeOf("#"), "Rest");
    EXPECT_EQ(*map.visemeOf("m"), "b");
    EXPECT_THROW(parseXfaceDictionary("english\na b c\n", "x.dic"), InputError);
    EXPECT_THROW(parseXfaceDictionary("english\na b\na c\n", "x.dic"), InputError);
    EXPECT_THROW(parseXfaceDictionary("", "x.dic"), InputError);
}

TEST(Xface, DictionaryOfOnlyAByteOrderMarkIsRejected) {
    const auto errorOf = [](std::string_view text) {
        try {
            parseXfaceDictionary(text, "bom.dic");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // Was accepted: the mark became the language and the dictionary was empty.
    EXPECT_EQ(errorOf("\xEF\xBB\xBF"), "bom.dic: empty phoneme dictionary");
    EXPECT_EQ(errorOf("\xEF\xBB\xBF\n\n"), "bom.dic: empty phoneme dictionary");
    EXPECT_EQ(errorOf("english\n"), "bom.dic: no 'phoneme viseme' lines after the language line");
    std::string language;
    const PhonemeVisemeMap map = parseXfaceDictionary("\xEF\xBB\xBF"
                                                      "english\nAA aa\n",
                                                      "bom.dic", &language);
    EXPECT_EQ(language, "english");
    EXPECT_EQ(map.entries.size(), 1u);
}

} // namespace
} // namespace vl
