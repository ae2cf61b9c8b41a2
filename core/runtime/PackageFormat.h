#pragma once
// Layout constants of the VisemeLab runtime package (docs/runtime-format.md), shared by the writer
// (core/export) and the dependency-free reader (core/runtime). Everything is little-endian.
#include "core/runtime/Package.h" // kRestKey, kNotFound

#include <cstdint>

namespace vl::runtime {

inline constexpr char kMagic[4] = {'V', 'L', 'R', 'T'};
inline constexpr std::uint16_t kFormatVersion = 1;
inline constexpr std::uint32_t kHeaderSize = 96;

// Header flags.
inline constexpr std::uint16_t kFlagQuantised = 1u
                                                << 0; // positions and displacements as uint16 + scale/offset
inline constexpr std::uint16_t kFlagIndices32 = 1u << 1; // uint32 indices (else uint16)
inline constexpr std::uint16_t kFlagHasUVs = 1u << 2;    // section kSectionUVs is present
inline constexpr std::uint16_t kKnownFlags = kFlagQuantised | kFlagIndices32 | kFlagHasUVs;

// Sections, in file order.
enum Section : std::uint32_t {
    kSectionNeutral = 0,       // neutral positions
    kSectionIndices = 1,       // triangle corner indices
    kSectionUVs = 2,           // per-vertex (u,v), empty without kFlagHasUVs
    kSectionDisplacements = 3, // per key mesh: displacement from the neutral, per vertex
    kSectionStrings = 4,       // key names, then phoneme names
    kSectionPhonemeMap = 5,    // per phoneme: key index
    kSectionCount = 6
};

// Byte offsets of the header fields.
namespace header {
inline constexpr std::uint32_t kMagic = 0;
inline constexpr std::uint32_t kVersion = 4;        // uint16
inline constexpr std::uint32_t kFlags = 6;          // uint16
inline constexpr std::uint32_t kHeaderSize = 8;     // uint32
inline constexpr std::uint32_t kFileSize = 12;      // uint32
inline constexpr std::uint32_t kVertexCount = 16;   // uint32
inline constexpr std::uint32_t kTriangleCount = 20; // uint32
inline constexpr std::uint32_t kKeyCount = 24;      // uint32
inline constexpr std::uint32_t kPhonemeCount = 28;  // uint32
inline constexpr std::uint32_t kPayloadCrc = 32;    // uint32, CRC-32 (IEEE) of bytes [headerSize, fileSize)
inline constexpr std::uint32_t kReserved0 = 36;     // uint32, zero
inline constexpr std::uint32_t kSections = 40;      // kSectionCount x {uint32 offset, uint32 size}
inline constexpr std::uint32_t kReserved1 = 88;     // 8 bytes, zero
} // namespace header

// A quantised array stores q in 0..65535 and means offset + scale * q, per axis.
inline constexpr std::uint32_t kQuantisationRecordSize = 24; // float32 offset[3], float32 scale[3]
inline constexpr double kQuantisationSteps = 65535.0;

// Upper bounds that keep every size computation far from overflow and reject absurd headers early.
inline constexpr std::uint32_t kMaxVertices = 1u << 24;
inline constexpr std::uint32_t kMaxTriangles = 1u << 25;
inline constexpr std::uint32_t kMaxKeys = 4096;
inline constexpr std::uint32_t kMaxPhonemes = 4096;

constexpr std::uint32_t alignTo4(std::uint32_t n) {
    return (n + 3u) & ~3u;
}

} // namespace vl::runtime
