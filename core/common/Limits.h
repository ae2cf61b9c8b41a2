#pragma once
// The limits every reader enforces before it allocates, in one place (docs/robustness.md lists
// them). A file that exceeds one is a data error (InputError, exit code 3) naming the file and the
// element, never a crash, a runaway allocation or a silent truncation.
#include <cstddef>

namespace vl::limits {

// No input file larger than this is read (a 40 M-vertex OBJ is about 1 GiB).
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 30;

// A JSON document of this many bytes builds a DOM of several GiB; none of ours comes close (a project
// embedding a 26 k-vertex head and 16 visemes is about 16 MB).
inline constexpr std::size_t kMaxJsonBytes = std::size_t{128} << 20;

// The tree a JSON document builds (16 bytes a value, more for objects, arrays and long strings) may
// take at most this much: `[{},{},...]` would otherwise grow 16 times its text.
inline constexpr std::size_t kMaxJsonDomBytes = std::size_t{512} << 20;

// Objects and arrays nested deeper than this are refused before any JSON document is built
// (a project nests about 8 levels; nlohmann's copy and dump recurse once per level).
inline constexpr std::size_t kMaxJsonDepth = 64;

// VRML `USE` of a Coordinate or TextureCoordinate node copies its points again. The numbers copied
// by USE may total at most this factor times the file's tokens, or kVrmlMinUseExpansionBudget,
// whichever is larger, so a small file cannot expand into gigabytes (433 KB once gave 60 M vertices).
inline constexpr std::size_t kVrmlUseExpansionFactor = 8;
inline constexpr std::size_t kVrmlMinUseExpansionBudget = std::size_t{1} << 22; // numbers (doubles)

// A viseme set has at most this many visemes (phoneme inventories have about 40; the reduction is
// exact only up to a few dozen).
inline constexpr std::size_t kMaxVisemes = 4096;

// Embedded per-vertex arrays (a project's deformable face (u,v)) hold at most this many entries.
inline constexpr std::size_t kMaxVisemeSetPositions = std::size_t{1} << 24;

// A viseme set (neutral plus visemes) holds at most this many vertex positions in total, however
// often a project, an .fdp or a viseme file names the same mesh: as many as half the machine's
// physical memory holds at 24 bytes a position (the set's doubles; the other half is for the file
// being read, the outputs and the rest of the process). 24 GiB: 536 M positions. Not a fixed 2^24,
// which refused 1,000,000 vertices x 16 visemes (issue 33).
inline constexpr std::size_t kVisemeSetBytesPerPosition = 24;
std::size_t maxVisemeSetPositions();

} // namespace vl::limits
