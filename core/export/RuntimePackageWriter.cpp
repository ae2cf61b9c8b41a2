#include "core/export/RuntimePackageWriter.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/runtime/Crc32.h"
#include "core/runtime/PackageFormat.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vl {
namespace {

namespace rt = vl::runtime;

class ByteWriter {
  public:
    std::string bytes;
    void u16(std::uint16_t v) {
        bytes.push_back(static_cast<char>(v & 0xFF));
        bytes.push_back(static_cast<char>(v >> 8));
    }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
    }
    void f32(float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void pad4() {
        while (bytes.size() % 4 != 0) bytes.push_back('\0');
    }
    void putU32At(std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
    }
};

// Per-axis offset and scale so that offset + scale * 65535 covers [min, max] of `values`.
struct Quantiser {
    float offset[3];
    float scale[3];
    explicit Quantiser(const std::vector<float>& xyz) {
        for (int a = 0; a < 3; ++a) {
            float lo = xyz[static_cast<std::size_t>(a)], hi = lo;
            for (std::size_t i = static_cast<std::size_t>(a); i < xyz.size(); i += 3) {
                lo = std::min(lo, xyz[i]);
                hi = std::max(hi, xyz[i]);
            }
            offset[a] = lo;
            scale[a] = static_cast<float>((static_cast<double>(hi) - lo) / rt::kQuantisationSteps);
        }
    }
    void writeRecord(ByteWriter& w) const {
        for (float o : offset) w.f32(o);
        for (float s : scale) w.f32(s);
    }
    void writeValues(ByteWriter& w, const std::vector<float>& xyz) const {
        for (std::size_t i = 0; i < xyz.size(); ++i) {
            const int a = static_cast<int>(i % 3);
            double q = scale[a] > 0 ? std::round((static_cast<double>(xyz[i]) - offset[a]) / scale[a]) : 0.0;
            w.u16(static_cast<std::uint16_t>(std::clamp(q, 0.0, rt::kQuantisationSteps)));
        }
    }
};

std::vector<float> toFloats(const std::vector<Vec3>& points) {
    std::vector<float> out;
    out.reserve(points.size() * 3);
    for (const Vec3& p : points)
        for (int a = 0; a < 3; ++a) out.push_back(static_cast<float>(p[a]));
    return out;
}

std::vector<float> displacementOf(const KeyMesh& key, const MeshData& neutral) {
    std::vector<float> out;
    out.reserve(key.positions.size() * 3);
    for (std::size_t i = 0; i < key.positions.size(); ++i)
        for (int a = 0; a < 3; ++a)
            out.push_back(static_cast<float>(key.positions[i][a] - neutral.positions[i][a]));
    return out;
}

void writeName(ByteWriter& w, const std::string& name) {
    if (name.size() > 0xFFFF)
        throwInputError("runtime package", "name longer than 65535 bytes: " + name.substr(0, 40));
    w.u16(static_cast<std::uint16_t>(name.size()));
    w.bytes += name;
}

} // namespace

