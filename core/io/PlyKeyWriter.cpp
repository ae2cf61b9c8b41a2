#include "core/io/PlyKeyWriter.h"

#include "core/common/Error.h"
#include "core/io/MeshIOSupport.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace vl {

namespace {

template <class T> char* putLittle(char* out, T value) {
    std::memcpy(out, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(out, out + sizeof(T));
    return out + sizeof(T);
}

} // namespace

PlyKeyWriter::PlyKeyWriter(const MeshData& topology)
    : PlyKeyWriter(topology.positions.size(), topology.triangles, topology.uvs) {}

PlyKeyWriter::PlyKeyWriter(std::size_t vertexCount, std::span<const Triangle> triangles,
                           std::span<const Vec2> uvs)
    : vertexCount_(vertexCount), uvs_(uvs.begin(), uvs.end()) {
    if (vertexCount_ > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throwInputError("mesh to write", "too many vertices for PLY int indices");
    head_ = "ply\nformat binary_little_endian 1.0\ncomment VisemeLab key mesh\nelement vertex " +
            std::to_string(vertexCount_) + "\nproperty float x\nproperty float y\nproperty float z\n";
    if (!uvs_.empty()) head_ += "property double u\nproperty double v\n";
    head_ += "element face " + std::to_string(triangles.size()) +
             "\nproperty list uchar int vertex_indices\nend_header\n";
    faces_.resize(triangles.size() * 13);
    char* out = faces_.data();
    for (const auto& t : triangles) {
        *out++ = 3;
        for (const auto v : t) out = putLittle(out, static_cast<std::int32_t>(v));
    }
}

std::string_view PlyKeyWriter::positions(std::span<const Vec3> positions, std::string& buffer) const {
    if (positions.size() != vertexCount_)
        throwInputError("mesh to write", std::to_string(positions.size()) + " positions for a topology of " +
                                             std::to_string(vertexCount_) + " vertices");
    meshio::requireWritablePositions(positions, PositionPrecision::Float32);
    const std::size_t stride = 3 * sizeof(float) + (uvs_.empty() ? 0 : 2 * sizeof(double));
    if (buffer.size() < vertexCount_ * stride) buffer.resize(vertexCount_ * stride); // reused across keys
    char* out = buffer.data();
    for (std::size_t i = 0; i < vertexCount_; ++i) {
        for (int k = 0; k < 3; ++k) out = putLittle(out, static_cast<float>(positions[i][k]));
        if (!uvs_.empty()) out = putLittle(putLittle(out, uvs_[i][0]), uvs_[i][1]);
    }
    return {buffer.data(), vertexCount_ * stride};
}

std::string_view PlyKeyWriter::positions(std::span<const float> xyz, std::string& buffer) const {
    if (xyz.size() != 3 * vertexCount_)
        throwInputError("mesh to write", std::to_string(xyz.size() / 3) + " positions for a topology of " +
                                             std::to_string(vertexCount_) + " vertices");
    for (std::size_t k = 0; k < xyz.size(); ++k)
        if (!std::isfinite(xyz[k]))
            throwInputError("mesh to write",
                            "vertex " + std::to_string(k / 3) + " has a non-finite coordinate");
    const std::size_t stride = 3 * sizeof(float) + (uvs_.empty() ? 0 : 2 * sizeof(double));
    if (buffer.size() < vertexCount_ * stride) buffer.resize(vertexCount_ * stride); // reused across keys
    char* out = buffer.data();
    if (uvs_.empty() && std::endian::native == std::endian::little) {
        std::memcpy(out, xyz.data(), xyz.size() * sizeof(float)); // the file's records, as they are
    } else {
        for (std::size_t i = 0; i < vertexCount_; ++i) {
            for (std::size_t k = 0; k < 3; ++k) out = putLittle(out, xyz[3 * i + k]);
            if (!uvs_.empty()) out = putLittle(putLittle(out, uvs_[i][0]), uvs_[i][1]);
        }
    }
    return {buffer.data(), vertexCount_ * stride};
}

} // namespace vl
