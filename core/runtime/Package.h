#pragma once
// The device-side reader of a VisemeLab runtime package (docs/runtime-format.md). Dependency-free
// C++17 (standard library only; tests/runtime compiles it as C++17 too), no exceptions thrown on
// bad input: every load validates magic, version, sizes, offsets, counts, CRC-32 and indices, and
// returns false with a message instead of reading out of bounds. The loaded package keeps
// positions in the file's representation (float32 or 16-bit quantised), so its resident memory is
// about the size of the file.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vl::runtime {

// What findKey / findPhoneme return for a name the package does not hold.
inline constexpr std::uint32_t kNotFound = 0xFFFFFFFFu;
// A key index meaning the neutral face (no displacement): for keyframes and blends, e.g. silence.
inline constexpr std::uint32_t kRestKey = 0xFFFFFFFFu;

// One term of a blend: key mesh `key` (or kRestKey for the neutral) with weight `weight`.
struct KeyWeight {
    std::uint32_t key = 0;
    float weight = 0.0f;
};

class Package {
  public:
    // Parses and validates `size` bytes; on failure returns false, sets `error` and leaves the
    // package empty.
    bool load(const std::uint8_t* data, std::size_t size, std::string& error);
    // Reads the whole file, then load(); errors name the file.
    bool loadFile(const char* path, std::string& error);

    bool empty() const { return vertexCount_ == 0; }
    std::uint32_t vertexCount() const { return vertexCount_; }
    std::uint32_t triangleCount() const { return triangleCount_; }
    std::uint32_t keyCount() const { return static_cast<std::uint32_t>(keyNames_.size()); }
    std::uint32_t phonemeCount() const { return static_cast<std::uint32_t>(phonemeNames_.size()); }
    bool quantised() const { return quantised_; }
    bool hasUVs() const { return !uvs_.empty(); }

    const std::string& keyName(std::uint32_t key) const { return keyNames_[key]; }
    const std::string& phonemeName(std::uint32_t phoneme) const { return phonemeNames_[phoneme]; }
    // kRestKey for a phoneme that rests (the neutral face).
    std::uint32_t keyOfPhoneme(std::uint32_t phoneme) const { return phonemeKeys_[phoneme]; }
    std::uint32_t findPhoneme(std::string_view name) const; // kNotFound when absent
    // The key that plays `name`: a key's own name ("FF+TH"), else an original viseme merged into a
    // key (a member of a name joined by '+': "FF"), else a phoneme ("F"); kNotFound when none.
    std::uint32_t findKey(std::string_view name) const;

    // Corner `corner` (0 .. 3*triangleCount-1) of the triangle list.
    std::uint32_t index(std::size_t corner) const {
        return indices32_.empty() ? indices16_[corner] : indices32_[corner];
    }
    bool indices32() const { return !indices32_.empty(); }
    const std::vector<float>& uvs() const { return uvs_; } // 2 per vertex, or empty

    // Decoded positions (3 floats per vertex) of the neutral, or of key mesh `key`.
    void neutralPositions(float* out) const;
    void keyPositions(std::uint32_t key, float* out) const;

    // out = neutral + sum_j weights[j].weight * displacement(weights[j].key), 3 floats per vertex.
    // Keys must be < keyCount() or kRestKey (contributes nothing).
    void blend(const KeyWeight* weights, std::size_t count, float* out) const;

    // Bytes of decoded data held (positions, indices, uvs, names).
    std::size_t memoryBytes() const;

  private:
    struct Quantisation {
        float offset[3] = {0, 0, 0};
        float scale[3] = {0, 0, 0};
    };
    friend struct PackageParser;
    void clear();
    static void dequantiseInto(const std::uint16_t* q, std::size_t n, const float constant[3],
                               const float factor[3], bool accumulate, float* out);

    std::uint32_t vertexCount_ = 0;
    std::uint32_t triangleCount_ = 0;
    bool quantised_ = false;
    std::vector<float> neutral_;                // float32 path: 3V
    std::vector<float> displacements_;          // float32 path: K * 3V
    std::vector<std::uint16_t> neutralQ_;       // quantised path: 3V
    std::vector<std::uint16_t> displacementsQ_; // quantised path: K * 3V
    Quantisation neutralQuant_;
    std::vector<Quantisation> keyQuant_;
    std::vector<std::uint16_t> indices16_;
    std::vector<std::uint32_t> indices32_;
    std::vector<float> uvs_;
    std::vector<std::string> keyNames_;
    std::vector<std::string> phonemeNames_;
    std::vector<std::uint32_t> phonemeKeys_;
};

} // namespace vl::runtime
