#include "core/runtime/Package.h"

#include <algorithm>

#include "core/runtime/Crc32.h"
#include "core/runtime/PackageFormat.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace vl::runtime {
namespace {

std::uint16_t u16At(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
std::uint32_t u32At(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
float f32At(const std::uint8_t* p) {
    const std::uint32_t bits = u32At(p);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

const char* sectionName(std::uint32_t section) {
    static const char* const names[kSectionCount] = {"neutral",       "indices", "uvs",
                                                     "displacements", "strings", "phoneme map"};
    return names[section];
}

} // namespace

// Validates and decodes one buffer. Every read is preceded by a bounds check against the section
// it belongs to, and every section was checked against the buffer, so no read leaves the input.
struct PackageParser {
    const std::uint8_t* data;
    std::size_t size;
    std::string& error;
    Package& out;
    std::uint32_t offsets[kSectionCount] = {};
    std::uint32_t sizes[kSectionCount] = {};
    std::uint16_t flags = 0;
    std::uint32_t keyCount = 0;
    std::uint32_t phonemeCount = 0;

    bool fail(const std::string& message) {
        error = message;
        return false;
    }

    bool run() {
        if (!parseHeader() || !checkSections()) return false;
        return parseNeutral() && parseIndices() && parseUVs() && parseDisplacements() && parseStrings() &&
               parsePhonemeMap();
    }

    bool parseHeader() {
        if (size < kHeaderSize)
            return fail("truncated: " + std::to_string(size) + " bytes, shorter than the " +
                        std::to_string(kHeaderSize) + "-byte header");
        if (std::memcmp(data + header::kMagic, kMagic, 4) != 0)
            return fail("not a VisemeLab runtime package (bad magic)");
        const std::uint16_t version = u16At(data + header::kVersion);
        if (version != kFormatVersion)
            return fail("unsupported format version " + std::to_string(version) +
                        " (this runtime reads version " + std::to_string(kFormatVersion) + ")");
        flags = u16At(data + header::kFlags);
        if ((flags & ~kKnownFlags) != 0) return fail("unknown header flags " + std::to_string(flags));
        if (u32At(data + header::kHeaderSize) != kHeaderSize)
            return fail("header size " + std::to_string(u32At(data + header::kHeaderSize)) + " is not " +
                        std::to_string(kHeaderSize));
        const std::uint32_t fileSize = u32At(data + header::kFileSize);
        if (fileSize != size)
            return fail((fileSize > size ? "truncated: header says " : "size mismatch: header says ") +
                        std::to_string(fileSize) + " bytes, got " + std::to_string(size));
        if (u32At(data + header::kReserved0) != 0 || u32At(data + header::kReserved1) != 0 ||
            u32At(data + header::kReserved1 + 4) != 0)
            return fail("reserved header fields are not zero");
        out.vertexCount_ = u32At(data + header::kVertexCount);
        out.triangleCount_ = u32At(data + header::kTriangleCount);
        keyCount = u32At(data + header::kKeyCount);
        phonemeCount = u32At(data + header::kPhonemeCount);
        if (out.vertexCount_ == 0 || out.vertexCount_ > kMaxVertices)
            return fail("vertex count " + std::to_string(out.vertexCount_) + " outside 1.." +
                        std::to_string(kMaxVertices));
        if (out.triangleCount_ == 0 || out.triangleCount_ > kMaxTriangles)
            return fail("triangle count " + std::to_string(out.triangleCount_) + " outside 1.." +
                        std::to_string(kMaxTriangles));
        if (keyCount == 0 || keyCount > kMaxKeys)
            return fail("key mesh count " + std::to_string(keyCount) + " outside 1.." +
                        std::to_string(kMaxKeys));
        if (phonemeCount > kMaxPhonemes)
            return fail("phoneme count " + std::to_string(phonemeCount) + " above " +
                        std::to_string(kMaxPhonemes));
        const std::uint32_t crc = crc32(data + kHeaderSize, size - kHeaderSize);
        if (crc != u32At(data + header::kPayloadCrc)) return fail("payload CRC-32 mismatch (file corrupted)");
        out.quantised_ = (flags & kFlagQuantised) != 0;
        return true;
    }

    // Sections follow each other without gaps from the header to the end of the file, 4-byte
    // aligned, and each has exactly the size its counts imply (the strings section is checked
    // while parsing).
    bool checkSections() {
        const std::uint64_t v = out.vertexCount_;
        const std::uint64_t k = keyCount;
        const bool q = out.quantised_;
        std::uint64_t expected[kSectionCount];
        expected[kSectionNeutral] =
            q ? kQuantisationRecordSize + alignTo4(static_cast<std::uint32_t>(6 * v)) : 12 * v;
        expected[kSectionIndices] =
            (flags & kFlagIndices32) ? 12ull * out.triangleCount_ : alignTo4(6u * out.triangleCount_);
        expected[kSectionUVs] = (flags & kFlagHasUVs) ? 8 * v : 0;
        expected[kSectionDisplacements] =
            q ? k * kQuantisationRecordSize + ((k * 6 * v + 3) & ~3ull) : k * 12 * v;
        expected[kSectionStrings] = 0; // variable
        expected[kSectionPhonemeMap] = 4ull * phonemeCount;
        std::uint64_t previousEnd = kHeaderSize;
        for (std::uint32_t s = 0; s < kSectionCount; ++s) {
            offsets[s] = u32At(data + header::kSections + 8 * s);
            sizes[s] = u32At(data + header::kSections + 8 * s + 4);
            const std::string name = std::string("section '") + sectionName(s) + "'";
            if (offsets[s] % 4 != 0 || sizes[s] % 4 != 0) return fail(name + " is not 4-byte aligned");
            if (offsets[s] != previousEnd)
                return fail(name + " does not start where the previous section ends");
            if (static_cast<std::uint64_t>(offsets[s]) + sizes[s] > size)
                return fail(name + " extends past the end of the file");
            if (s != kSectionStrings && sizes[s] != expected[s])
                return fail(name + " has " + std::to_string(sizes[s]) + " bytes, expected " +
                            std::to_string(expected[s]));
            previousEnd = static_cast<std::uint64_t>(offsets[s]) + sizes[s];
        }
        if (previousEnd != size) return fail("unused bytes after the last section");
        return true;
    }

    bool readQuantisation(const std::uint8_t* p, Package::Quantisation& qz, const std::string& what) {
        for (int a = 0; a < 3; ++a) {
            qz.offset[a] = f32At(p + 4 * a);
            qz.scale[a] = f32At(p + 12 + 4 * a);
            const double top =
                static_cast<double>(qz.offset[a]) + static_cast<double>(qz.scale[a]) * kQuantisationSteps;
            if (!std::isfinite(qz.offset[a]) || !std::isfinite(qz.scale[a]) || qz.scale[a] < 0.0f ||
                !std::isfinite(static_cast<float>(top)))
                return fail(what + ": invalid quantisation offset/scale");
        }
        return true;
    }

    bool readFloats(std::uint32_t offset, std::size_t count, std::vector<float>& values, const char* what) {
        values.resize(count);
        const std::uint8_t* p = data + offset;
        for (std::size_t i = 0; i < count; ++i) {
            values[i] = f32At(p + 4 * i);
            if (!std::isfinite(values[i]))
                return fail(std::string(what) + ": non-finite value at element " + std::to_string(i));
        }
        return true;
    }

    static void readU16s(const std::uint8_t* p, std::size_t count, std::vector<std::uint16_t>& values) {
        values.resize(count);
        for (std::size_t i = 0; i < count; ++i) values[i] = u16At(p + 2 * i);
    }

    bool parseNeutral() {
        const std::size_t n = 3ull * out.vertexCount_;
        if (!out.quantised_)
            return readFloats(offsets[kSectionNeutral], n, out.neutral_, "neutral positions");
        const std::uint8_t* p = data + offsets[kSectionNeutral];
        if (!readQuantisation(p, out.neutralQuant_, "neutral positions")) return false;
        readU16s(p + kQuantisationRecordSize, n, out.neutralQ_);
        return true;
    }

    bool parseIndices() {
        const std::size_t n = 3ull * out.triangleCount_;
        const std::uint8_t* p = data + offsets[kSectionIndices];
        if (flags & kFlagIndices32) {
            out.indices32_.resize(n);
            for (std::size_t i = 0; i < n; ++i) out.indices32_[i] = u32At(p + 4 * i);
        } else {
            readU16s(p, n, out.indices16_);
        }
        for (std::size_t i = 0; i < n; ++i)
            if (out.index(i) >= out.vertexCount_)
                return fail("index " + std::to_string(out.index(i)) + " of triangle " +
                            std::to_string(i / 3) + " is out of range (" + std::to_string(out.vertexCount_) +
                            " vertices)");
        return true;
    }

    bool parseUVs() {
        if (!(flags & kFlagHasUVs)) return true;
        return readFloats(offsets[kSectionUVs], 2ull * out.vertexCount_, out.uvs_, "uvs");
    }

    bool parseDisplacements() {
        const std::size_t n = 3ull * out.vertexCount_ * keyCount;
        const std::uint32_t offset = offsets[kSectionDisplacements];
        if (!out.quantised_) return readFloats(offset, n, out.displacements_, "displacements");
        out.keyQuant_.resize(keyCount);
        for (std::uint32_t k = 0; k < keyCount; ++k)
            if (!readQuantisation(data + offset + k * kQuantisationRecordSize, out.keyQuant_[k],
                                  "displacements of key " + std::to_string(k)))
                return false;
        readU16s(data + offset + keyCount * kQuantisationRecordSize, n, out.displacementsQ_);
        return true;
    }

    bool parseStrings() {
        const std::uint8_t* p = data + offsets[kSectionStrings];
        const std::uint32_t sectionSize = sizes[kSectionStrings];
        std::uint32_t at = 0;
        auto readString = [&](std::string& s, const std::string& what) {
            if (sectionSize - at < 2) return fail("strings: " + what + " runs past the section");
            const std::uint16_t length = u16At(p + at);
            at += 2;
            if (length == 0) return fail("strings: " + what + " is empty");
            if (sectionSize - at < length) return fail("strings: " + what + " runs past the section");
            s.assign(reinterpret_cast<const char*>(p + at), length);
            at += length;
            if (s.find('\0') != std::string::npos) return fail("strings: " + what + " contains a NUL byte");
            return true;
        };
        out.keyNames_.resize(keyCount);
        for (std::uint32_t k = 0; k < keyCount; ++k)
            if (!readString(out.keyNames_[k], "name of key " + std::to_string(k))) return false;
        out.phonemeNames_.resize(phonemeCount);
        for (std::uint32_t i = 0; i < phonemeCount; ++i) {
            if (!readString(out.phonemeNames_[i], "name of phoneme " + std::to_string(i))) return false;
            for (std::uint32_t j = 0; j < i; ++j)
                if (out.phonemeNames_[j] == out.phonemeNames_[i])
                    return fail("strings: phoneme '" + out.phonemeNames_[i] + "' is listed twice");
        }
        if (sectionSize - at >= 4) return fail("strings: unused bytes after the last name");
        for (; at < sectionSize; ++at)
            if (p[at] != 0) return fail("strings: padding is not zero");
        return true;
    }

    bool parsePhonemeMap() {
        const std::uint8_t* p = data + offsets[kSectionPhonemeMap];
        out.phonemeKeys_.resize(phonemeCount);
        for (std::uint32_t i = 0; i < phonemeCount; ++i) {
            out.phonemeKeys_[i] = u32At(p + 4 * i);
            if (out.phonemeKeys_[i] >= keyCount && out.phonemeKeys_[i] != kRestKey) // kRestKey: rests
                return fail("phoneme map: phoneme '" + out.phonemeNames_[i] + "' maps to key " +
                            std::to_string(out.phonemeKeys_[i]) + " of " + std::to_string(keyCount));
        }
        return true;
    }
};

void Package::clear() {
    *this = Package();
}

bool Package::load(const std::uint8_t* data, std::size_t size, std::string& error) {
    clear();
    if (data == nullptr && size != 0) {
        error = "null buffer";
        return false;
    }
    PackageParser parser{data, size, error, *this};
    if (size > 0xFFFFFFFFu) {
        error = "file larger than 4 GiB";
        clear();
        return false;
    }
    if (!parser.run()) {
        clear();
        return false;
    }
    return true;
}

bool Package::loadFile(const char* path, std::string& error) {
    clear();
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), &std::fclose);
    if (!file) {
        error = std::string(path) + ": cannot open";
        return false;
    }
    std::vector<std::uint8_t> bytes;
    std::uint8_t chunk[65536];
    std::size_t got;
    while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0)
        bytes.insert(bytes.end(), chunk, chunk + got);
    if (std::ferror(file.get())) {
        error = std::string(path) + ": read error";
        return false;
    }
    if (!load(bytes.data(), bytes.size(), error)) {
        error = std::string(path) + ": " + error;
        return false;
    }
    return true;
}

