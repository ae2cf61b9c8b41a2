#pragma once
// Splits VRML97 text into tokens (internal to core/io): words and numbers, quoted strings (kept
// with their quotes) and the brackets { } [ ]. Commas count as whitespace and '#' starts a comment
// that runs to the end of the line, as the VRML97 grammar says.
#include <cstddef>
#include <string_view>
#include <vector>

namespace vl::meshio {

struct VrmlToken {
    std::string_view text;
    std::size_t line; // 1-based, for messages
};

// Throws InputError "<source>:<line>: ..." for an unterminated string.
std::vector<VrmlToken> tokenizeVrml(std::string_view text, std::string_view source);

} // namespace vl::meshio
