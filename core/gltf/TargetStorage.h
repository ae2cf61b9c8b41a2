#pragma once
// How the reduced keys' morph target attributes are stored: as their member targets are in the
// input, so that a compressed avatar stays compressed and a reduction makes it smaller.
//
// - Quantised members (KHR_mesh_quantization: BYTE/SHORT, normalised or not): the key keeps the
//   componentType and normalized flag; each value is the mean of the dequantised member values put
//   back on the same grid (rounded, clamped). Dense views keep 4-byte element alignment (SHORT VEC3
//   stride 8, BYTE VEC3 stride 4, padding zero); integer min/max hold the stored integers.
// - Members in EXT_meshopt_compression views: the key's dense view is encoded with
//   meshopt_encodeVertexBuffer (vertex format version 0, the only one the extension allows), mode
//   ATTRIBUTES. Filter EXPONENTIAL is kept with the member's mantissa bits (inferred: the smallest K
//   whose encode + decode reproduces the member's decoded data bit for bit; kDefaultExponentBits when
//   none does); OCTAHEDRAL and QUATERNION describe unit vectors, not deltas: NONE instead.
// - Members stored differently: the most precise member's storage (morePrecise()).
// Then, per accessor, the smallest of the layouts that keep that precision: no bytes at all (every
// value zero), sparse (indices + tightly packed values), dense, or dense compressed (meshopt members).
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace vl {

class BufferViews;
class GltfDocument;
class GlbRepack;

// Mantissa bits when a member's EXPONENTIAL data matches no K (not written by meshopt's encoder):
// 16, finer than gltfpack's default of 14 for positions, so the key never loses what its members had.
inline constexpr int kDefaultExponentBits = 16;

enum class MeshoptFilter { None, Exponential };

struct TargetStorage {
    int componentType = 5126; // FLOAT, BYTE (5120) or SHORT (5122)
    bool normalized = false;
    bool meshopt = false; // dense views compressed with EXT_meshopt_compression
    MeshoptFilter filter = MeshoptFilter::None;
    int exponentBits = 0; // EXPONENTIAL: mantissa bits, 1..24
};

// The storage of member target accessor `accessor`: its component type, and its view's compression
// (decoded through `views` to infer exponential mantissa bits). A type KHR_mesh_quantization does not
// allow for targets (unsigned) reads as FLOAT.
TargetStorage storageOf(const GltfDocument& doc, BufferViews& views, int accessor, const std::string& where);

// The more precise of two member storages: floats before integers (an unfiltered float before an
// exponential one, more mantissa bits before fewer), then the finer integer step (normalised SHORT,
// normalised BYTE, SHORT, BYTE); equal precision: the compressed one.
TargetStorage morePrecise(const TargetStorage& a, const TargetStorage& b);

// Smallest K in 1..24 for which meshopt_encodeFilterExp(K) + decode reproduces `data` (count
// elements of `stride` bytes, floats) bit-exactly; kDefaultExponentBits when none does.
int inferExponentBits(const unsigned char* data, std::size_t count, std::size_t stride);

// Counts of written key accessors by storage description ("SHORT normalised, sparse", ...).
using StorageTally = std::map<std::string, std::size_t>;

// A VEC3 accessor of `values` (3 per vertex, the float mean) in `storage`, in the smallest layout
// that keeps its precision; POSITION (`bounds`) gets min/max of what is stored. Counts the choice
// into `tally` when given. Returns the accessor's index in `out`.
int addVec3Target(GlbRepack& out, const std::vector<double>& values, const TargetStorage& storage,
                  bool bounds, StorageTally* tally = nullptr);

} // namespace vl