std::uint32_t Package::findPhoneme(std::string_view name) const {
    for (std::size_t i = 0; i < phonemeNames_.size(); ++i)
        if (phonemeNames_[i] == name) return static_cast<std::uint32_t>(i);
    return kNotFound;
}

std::uint32_t Package::findKey(std::string_view name) const {
    if (name.empty()) return kNotFound;
    for (std::size_t i = 0; i < keyNames_.size(); ++i)
        if (keyNames_[i] == name) return static_cast<std::uint32_t>(i);
    for (std::size_t i = 0; i < keyNames_.size(); ++i) { // members of merged keys: "a+b+c"
        const std::string_view key = keyNames_[i];
        for (std::size_t start = 0; start <= key.size();) {
            const std::size_t end = std::min(key.find('+', start), key.size());
            if (key.substr(start, end - start) == name) return static_cast<std::uint32_t>(i);
            start = end + 1;
        }
    }
    const std::uint32_t phoneme = findPhoneme(name);
    return phoneme == kNotFound ? kNotFound : phonemeKeys_[phoneme];
}

void Package::neutralPositions(float* out) const {
    blend(nullptr, 0, out);
}

void Package::keyPositions(std::uint32_t key, float* out) const {
    const KeyWeight one{key, 1.0f};
    blend(&one, 1, out);
}

