#include "core/common/Limits.h"

#include <unistd.h>

namespace vl::limits {

std::size_t maxVisemeSetPositions() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return kMaxVisemeSetPositions; // unknown: the old fixed limit
    const auto physical = static_cast<std::size_t>(pages) * static_cast<std::size_t>(pageSize);
    return physical / 2 / kVisemeSetBytesPerPosition;
}

} // namespace vl::limits
