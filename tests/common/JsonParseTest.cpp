// The JSON limits every JSON reader relies on: nesting depth checked before a document is built,
// overflowing numbers refused, both naming the file and the JSON path.
#include "core/common/JsonParse.h"
#include "core/common/Error.h"
#include "core/common/Limits.h"

#include <gtest/gtest.h>

#include <string>

namespace vl {
namespace {

std::string errorOf(std::string_view text, std::string_view source = "deep.json") {
    try {
        parseJsonStrict(text, source);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

std::string nestedArrays(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

TEST(JsonParse, NestingUpToTheLimitIsAccepted) {
    EXPECT_NO_THROW(parseJsonStrict(nestedArrays(limits::kMaxJsonDepth), "f.json"));
    EXPECT_NO_THROW(parseJsonStrict(R"({"a": [{"b": {"c": []}}], "d": "[[[[{{{{"})", "f.json"));
}

TEST(JsonParse, DeepNestingIsRefusedWithThePathBeforeParsing) {
    // A million levels overflowed the stack of every JSON reader before the limit existed.
    const std::string message = errorOf(nestedArrays(1'000'000));
    EXPECT_EQ(message.find("deep.json: /0/0/0/"), 0u) << message;
    EXPECT_NE(
        message.find("JSON nested deeper than " + std::to_string(limits::kMaxJsonDepth) + " levels (line 1)"),
        std::string::npos)
        << message;

    std::string objects = "{\n\"keep\": 1,\n\"x\": ";
    for (std::size_t i = 0; i < 100; ++i) objects += "{\"k/" + std::to_string(i) + "\": [0, ";
    EXPECT_NE(errorOf(objects, "o.json").find("o.json: /x/k~10/1/k~11/1/k~12/1/"), std::string::npos)
        << errorOf(objects, "o.json");
    EXPECT_NE(errorOf(objects, "o.json").find("(line 3)"), std::string::npos);
}

TEST(JsonParse, BracketsInsideStringsDoNotCount) {
    const std::string text = "[\"" + std::string(1000, '[') + "\\\"" + std::string(1000, '{') + "\"]";
    EXPECT_NO_THROW(parseJsonStrict(text, "s.json"));
}

TEST(JsonParse, MalformedTextIsLeftToTheParser) {
    EXPECT_NE(errorOf("[\"unterminated", "m.json").find("m.json: invalid JSON"), std::string::npos);
    EXPECT_NE(errorOf("]]]]{", "m.json").find("m.json: invalid JSON"), std::string::npos);
}

TEST(JsonParse, OverflowingNumbersAreDataErrorsWithTheirPath) {
    EXPECT_EQ(errorOf(R"({"w": [1, 1e999]})", "w.json"), "w.json: /w/1: number out of range: 1e999");
    EXPECT_EQ(errorOf(R"([-1e400])", "w.json"), "w.json: /0: number out of range: -1e400");
}

} // namespace
} // namespace vl
