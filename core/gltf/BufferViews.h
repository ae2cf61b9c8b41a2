#pragma once
// The bytes of a glTF buffer view, checked against its buffer, with EXT_meshopt_compression views
// decoded by meshoptimizer (the extension's reference decoder; Debian libmeshoptimizer-dev) on
// first use and kept. A compressed view may expand to at most kMaxMeshoptExpansion times its
// compressed size (the codecs cannot do better; a larger claim is a hostile count), so a small file
// cannot make the reader allocate much.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace vl {

class GltfDocument;

inline constexpr std::size_t kMaxMeshoptExpansion = 128;

struct ViewBytes {
    const unsigned char* data = nullptr;
    std::size_t size = 0;
    std::size_t stride = 0; // bufferView.byteStride; 0 = tightly packed
    bool compressed = false;
};

class BufferViews {
  public:
    explicit BufferViews(const GltfDocument& doc) : doc_(doc) {}

    // The view's (decoded) bytes; throws InputError naming `where` and the view at fault.
    ViewBytes view(int index, const std::string& where);
    // True when the view carries EXT_meshopt_compression.
    bool isCompressed(int index) const;

  private:
    const std::vector<unsigned char>& decodeMeshopt(int index, const std::string& where);

    const GltfDocument& doc_;
    std::map<int, std::vector<unsigned char>> decoded_;
};

} // namespace vl
