#pragma once
// JSON scalars as text, for the track writers that lay out their JSON by hand (one cue a line).
#include "core/common/JsonParse.h"

#include <string>
#include <string_view>

namespace vl::json_text {

// Shortest text that reads back as the same double.
inline std::string number(double value) {
    return Json(value).dump();
}

inline std::string string(std::string_view text) {
    return Json(std::string(text)).dump();
}

} // namespace vl::json_text
