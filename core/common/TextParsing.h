#pragma once
// Small, strict number parsing and formatting shared by the text formats (OBJ, PLY, VRML, CSV).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// Parses a finite double; throws InputError "<where>: ..." for junk, NaN or infinity.
double parseFiniteDouble(std::string_view token, std::string_view where);

// Parses a signed integer; throws InputError "<where>: ..." for junk or overflow.
std::int64_t parseInteger(std::string_view token, std::string_view where);

// Shortest text that parses back to exactly the same double (round-trip exact).
std::string formatDouble(double value);
// The same text appended to `out` without a temporary string (writers format ~100k numbers per mesh).
void appendDouble(std::string& out, double value);
// Decimal text of an integer appended to `out`.
void appendInteger(std::string& out, std::int64_t value);

// Splits on spaces/tabs (and '\r'), skipping empty tokens.
std::vector<std::string_view> splitWhitespace(std::string_view line);

std::string_view trim(std::string_view text);

// `text` without a leading UTF-8 byte order mark (EF BB BF), which some editors write.
std::string_view stripUtf8Bom(std::string_view text);

// True when the text holds nothing but white space (and perhaps a byte order mark).
bool isBlankText(std::string_view text);

} // namespace vl
