#include "tests/cli/CliRunner.h"
#include "tests/phonetics/PhoneticsTestSupport.h"

#include "core/common/AtomicFile.h"
#include "core/io/MeshIO.h"
#include "core/phonetics/PhonemeTableIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace vl;

namespace {

std::string quoted(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

} // namespace

TEST(FreqCli, PrintsAndWritesTheTable) {
    test::PhoneticsScratch dir("cli");
    const auto corpus =
        dir.write("corpus.txt", "The cat sat on the mat.\nA boy sings; the judge measures the house.\n");
    const auto csv = dir.path() / "table.csv";
    const auto result = test::runCli("freq " + quoted(corpus) + " --out " + quoted(csv));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("AH       ʌ              6    15.00 %"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("sil      sil            3     7.50 %"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("40 phonemes"), std::string::npos) << result.output;
    const auto table = loadPhonemeTable(csv);
    ASSERT_EQ(table.entries.size(), 40u);
    EXPECT_EQ(table.entries[0], (std::pair<std::string, double>{"AH", 6}));
}

TEST(FreqCli, JsonWithMapFeedsTheReducer) {
    test::PhoneticsScratch dir("cli-json");
    const auto corpus = dir.write("corpus.txt", "Four poor fire fighters came at noon.");
    const auto json = dir.path() / "table.json";
    const auto map = test::assetsDir() / "phonemes" / "map_oculus.csv";
    const auto result = test::runCli("freq " + quoted(corpus) + " --voice en-us --quiet --map " +
                                     quoted(map) + " --out " + quoted(json));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const FrequencySource source = loadFrequencyFile(json);
    ASSERT_TRUE(source.isPhonemeBased());
    EXPECT_EQ(source.map.entries.size(), 40u);
    EXPECT_EQ(nlohmann::json::parse(readFileToString(json))["voice"], "en-us");
}

TEST(FreqCli, BadInputGetsExitCodesAndNamesTheFile) {
    test::PhoneticsScratch dir("cli-bad");
    const auto empty = dir.write("empty.txt", "");
    auto result = test::runCli("freq " + quoted(empty));
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_NE(result.output.find("empty.txt: empty file"), std::string::npos) << result.output;

    const auto binary = dir.write("blob.bin", std::string("\x7F"
                                                          "ELF\x02\x01\x01\0\0\0\0\0\0\0\0\0",
                                                          16));
    result = test::runCli("freq " + quoted(binary));
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_NE(result.output.find("blob.bin: binary file"), std::string::npos) << result.output;

    const auto corpus = dir.write("ok.txt", "hello world");
    result = test::runCli("freq " + quoted(corpus) + " --voice xx-none");
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_NE(result.output.find("xx-none"), std::string::npos) << result.output;

    const auto map = test::assetsDir() / "phonemes" / "map_oculus.csv";
    result = test::runCli("freq " + quoted(corpus) + " --map " + quoted(map) + " --out " +
                          quoted(dir.path() / "t.csv"));
    EXPECT_EQ(result.exitCode, 2) << result.output;

    result = test::runCli("freq");
    EXPECT_EQ(result.exitCode, 2) << result.output;
}

// The whole flow of the issue: bundled phoneme table + bundled map -> viseme frequencies -> reduction.
TEST(FreqCli, ReduceTakesTheBundledTablePlusMap) {
    test::PhoneticsScratch dir("cli-reduce");
    const std::vector<std::string> oculus = {"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                             "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};
    auto quad = [](double lift) {
        MeshData mesh;
        mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, lift), Vec3(0, 1, 0)};
        mesh.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
        return mesh;
    };
    const auto visemes = dir.path() / "visemes";
    std::filesystem::create_directories(visemes);
    writeMesh(visemes / "neutral.obj", quad(0));
    for (std::size_t i = 0; i < oculus.size(); ++i)
        writeMesh(visemes / (oculus[i] + ".obj"), quad(0.1 * double(i)));
    const auto phonemes = test::assetsDir() / "phonemes";
    const auto out = dir.path() / "out";
    const auto result = test::runCli(
        "reduce --visemes " + quoted(visemes) + " --freq-file " + quoted(phonemes / "en-us_frequencies.csv") +
        " --map " + quoted(phonemes / "map_oculus.csv") + " --target 4 --out " + quoted(out));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const auto mapping = nlohmann::json::parse(readFileToString(out / "mapping.json"));
    ASSERT_TRUE(mapping.contains("phonemes")) << mapping.dump();
    EXPECT_EQ(mapping["phonemes"].size(), 40u);
}
