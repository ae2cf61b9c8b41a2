#pragma once
// Strict JSON parsing shared by every JSON reader (project, frequencies, maps, weights, viseme
// parameter files): nesting depth checked on the text before any document is built, duplicate
// object keys refused, numbers that overflow a double refused, each error naming the file and the
// JSON path (RFC 6901 pointer) or line of the problem.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace vl {

// Object keys keep their file order, so a save of a loaded document lists them as the user did.
using Json = nlohmann::ordered_json;

// Parses text; syntax errors, nesting deeper than limits::kMaxJsonDepth, duplicate object keys
// (which nlohmann would silently merge) and numbers out of a double's range (1e999) are
// InputErrors naming `source` and the position / the JSON path.
Json parseJsonStrict(std::string_view text, std::string_view source);

// The depth pre-pass parseJsonStrict runs first: a linear scan that needs memory only for
// `maxDepth` levels. Throws InputError "<source>: <path>: JSON nested deeper than N levels (line L)".
// Malformed text is left to the parser to report.
void checkJsonNesting(std::string_view text, std::string_view source, std::size_t maxDepth);

// A JSON value quoted in a message: compact text, capped by quoteInput (a 1 MB array once went to
// stderr whole); strings that are not valid UTF-8 are shown with U+FFFD instead of throwing.
std::string quoteJson(const Json& value);

// "number", "string", "object", ... for messages.
std::string jsonTypeName(const Json& value);

// Appends an object key to a JSON path, escaping '~' and '/' as RFC 6901 requires.
std::string jsonPathAppend(std::string_view path, std::string_view key);
std::string jsonPathAppend(std::string_view path, std::size_t index);

} // namespace vl
