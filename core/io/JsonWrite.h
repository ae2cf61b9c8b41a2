#pragma once
// Deterministic, diff-friendly JSON text: objects one member per line, arrays that hold only
// scalars on one line ([0.5, 1, 2]), arrays of such arrays one element per line (mesh vertices).
// Numbers use nlohmann's shortest round-trip form, so parse(format(x)) == x bit for bit and
// format(parse(format(x))) == format(x) byte for byte.
#include "core/io/JsonRead.h"

#include <string>
#include <string_view>

namespace vl {

std::string formatJsonPretty(const Json& value);

// The JSON text `json` on one line: every space, tab, carriage return and newline outside strings
// removed (JSON Lines from a pretty text without parsing it again). `json` must be valid JSON.
std::string compactJsonText(std::string_view json);

} // namespace vl
