#include "core/io/MeshIOSupport.h"

#include "core/common/Error.h"

#include <algorithm>
#include <limits>

namespace vl::meshio {

namespace {

// The first vertex that occurs twice in `corners`, or -1. Quadratic scan for the usual small
// polygons, a sorted copy for big ones.
std::int64_t repeatedVertex(std::span<const std::uint32_t> corners) {
    if (corners.size() <= 16) {
        for (std::size_t i = 1; i < corners.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (corners[i] == corners[j]) return corners[i];
        return -1;
    }
    std::vector<std::uint32_t> sorted(corners.begin(), corners.end());
    std::sort(sorted.begin(), sorted.end());
    const auto it = std::adjacent_find(sorted.begin(), sorted.end());
    return it == sorted.end() ? -1 : static_cast<std::int64_t>(*it);
}

} // namespace

std::string appendPolygonFan(std::span<const std::uint32_t> corners, std::size_t faceIndex,
                             std::int64_t indexBase, std::vector<Triangle>& triangles) {
    if (corners.size() < 3)
        return "face " + std::to_string(faceIndex) + " has " + std::to_string(corners.size()) +
               " corner(s); a face needs at least 3";
    if (const auto v = repeatedVertex(corners); v >= 0)
        return "face " + std::to_string(faceIndex) + " is degenerate: vertex " +
               std::to_string(v + indexBase) + " appears more than once";
    for (std::size_t k = 2; k < corners.size(); ++k)
        triangles.push_back({corners[0], corners[k - 1], corners[k]});
    return {};
}

void requireNotBlank(std::string_view text, std::string_view source) {
    if (trim(text).empty()) throwInputError(source, "empty file");
}

void requireVerticesAndFaces(const MeshData& mesh, std::string_view source) {
    if (mesh.positions.empty()) throwInputError(source, "no vertices");
    if (mesh.triangles.empty()) throwInputError(source, "no faces");
}

void requireWritablePositions(std::span<const Vec3> positions, PositionPrecision precision) {
    constexpr std::string_view where = "mesh to write";
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const auto& p = positions[i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throwInputError(where, "vertex " + std::to_string(i) + " has a non-finite coordinate");
        if (precision == PositionPrecision::Float32) {
            // Rounds to infinity as a float: the text would be "inf", which no reader accepts.
            constexpr double kLimit = std::numeric_limits<float>::max();
            if (std::abs(p[0]) > kLimit || std::abs(p[1]) > kLimit || std::abs(p[2]) > kLimit)
                throwInputError(where, "vertex " + std::to_string(i) +
                                           " has a coordinate beyond float32's range (key meshes are "
                                           "written as float32)");
        }
    }
}

void requireWritable(const MeshData& mesh, PositionPrecision precision) {
    constexpr std::string_view where = "mesh to write";
    if (mesh.hasUVs() && mesh.uvs.size() != mesh.positions.size())
        throwInputError(where, std::to_string(mesh.uvs.size()) + " (u,v) pairs for " +
                                   std::to_string(mesh.positions.size()) + " vertices");
    requireWritablePositions(mesh.positions, precision);
    for (std::size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i][0]) || !std::isfinite(mesh.uvs[i][1]))
            throwInputError(where, "vertex " + std::to_string(i) + " has a non-finite (u,v)");
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (const auto v : mesh.triangles[f])
            if (v >= mesh.positions.size())
                throwInputError(where, "triangle " + std::to_string(f) + " has vertex index " +
                                           std::to_string(v) + " out of range (" +
                                           std::to_string(mesh.positions.size()) + " vertices)");
}

void appendDoubles(std::string& out, std::string_view prefix, std::initializer_list<double> values,
                   std::string_view suffix) {
    out += prefix;
    const char* separator = "";
    for (const double value : values) {
        out.append(separator);
        appendDouble(out, value);
        separator = " ";
    }
    out += suffix;
}

std::vector<Vec2> uvsFromFirstCorners(std::span<const std::int64_t> cornerUV,
                                      std::span<const Vec2> texCoords) {
    if (std::all_of(cornerUV.begin(), cornerUV.end(), [](std::int64_t t) { return t < 0; })) return {};
    std::vector<Vec2> uvs(cornerUV.size(), Vec2(0.0, 0.0));
    for (std::size_t v = 0; v < cornerUV.size(); ++v)
        if (cornerUV[v] >= 0) uvs[v] = texCoords[static_cast<std::size_t>(cornerUV[v])];
    return uvs;
}

std::string joinAroundPositions(TextAroundPositions parts, const PositionText& positions,
                                AppendPositions appendPositions) {
    constexpr std::size_t kBytesPerPosition = 70; // three shortest doubles and separators, generously
    std::string out = std::move(parts.head);
    out.reserve(out.size() + positions.vertexCount() * kBytesPerPosition + parts.tail.size());
    appendPositions(out, positions);
    return out += parts.tail;
}

} // namespace vl::meshio