void Package::blend(const KeyWeight* weights, std::size_t count, float* out) const {
    const std::size_t n = 3ull * vertexCount_;
    if (!quantised_) {
        std::memcpy(out, neutral_.data(), n * sizeof(float));
        for (std::size_t j = 0; j < count; ++j) {
            if (weights[j].key == kRestKey || weights[j].weight == 0.0f) continue;
            const float w = weights[j].weight;
            const float* d = displacements_.data() + n * weights[j].key;
            for (std::size_t i = 0; i < n; ++i) out[i] += w * d[i];
        }
        return;
    }
    // value = offset + scale * q: fold every offset into one constant per axis, every scale into
    // one factor per key and axis, so the vertex loop is multiply-adds on the stored integers.
    float constant[3], factor[3];
    for (int a = 0; a < 3; ++a) {
        constant[a] = neutralQuant_.offset[a];
        factor[a] = neutralQuant_.scale[a];
    }
    dequantiseInto(neutralQ_.data(), n, constant, factor, false, out);
    for (std::size_t j = 0; j < count; ++j) {
        if (weights[j].key == kRestKey || weights[j].weight == 0.0f) continue;
        const Quantisation& qz = keyQuant_[weights[j].key];
        for (int a = 0; a < 3; ++a) {
            constant[a] = weights[j].weight * qz.offset[a];
            factor[a] = weights[j].weight * qz.scale[a];
        }
        dequantiseInto(displacementsQ_.data() + n * weights[j].key, n, constant, factor, true, out);
    }
}

