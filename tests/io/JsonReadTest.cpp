// The strict JSON layer: JSON paths in messages, duplicate keys, number checks, stable formatting.
#include "tests/project/ProjectTestUtil.h"

#include "core/io/JsonRead.h"
#include "core/io/JsonWrite.h"

namespace vl {
namespace {

TEST(JsonRead, DuplicateKeysAreReportedWithTheirPath) {
    EXPECT_INPUT_ERROR(parseJsonStrict(R"({"a": 1, "a": 2})", "f.json"), "f.json: /a: duplicate key \"a\"");
    EXPECT_INPUT_ERROR(parseJsonStrict(R"({"list": [{"x": 1}, [], {"y": 2, "y": 3}]})", "f.json"),
                       "/list/2/y: duplicate key");
    EXPECT_INPUT_ERROR(parseJsonStrict(R"({"o": {"k": [1, 2, {"a/b~": 0, "a/b~": 1}]}})", "f.json"),
                       "/o/k/2/a~1b~0: duplicate key");
    // The same key in different objects is fine.
    EXPECT_NO_THROW(
        parseJsonStrict(R"({"a": {"x": 1}, "b": {"x": 1}, "c": [{"x": 1}, {"x": 2}]})", "f.json"));
}

TEST(JsonRead, SyntaxErrorsNameTheFileAndPosition) {
    EXPECT_INPUT_ERROR(parseJsonStrict("{\"a\": NaN}", "f.json"),
                       "f.json: invalid JSON: parse error at line 1");
    EXPECT_INPUT_ERROR(parseJsonStrict("{\n\"a\": 1,\n}", "f.json"), "line 3");
    EXPECT_INPUT_ERROR(parseJsonStrict("", "f.json"), "f.json: invalid JSON");
}

TEST(JsonRead, NumbersAreCheckedStrictly) {
    const Json doc =
        parseJsonStrict(R"({"neg": -1, "frac": 2.5, "str": "3", "int": 7, "u": 18446744073709551615})", "f");
    const JsonNode root(doc, "");
    EXPECT_INPUT_ERROR(parseJsonStrict(R"({"a": {"b": [0, -1e999]}})", "f"),
                       "f: /a/b/1: number out of range: -1e999");
    EXPECT_INPUT_ERROR(parseJsonStrict(R"({"a": 1, "big": 1e999})", "f"),
                       "f: /big: number out of range: 1e999");
    EXPECT_INPUT_ERROR(root["neg"].nonNegativeNumber(), "/neg: expected a non-negative number, found -1");
    EXPECT_INPUT_ERROR(root["frac"].integer(), "/frac: expected an integer, found 2.5");
    EXPECT_INPUT_ERROR(root["str"].number(), "/str: expected a number, found string \"3\"");
    EXPECT_INPUT_ERROR(root["int"].integerInRange(1, 5), "/int: 7 is outside the allowed range 1..5");
    EXPECT_INPUT_ERROR(root["u"].integer(), "/u: integer out of range");
    EXPECT_INPUT_ERROR(root["missing"], "/missing: missing field");
    EXPECT_INPUT_ERROR(root.allowOnly({"neg"}), "/frac: unknown field");
    EXPECT_EQ(root["int"].integer(), 7);
    EXPECT_EQ(root["frac"].number(), 2.5);
}

TEST(JsonWrite, PrettyFormatIsStableAndExact) {
    const Json doc = parseJsonStrict(
        R"({"s": "x\"y", "flat": [1, 2.5, -0.0, true, null], "nested": [[0.1, 0.2], [3, 4]], "e": [], "o": {}})",
        "f");
    const std::string text = formatJsonPretty(doc);
    EXPECT_EQ(
        text,
        "{\n  \"s\": \"x\\\"y\",\n  \"flat\": [1, 2.5, -0.0, true, null],\n  \"nested\": [\n    [0.1, 0.2],\n"
        "    [3, 4]\n  ],\n  \"e\": [],\n  \"o\": {}\n}\n");
    EXPECT_EQ(formatJsonPretty(parseJsonStrict(text, "f")), text);
}

TEST(JsonWrite, CompactTextIsTheOneLineDumpOfThePrettyText) {
    // Spaces, escaped quotes and backslashes inside strings stay; every layout character outside goes.
    const std::string pretty = formatJsonPretty(parseJsonStrict(
        R"({"text": "a \"quoted\" word,\tand a\\ back slash \n", "list": [1.5, -2, 3e-07],
            "nested": {"empty": [], "o": {}, "s": " { [ , ] } "}, "unicode": "\u00e9 caf\u00e9"})",
        "f.json"));
    ASSERT_NE(pretty.find('\n'), std::string::npos);
    const std::string compact = compactJsonText(pretty);
    EXPECT_EQ(compact.find('\n'), std::string::npos);
    EXPECT_EQ(compact, nlohmann::ordered_json::parse(pretty).dump()); // members in the text's order
    EXPECT_EQ(nlohmann::ordered_json::parse(compact), nlohmann::ordered_json::parse(pretty));
}

} // namespace
} // namespace vl
