#pragma once
// JSON scalars as text, for the track writers that lay out their JSON by hand (one cue a line).
#include "core/common/JsonParse.h"

#include <string>
#include <string_view>

namespace vl::json_text {

// Shortest text that reads back as the same double, laid out as nlohmann's dump (Json(value).dump():
// "60.0", "0.001234", "1.5e-05", "1e+20"; not finite: "null"), from std::to_chars's shortest digits
// (a track has thousands of numbers; a Json value and its serializer per number cost more than the
// rest of the track's text).
std::string number(double value);
void appendNumber(std::string& text, double value); // text += number(value)

// `text` quoted and escaped as nlohmann's dump (Json(text).dump()): throws on invalid UTF-8.
std::string string(std::string_view text);
void appendString(std::string& out, std::string_view text); // out += string(text)

} // namespace vl::json_text
