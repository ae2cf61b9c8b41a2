#include "core/import/VisemeFile.h"
#include "core/common/Error.h"
#include "core/common/Limits.h"
#include "core/face/BundledFace.h"

#include <gtest/gtest.h>

#include <string>

namespace vl {
namespace {

const DeformationCascade& face() {
    static const DeformationCascade bundled = face::makeBundledFace();
    return bundled;
}

// The message of the InputError parsing `text` throws ("" when it loads).
std::string errorOf(const std::string& text) {
    try {
        parseVisemeFile(text, "mine.json", face());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(VisemeFile, ReadsNamesAndParameterValuesIgnoringOtherKeys) {
    const auto visemes = parseVisemeFile(
        R"({"face": "bundled", "visemes": [{"name": "open", "file": "open.obj", "parameters": {"jaw_open": 0.5}},
                                           {"name": "rest"}]})",
        "mine.json", face());
    ASSERT_EQ(visemes.size(), 2u);
    EXPECT_EQ(visemes[0].name, "open");
    ASSERT_EQ(visemes[0].values.size(), 1u);
    EXPECT_EQ(visemes[0].values[0], (std::pair<std::string, double>("jaw_open", 0.5)));
    EXPECT_TRUE(visemes[1].values.empty());
}

TEST(VisemeFile, ErrorsNameTheFileAndTheJsonPath) {
    EXPECT_NE(errorOf(R"({"visemes": [{"name": "a", "parameters": {"jaw": 1}}]})")
                  .find("mine.json:/visemes/0/parameters/jaw: unknown parameter 'jaw'"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"visemes": [{"name": "a"}, {"name": "b", "parameters": {"jaw_open": 1e999}}]})")
                  .find("mine.json"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"visemes": [{"name": "a", "parameters": {"jaw_open": 2}}]})")
                  .find("mine.json:/visemes/0/parameters/jaw_open: value 2 is outside [0, 1]"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"visemes": [{"name": "a"}, {"name": "a"}]})").find("mine.json:/visemes/1/name"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"visemes": [{"name": "a", "colour": 1}]})").find("mine.json:/visemes/0"),
              std::string::npos);
    EXPECT_NE(errorOf(R"([1, 2])").find("mine.json"), std::string::npos);
}

TEST(VisemeFile, RefusesNamesThatAreNotFileNames) {
    for (const char* name : {"../up", "a/b", "neutral", "a b", ""})
        EXPECT_NE(errorOf(std::string(R"({"visemes": [{"name": ")") + name + R"("}]})")
                      .find("mine.json:/visemes/0/name"),
                  std::string::npos)
            << name;
}

TEST(VisemeFile, RefusesHostileSizesBeforeBuildingAnything) {
    std::string many = R"({"visemes": [)";
    for (std::size_t k = 0; k <= limits::kMaxVisemes; ++k) many += (k ? ",{}" : "{}");
    many += "]}";
    EXPECT_NE(errorOf(many).find("too many visemes"), std::string::npos);
    const std::string deep = R"({"visemes": )" + std::string(100000, '[') + std::string(100000, ']') + "}";
    EXPECT_NE(errorOf(deep).find("mine.json"), std::string::npos);
}

} // namespace
} // namespace vl
