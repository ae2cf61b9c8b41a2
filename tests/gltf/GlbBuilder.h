#pragma once
// A small writer of glTF 2.0 binaries for the avatar fixtures: JSON assembled by hand (nlohmann) and
// one BIN buffer, with the storage real exporters use: tight or strided views, quantised and
// normalised accessors, sparse accessors, EXT_meshopt_compression views (encoded with
// meshoptimizer, fallback buffer without data) and KHR_draco_mesh_compression streams.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace vl::test {

constexpr int kFloat = 5126, kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
              kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class GlbBuilder {
  public:
    nlohmann::ordered_json json;
    std::string bin;

    GlbBuilder();

    void useExtension(const std::string& name, bool required);

    // A plain view of raw bytes (4-byte aligned in BIN); returns its index.
    int addView(const void* data, std::size_t bytes, int target = 0, std::size_t stride = 0);
    // A view compressed with EXT_meshopt_compression: `data` holds count elements of `stride` bytes
    // (already filtered when `filter` is not "NONE"); mode "ATTRIBUTES", "TRIANGLES" or "INDICES".
    int addMeshoptView(const void* data, std::size_t count, std::size_t stride, const std::string& mode,
                       const std::string& filter = "NONE", int target = 0);

    // An accessor over view `view`; min/max computed from `values` (dequantised) when `bounds`.
    int addAccessor(int view, int componentType, const std::string& type, std::size_t count, bool normalized,
                    const std::vector<double>& minValues = {}, const std::vector<double>& maxValues = {});

    // Float VEC3/VEC2/... data in its own view; bounds written when asked (POSITION needs them).
    int addFloats(const std::vector<float>& values, const std::string& type, bool bounds,
                  int target = kArrayBuffer);
    // Indices as unsigned short (all < 65535) or unsigned int.
    int addIndices(const std::vector<std::uint32_t>& indices);
    // A VEC3 float accessor stored sparsely (no buffer view: zeros plus the non-zero elements).
    int addSparseVec3(const std::vector<float>& values, int indexType = kUnsignedShort);

    // Adds an object to a top-level array ("nodes", "meshes", ...) and returns its index.
    int add(const std::string& array, nlohmann::ordered_json object);

    std::string glb() const;

  private:
    void align();
    int meshoptFallback_ = -1;
};

// min/max of VEC-n data.
void vectorBounds(const std::vector<float>& values, int components, std::vector<double>& lo,
                  std::vector<double>& hi);

} // namespace vl::test
