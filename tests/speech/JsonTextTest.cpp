// json_text::number (core/speech/JsonText.h): the track writers' fast number text against the
// reference it replaced, nlohmann's dump of a Json value.
#include "core/speech/JsonText.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

using namespace vl;

namespace {

std::string reference(double value) {
    return Json(value).dump();
}

// The double a JSON reader gets from `text`.
double parsed(const std::string& text) {
    return Json::parse(text).get<double>();
}

} // namespace

TEST(JsonText, NumbersAreLaidOutAsNlohmannDumpsThem) {
    const double values[] = {0.0,
                             -0.0,
                             1.0,
                             60.0,
                             -2.5,
                             0.1,
                             1.0 / 3,
                             1e-5,
                             1.5e-5,
                             0.0001,
                             0.001234,
                             12.34,
                             1e15,
                             1e16,
                             1.5e16,
                             123456789012345.0,
                             1e300,
                             -1e-300,
                             5e-324,
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::min(),
                             0.016666666666666666,
                             2.75139e-05};
    for (const double value : values) EXPECT_EQ(json_text::number(value), reference(value)) << value;
    std::string text = "[1.0, ";
    json_text::appendNumber(text, 0.5);
    EXPECT_EQ(text, "[1.0, 0.5");
    EXPECT_EQ(json_text::number(std::nan("")), "null");
    EXPECT_EQ(json_text::number(std::numeric_limits<double>::infinity()), "null");
}

TEST(JsonText, StringsAreEscapedAsNlohmannDumpsThem) {
    const std::string texts[] = {"",     "sil",  "PP merged", "a\"b",      "back\\slash",  "tab\tnew\nline",
                                 "\x01", "\x7f", "~ }{",      "caf\u00e9", "\u65e5\u672c", "/slash"};
    for (const std::string& text : texts) EXPECT_EQ(json_text::string(text), Json(text).dump()) << text;
    std::string out = "[";
    json_text::appendString(out, "x y");
    EXPECT_EQ(out, "[\"x y\"");
    EXPECT_ANY_THROW(json_text::string("bad \xff UTF-8")); // as nlohmann: not silently written
}

// Random doubles of every magnitude a track holds (and far beyond): the text reads back as the same
// double to the bit, and is nlohmann's text, or (where Grisu2's digits are not the shortest) no
// longer than it and read as the same double.
TEST(JsonText, RandomNumbersReadBackExactly) {
    std::mt19937_64 rng(33);
    std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
    std::uniform_int_distribution<int> exponent(-30, 30);
    int same = 0, total = 0;
    for (int i = 0; i < 100000; ++i) {
        const double value = mantissa(rng) * std::pow(10.0, exponent(rng));
        const std::string ours = json_text::number(value), theirs = reference(value);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(parsed(ours)), std::bit_cast<std::uint64_t>(value)) << ours;
        ++total;
        if (ours == theirs) {
            ++same;
            continue;
        }
        ASSERT_LE(ours.size(), theirs.size()) << ours << " against " << theirs;
        ASSERT_EQ(parsed(ours), parsed(theirs)) << ours << " against " << theirs;
    }
    EXPECT_GT(same, total * 99 / 100); // Grisu2 is shortest for all but a few
}

namespace {

// The digits of std::to_chars's shortest scientific form (the layout's general route): significant
// digits only, no point, no trailing zeros.
std::string shortestDigits(double value) {
    char text[40];
    const char* end =
        std::to_chars(text, text + sizeof text, std::fabs(value), std::chars_format::scientific).ptr;
    std::string digits;
    for (const char* p = text; p < end && *p != 'e'; ++p)
        if (*p != '.') digits += *p;
    return digits.substr(0, digits.find_last_not_of('0') + 1);
}

} // namespace

// Between 1e-4 and 1e15 the text is std::to_chars's fixed form: it must hold the same shortest digits
// as the scientific form, so the text is the one the general route lays out (the bounds included).
TEST(JsonText, FixedRangeHasTheShortestDigits) {
    std::mt19937_64 rng(34);
    std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
    std::uniform_int_distribution<int> exponent(-5, 15);
    std::vector<double> values = {1e-4, std::nextafter(1e-4, 0.0), std::nextafter(1e15, 0.0), 1e15, 0.1,
                                  100.0};
    for (int i = 0; i < 100000; ++i) values.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
    for (const double value : values) {
        const std::string ours = json_text::number(value);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(parsed(ours)), std::bit_cast<std::uint64_t>(value)) << ours;
        std::string digits;
        for (const char c : ours.substr(0, ours.find('e')))
            if (c >= '0' && c <= '9') digits += c;
        digits = digits.substr(std::min(digits.find_first_not_of('0'), digits.size()));
        digits = digits.substr(0, digits.find_last_not_of('0') + 1);
        ASSERT_EQ(digits, shortestDigits(value)) << ours;
        const bool fixedRange = std::fabs(value) >= 1e-4 && std::fabs(value) < 1e15;
        ASSERT_EQ(ours.find('e') == std::string::npos, fixedRange) << ours;
        ASSERT_TRUE(!fixedRange || ours.find('.') != std::string::npos) << ours; // "60.0", as nlohmann
    }
}
