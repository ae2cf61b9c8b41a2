#pragma once
// Deterministic, diff-friendly JSON text: objects one member per line, arrays that hold only
// scalars on one line ([0.5, 1, 2]), arrays of such arrays one element per line (mesh vertices).
// Numbers use nlohmann's shortest round-trip form, so parse(format(x)) == x bit for bit and
// format(parse(format(x))) == format(x) byte for byte.
#include "core/io/JsonRead.h"

#include <string>

namespace vl {

std::string formatJsonPretty(const Json& value);

} // namespace vl
