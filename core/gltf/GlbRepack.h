#pragma once
// Writes an edited copy of a glTF document as one GLB: the caller edits `json` (a copy of the
// original), adds accessors and views of new data, and names the accessors it stopped using.
// finish() then removes those accessors and the buffer views only they used (nothing else: an
// object the input already left unused stays), and the elements only they used from compressed vertex
// views they shared with accessors that stay, renumbers every reference (core/gltf/GltfReferences),
// copies the bytes of every remaining view unchanged into the BIN chunk (compressed
// EXT_meshopt_compression data included; placeholder fallback buffers stay placeholders), places new
// compressed views' compressed bytes in the BIN chunk and their uncompressed layout in a fallback
// buffer without data (the input's first one, grown, or a new one), embeds external images, and drops
// compression extensions nothing uses any more.
#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace vl {

class GltfDocument;

struct RepackStats {
    std::size_t accessorsBefore = 0, accessorsAfter = 0;
    std::size_t binaryBytesBefore = 0, binaryBytesAfter = 0;
};

class GlbRepack {
  public:
    explicit GlbRepack(const GltfDocument& doc);

    nlohmann::ordered_json json; // the document being edited (starts as the original)

    // A buffer view of new bytes, placed in the BIN chunk; returns its index (current numbering).
    // `stride` > 0 is written as byteStride.
    int addView(std::string bytes, int target = 0, std::size_t stride = 0);
    // A buffer view compressed with EXT_meshopt_compression: `encoded` is meshoptimizer's encoding of
    // count elements of `stride` bytes (mode "ATTRIBUTES", "TRIANGLES" or "INDICES"; filter as the
    // extension names it). Marks the extension used and required (its fallback buffer has no data).
    int addMeshoptView(std::string encoded, std::size_t count, std::size_t stride, const std::string& mode,
                       const std::string& filter, int target = 0);
    // Lists `name` in extensionsUsed and extensionsRequired when it is not there yet.
    void requireExtension(const std::string& name);
    // Appends an accessor; returns its index (current numbering).
    int addAccessor(nlohmann::ordered_json accessor);
    // The accessor may have lost its last user: remove it if nothing refers to it at finish().
    void mayDrop(int accessor) { dropCandidates_.insert(accessor); }

    std::string finish(RepackStats* stats = nullptr);

  private:
    void embedExternalImages();
    std::size_t binBound() const; // at least the BIN chunk's size: every input buffer and new view

    // EXT_meshopt_compression vertex views that accessors staying and accessors going share (gltfpack
    // puts all morph targets of a primitive in one view): re-encoded with only the elements that stay,
    // the staying accessors' byteOffsets moved. Original view -> its new compressed bytes.
    std::map<long long, std::string> compactSharedViews(const std::vector<int>& accessorIndex);
    const GltfDocument& doc_;
    std::size_t originalViews_ = 0;
    struct NewView {
        std::string bytes; // compressed bytes when `meshopt`
        bool meshopt = false;
    };
    std::vector<NewView> newViews_; // views originalViews_, originalViews_ + 1, ...
    std::set<int> dropCandidates_;
};

} // namespace vl
