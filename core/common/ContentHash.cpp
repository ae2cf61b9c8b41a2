#include "core/common/ContentHash.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

#include <cstdio>

namespace vl {

std::uint64_t contentHash(std::string_view bytes) {
    return XXH3_64bits(bytes.data(), bytes.size());
}

std::string hashHex(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

} // namespace vl
