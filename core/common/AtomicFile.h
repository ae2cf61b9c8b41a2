#pragma once
// File reading and atomic writing shared by every loader and saver.
#include <filesystem>
#include <string>
#include <string_view>

namespace vl {

// Reads a whole file; throws InputError naming the file when it is missing or unreadable.
std::string readFileToString(const std::filesystem::path& path);

// Writes `contents` to a temporary file beside `path`, flushes it, then renames it over `path`,
// so a crash or a full disk never leaves a half-written file where the old one was.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

} // namespace vl
