#pragma once
// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as zlib and PNG compute it.
#include <cstddef>
#include <cstdint>

namespace vl::runtime {

// Continues a CRC: crc32(b, crc32(a)) equals the CRC of a followed by b. Start with 0.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0);

} // namespace vl::runtime