// out[i] (+)= constant[i % 3] + factor[i % 3] * q[i]. Blocks of 12 values (4 vertices) repeat the
// per-axis pattern exactly, so the inner loop has constant coefficients and vectorises.
void Package::dequantiseInto(const std::uint16_t* q, std::size_t n, const float constant[3],
                             const float factor[3], bool accumulate, float* out) {
    constexpr std::size_t kBlock = 12;
    float c[kBlock], f[kBlock];
    for (std::size_t i = 0; i < kBlock; ++i) {
        c[i] = constant[i % 3];
        f[i] = factor[i % 3];
    }
    std::size_t i = 0;
    if (accumulate) {
        for (; i + kBlock <= n; i += kBlock)
            for (std::size_t k = 0; k < kBlock; ++k) out[i + k] += c[k] + f[k] * static_cast<float>(q[i + k]);
        for (; i < n; ++i) out[i] += c[i % 3] + f[i % 3] * static_cast<float>(q[i]);
    } else {
        for (; i + kBlock <= n; i += kBlock)
            for (std::size_t k = 0; k < kBlock; ++k) out[i + k] = c[k] + f[k] * static_cast<float>(q[i + k]);
        for (; i < n; ++i) out[i] = c[i % 3] + f[i % 3] * static_cast<float>(q[i]);
    }
}

std::size_t Package::memoryBytes() const {
    std::size_t bytes = sizeof(Package);
    bytes += (neutral_.capacity() + displacements_.capacity() + uvs_.capacity()) * sizeof(float);
    bytes +=
        (neutralQ_.capacity() + displacementsQ_.capacity() + indices16_.capacity()) * sizeof(std::uint16_t);
    bytes += (indices32_.capacity() + phonemeKeys_.capacity()) * sizeof(std::uint32_t);
    bytes += keyQuant_.capacity() * sizeof(Quantisation);
    for (const auto* names : {&keyNames_, &phonemeNames_})
        for (const std::string& s : *names)
            bytes += sizeof(std::string) + (s.capacity() > 15 ? s.capacity() : 0);
    return bytes;
}

} // namespace vl::runtime
