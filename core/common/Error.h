#pragma once
// Errors the core reports. InputError is bad user input (a file, a flag, a table entry): its message
// always names where the problem is (file, line, element or JSON path) so the user can fix it.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace vl {

class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Throws InputError with the message "<where>: <what>".
[[noreturn]] void throwInputError(std::string_view where, std::string_view what);

// Input quoted in a message: at most `maxBytes` bytes (a whole 6 MB line once went to stderr), cut on
// a character boundary and marked "... (N bytes)"; bytes that are not valid UTF-8 and control
// characters are shown as \xNN, so every message is valid UTF-8 on one line.
inline constexpr std::size_t kMaxQuotedInput = 200;
std::string quoteInput(std::string_view text, std::size_t maxBytes = kMaxQuotedInput);

// True when `text` is valid UTF-8 (names read from argv, file names and CSV must be: reports and
// JSON outputs cannot hold anything else).
bool isValidUtf8(std::string_view text);

// "<file>:<line>" for messages about a line of a text file.
std::string fileLine(std::string_view file, std::size_t line);

} // namespace vl
