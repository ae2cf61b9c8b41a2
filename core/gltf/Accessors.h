#pragma once
// glTF accessors decoded to floats or vertex indices by the spec's rules (section 3.6.2: dense and
// sparse storage, byte strides; section 3.11: normalised integers, e.g. max(c / 32767, -1) for
// signed shorts, as KHR_mesh_quantization files use them). Every declared count is checked against
// the bytes actually present before anything is allocated; sparse indices must be unsigned byte,
// short or int (the only types the spec allows), strictly increasing and below the accessor count.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tinygltf {
struct Accessor;
}

namespace vl {

class GltfDocument;
class BufferViews;

inline constexpr std::size_t kAnyCount = static_cast<std::size_t>(-1);

class AccessorReader {
  public:
    AccessorReader(const GltfDocument& doc, BufferViews& views) : doc_(doc), views_(views) {}

    // The accessor, or an InputError naming `where` when the index does not exist.
    const tinygltf::Accessor& accessor(int index, const std::string& where) const;

    // count x components floats, `type` a TINYGLTF_TYPE_* (or -1: any). An accessor without a
    // buffer view (zeros, optionally with sparse values) must declare `expectedCount` elements:
    // nothing else bounds its size. When `expectedCount` is given, the accessor count must equal it.
    std::vector<float> floats(int index, int type, const std::string& where,
                              std::size_t expectedCount = kAnyCount);

    // Scalar unsigned byte/short/int vertex indices, each below `vertexCount`.
    std::vector<std::uint32_t> indices(int index, const std::string& where, std::size_t vertexCount);

    // Contents decoded elsewhere (KHR_draco_mesh_compression) that replace the accessor's own.
    void provide(int index, std::vector<float> values) { providedFloats_[index] = std::move(values); }
    void provideIndices(int index, std::vector<std::uint32_t> values) {
        providedIndices_[index] = std::move(values);
    }

  private:
    void readDense(int viewIndex, std::size_t byteOffset, std::size_t count, int components,
                   int componentType, bool normalized, float* out, const std::string& where);
    std::vector<std::uint32_t> readUnsigned(int viewIndex, std::size_t byteOffset, std::size_t count,
                                            int componentType, const std::string& where);

    const GltfDocument& doc_;
    BufferViews& views_;
    std::map<int, std::vector<float>> providedFloats_;
    std::map<int, std::vector<std::uint32_t>> providedIndices_;
};

// Components of a TINYGLTF_TYPE_* (SCALAR 1 ... MAT4 16), or 0 for anything else.
int componentsOf(int type);
// Bytes of a TINYGLTF_COMPONENT_TYPE_* allowed in glTF 2.0, or 0 (DOUBLE and unknown values).
int componentBytes(int componentType);

} // namespace vl
