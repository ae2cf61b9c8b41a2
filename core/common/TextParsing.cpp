#include "core/common/TextParsing.h"

#include "core/common/Error.h"

#include <charconv>
#include <cmath>

namespace vl {

double parseFiniteDouble(std::string_view token, std::string_view where) {
    double value = 0.0;
    const char* begin = token.data();
    const char* end = token.data() + token.size();
    if (begin != end && *begin == '+') ++begin; // from_chars rejects a leading '+', files use it
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range)
        throwInputError(where, "number out of range '" + std::string(token) + "'");
    if (ec != std::errc() || ptr != end)
        throwInputError(where, "expected a number, found '" + std::string(token) + "'");
    if (!std::isfinite(value))
        throwInputError(where, "non-finite number '" + std::string(token) + "' (NaN or Inf)");
    return value;
}

std::int64_t parseInteger(std::string_view token, std::string_view where) {
    std::int64_t value = 0;
    const char* begin = token.data();
    const char* end = token.data() + token.size();
    if (begin != end && *begin == '+') ++begin;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range)
        throwInputError(where, "integer out of range '" + std::string(token) + "'");
    if (ec != std::errc() || ptr != end)
        throwInputError(where, "expected an integer, found '" + std::string(token) + "'");
    return value;
}

std::string formatDouble(double value) {
    std::string text;
    appendDouble(text, value);
    return text;
}

void appendDouble(std::string& out, double value) {
    char buffer[32];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    (void)ec; // 32 characters always suffice for the shortest round-trip form of a double
    out.append(buffer, ptr);
}

void appendInteger(std::string& out, std::int64_t value) {
    char buffer[24];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    (void)ec; // 20 digits and a sign fit
    out.append(buffer, ptr);
}

std::vector<std::string_view> splitWhitespace(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r\n");
    return text.substr(first, last - first + 1);
}

std::string_view stripUtf8Bom(std::string_view text) {
    return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

bool isBlankText(std::string_view text) {
    return trim(stripUtf8Bom(text)).empty();
}

} // namespace vl
