#pragma once
// A fast 64-bit hash of bytes (XXH3 from Debian's libxxhash-dev, compiled in: no library is loaded at
// run time), for telling whether a cached result's inputs changed. Not for security.
#include <cstdint>
#include <string>
#include <string_view>

namespace vl {

std::uint64_t contentHash(std::string_view bytes);

// 16 lowercase hex digits, for file names.
std::string hashHex(std::uint64_t hash);

} // namespace vl