std::string encodeRuntimePackage(const ReducedModel& model, const RuntimePackageOptions& options) {
    validateReducedModel(model, "runtime package");
    const MeshData& mesh = model.neutral;
    const std::size_t v = mesh.positions.size();
    if (v > rt::kMaxVertices || mesh.triangles.size() > rt::kMaxTriangles ||
        model.keys.size() > rt::kMaxKeys || model.phonemeToKey.size() > rt::kMaxPhonemes)
        throwInputError("runtime package", "the model exceeds the format's limits (docs/runtime-format.md)");
    const bool indices32 = v > 0xFFFF;
    std::uint16_t flags = 0;
    if (options.quantise) flags |= rt::kFlagQuantised;
    if (indices32) flags |= rt::kFlagIndices32;
    if (mesh.hasUVs()) flags |= rt::kFlagHasUVs;

    ByteWriter w;
    w.bytes.assign(rt::kHeaderSize, '\0');
    std::uint32_t offsets[rt::kSectionCount], sizes[rt::kSectionCount];
    auto beginSection = [&](int s) { offsets[s] = static_cast<std::uint32_t>(w.bytes.size()); };
    auto endSection = [&](int s) {
        w.pad4();
        sizes[s] = static_cast<std::uint32_t>(w.bytes.size()) - offsets[s];
    };

    beginSection(rt::kSectionNeutral);
    const std::vector<float> neutral = toFloats(mesh.positions);
    if (options.quantise) {
        const Quantiser q(neutral);
        q.writeRecord(w);
        q.writeValues(w, neutral);
    } else {
        for (float x : neutral) w.f32(x);
    }
    endSection(rt::kSectionNeutral);

    beginSection(rt::kSectionIndices);
    for (const Triangle& t : mesh.triangles)
        for (std::uint32_t i : t) indices32 ? w.u32(i) : w.u16(static_cast<std::uint16_t>(i));
    endSection(rt::kSectionIndices);

    beginSection(rt::kSectionUVs);
    for (const Vec2& uv : mesh.uvs) {
        w.f32(static_cast<float>(uv[0]));
        w.f32(static_cast<float>(uv[1]));
    }
    endSection(rt::kSectionUVs);

    beginSection(rt::kSectionDisplacements);
    std::vector<std::vector<float>> displacements;
    for (const KeyMesh& key : model.keys) displacements.push_back(displacementOf(key, mesh));
    if (options.quantise) {
        std::vector<Quantiser> quantisers;
        for (const auto& d : displacements) quantisers.emplace_back(d);
        for (const Quantiser& q : quantisers) q.writeRecord(w);
        for (std::size_t k = 0; k < displacements.size(); ++k) quantisers[k].writeValues(w, displacements[k]);
    } else {
        for (const auto& d : displacements)
            for (float x : d) w.f32(x);
    }
    endSection(rt::kSectionDisplacements);

    beginSection(rt::kSectionStrings);
    for (const KeyMesh& key : model.keys) writeName(w, key.name);
    for (const auto& entry : model.phonemeToKey) writeName(w, entry.first);
    endSection(rt::kSectionStrings);

    beginSection(rt::kSectionPhonemeMap);
    for (const auto& entry : model.phonemeToKey) w.u32(static_cast<std::uint32_t>(entry.second));
    endSection(rt::kSectionPhonemeMap);

    if (w.bytes.size() > 0xFFFFFFFFu) throwInputError("runtime package", "the package would exceed 4 GiB");
    std::memcpy(w.bytes.data() + rt::header::kMagic, rt::kMagic, 4);
    w.bytes[rt::header::kVersion] = static_cast<char>(rt::kFormatVersion & 0xFF);
    w.bytes[rt::header::kVersion + 1] = static_cast<char>(rt::kFormatVersion >> 8);
    w.bytes[rt::header::kFlags] = static_cast<char>(flags & 0xFF);
    w.bytes[rt::header::kFlags + 1] = static_cast<char>(flags >> 8);
    w.putU32At(rt::header::kHeaderSize, rt::kHeaderSize);
    w.putU32At(rt::header::kFileSize, static_cast<std::uint32_t>(w.bytes.size()));
    w.putU32At(rt::header::kVertexCount, static_cast<std::uint32_t>(v));
    w.putU32At(rt::header::kTriangleCount, static_cast<std::uint32_t>(mesh.triangles.size()));
    w.putU32At(rt::header::kKeyCount, static_cast<std::uint32_t>(model.keys.size()));
    w.putU32At(rt::header::kPhonemeCount, static_cast<std::uint32_t>(model.phonemeToKey.size()));
    for (std::uint32_t s = 0; s < rt::kSectionCount; ++s) {
        w.putU32At(rt::header::kSections + 8 * s, offsets[s]);
        w.putU32At(rt::header::kSections + 8 * s + 4, sizes[s]);
    }
    const auto* payload = reinterpret_cast<const std::uint8_t*>(w.bytes.data()) + rt::kHeaderSize;
    w.putU32At(rt::header::kPayloadCrc, rt::crc32(payload, w.bytes.size() - rt::kHeaderSize));
    return std::move(w.bytes);
}

void writeRuntimePackage(const std::filesystem::path& path, const ReducedModel& model,
                         const RuntimePackageOptions& options) {
    writeFileAtomically(path, encodeRuntimePackage(model, options));
}

} // namespace vl
