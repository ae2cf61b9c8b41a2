#include "core/speech/JsonText.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

namespace vl::json_text {

void appendNumber(std::string& text, double value) {
    if (!std::isfinite(value)) {
        text += "null";
        return;
    }
    // Where nlohmann writes the digits in fixed notation (decimal exponent -4 < n <= 15, n counting
    // the digits before the point), std::to_chars's fixed form has the same shortest digits in the
    // same place, but for the ".0" nlohmann gives whole numbers. The bounds are exact: a double is
    // >= 1e-4 exactly when its shortest digits are (the shortest text reads back as the double, and
    // rounding is monotone), and likewise < 1e15.
    if (const double magnitude = std::fabs(value); magnitude >= 1e-4 && magnitude < 1e15) {
        char fixed[40];
        const auto [last, error] =
            std::to_chars(fixed, fixed + sizeof fixed, value, std::chars_format::fixed);
        if (error == std::errc()) {
            text.append(fixed, last);
            if (!std::memchr(fixed, '.', std::size_t(last - fixed))) text += ".0";
            return;
        }
    }
    // Shortest round-trip digits in scientific form, d[.ddd]e±XX, then laid out as nlohmann does
    // (detail::dtoa_impl::format_buffer, min_exp -4, max_exp 15). Written into one buffer: a track
    // formats thousands of numbers.
    char scientific[32];
    const auto [end, ec] = std::to_chars(scientific, scientific + sizeof scientific, std::fabs(value),
                                         std::chars_format::scientific);
    if (ec != std::errc()) { // cannot happen: 32 bytes hold any double
        text += Json(value).dump();
        return;
    }
    char digits[24];
    int k = 0; // digit count
    const char* p = scientific;
    for (; p < end && *p != 'e'; ++p)
        if (*p != '.') digits[k++] = *p;
    int exponent = 0;
    const char* e = p + 1;
    if (e < end && *e == '+') ++e; // from_chars reads a '-' but not a '+'
    std::from_chars(e, end, exponent);

    char out[48];
    char* o = out;
    if (std::signbit(value)) *o++ = '-';
    if (value == 0) {
        std::memcpy(o, "0.0", 3);
        text.append(out, std::size_t(o + 3 - out));
        return;
    }
    constexpr int kMinExp = -4, kMaxExp = 15;
    const int n = exponent + 1;   // where the decimal point falls in the digits
    if (k <= n && n <= kMaxExp) { // 1234e7 -> 12340000000.0
        std::memcpy(o, digits, std::size_t(k));
        o += k;
        std::memset(o, '0', std::size_t(n - k));
        o += n - k;
        *o++ = '.';
        *o++ = '0';
    } else if (0 < n && n <= kMaxExp) { // 1234e-2 -> 12.34
        std::memcpy(o, digits, std::size_t(n));
        o += n;
        *o++ = '.';
        std::memcpy(o, digits + n, std::size_t(k - n));
        o += k - n;
    } else if (kMinExp < n && n <= 0) { // 1234e-6 -> 0.001234
        *o++ = '0';
        *o++ = '.';
        std::memset(o, '0', std::size_t(-n));
        o += -n;
        std::memcpy(o, digits, std::size_t(k));
        o += k;
    } else { // 1.234e+30, 1e-05
        *o++ = digits[0];
        if (k > 1) {
            *o++ = '.';
            std::memcpy(o, digits + 1, std::size_t(k - 1));
            o += k - 1;
        }
        const int power = n - 1;
        *o++ = 'e';
        *o++ = power < 0 ? '-' : '+';
        const int magnitude = power < 0 ? -power : power;
        if (magnitude < 10) *o++ = '0';
        o = std::to_chars(o, out + sizeof out, magnitude).ptr;
    }
    text.append(out, std::size_t(o - out));
}

void appendString(std::string& out, std::string_view text) {
    // Printable ASCII without a quote or backslash is its own JSON text: most of a track's strings
    // (viseme and phoneme names), without a Json value and serializer each. Anything else is
    // escaped, and UTF-8 checked, by nlohmann.
    for (const char c : text)
        if (c < 0x20 || c > 0x7e || c == '"' || c == '\\') {
            out += Json(std::string(text)).dump();
            return;
        }
    out += '"';
    out += text;
    out += '"';
}

std::string string(std::string_view text) {
    std::string out;
    appendString(out, text);
    return out;
}

std::string number(double value) {
    std::string text;
    appendNumber(text, value);
    return text;
}

} // namespace vl::json_text
