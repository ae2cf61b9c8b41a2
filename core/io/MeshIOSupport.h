#pragma once
// Pieces every mesh format reader and writer shares (internal to core/io): fast number tokens,
// fan triangulation with the polygon checks, and the final "is this a mesh" checks.
#include "core/common/TextParsing.h"
#include "core/io/MeshIO.h"
#include "core/mesh/Mesh.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl::meshio {

// std::from_chars fast path for the common case; anything unusual ('+' sign, junk, NaN/Inf,
// overflow) goes to the strict parser, which accepts it or throws the canonical message at
// where(). `where` is a callable so "file:line" strings are only built when needed.
template <class Where> double toFiniteDouble(std::string_view token, const Where& where) {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec == std::errc() && ptr == token.data() + token.size() && std::isfinite(value)) return value;
    return parseFiniteDouble(token, where());
}

template <class Where> std::int64_t toInteger(std::string_view token, const Where& where) {
    std::int64_t value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec == std::errc() && ptr == token.data() + token.size()) return value;
    return parseInteger(token, where());
}

// Appends the fan triangulation (c0 c1 c2, c0 c2 c3, ...) of one polygon whose corners are
// 0-based, range-checked vertex indices. Returns an empty string, or why the polygon is rejected
// (fewer than 3 corners, a repeated vertex) for the caller to report at its location. Messages
// call it "face <faceIndex>" and number vertices from `indexBase` as the file does.
std::string appendPolygonFan(std::span<const std::uint32_t> corners, std::size_t faceIndex,
                             std::int64_t indexBase, std::vector<Triangle>& triangles);

// Throws InputError "<source>: empty file" for a file with nothing but whitespace.
void requireNotBlank(std::string_view text, std::string_view source);

// Throws InputError "<source>: no vertices" / "<source>: no faces".
void requireVerticesAndFaces(const MeshData& mesh, std::string_view source);

// A mesh a writer can save so that it reads back: (u,v) empty or one per vertex, indices in range,
// finite numbers (positions within float32's range for PositionPrecision::Float32). Throws
// InputError "mesh to write: ..." otherwise.
void requireWritable(const MeshData& mesh, PositionPrecision precision = PositionPrecision::Exact);
// The positions' part of requireWritable.
void requireWritablePositions(std::span<const Vec3> positions, PositionPrecision precision);

// Appends `prefix`, the values in their shortest exact form separated by spaces, then `suffix`.
void appendDoubles(std::string& out, std::string_view prefix, std::initializer_list<double> values,
                   std::string_view suffix);

// Gives every vertex the (u,v) of its first corner: cornerUV[v] is the texture coordinate index
// of vertex v's first corner, or -1 for none ((0,0) then). Returns empty when no corner has one.
std::vector<Vec2> uvsFromFirstCorners(std::span<const std::int64_t> cornerUV,
                                      std::span<const Vec2> texCoords);

// A text format's file split around its vertex positions: head + positions + tail is the file, and
// head and tail depend only on the mesh's counts, (u,v) and triangles (formatted once for many meshes
// of one topology, MeshTextFormatter).
struct TextAroundPositions {
    std::string head, tail;
};
TextAroundPositions objTextAroundPositions(const MeshData& topology);
void appendObjPositions(std::string& out, const PositionText& positions);
TextAroundPositions vrmlTextAroundPositions(const MeshData& topology);
void appendVrmlPositions(std::string& out, const PositionText& positions);
// The whole file: parts.head + positions (by appendPositions) + parts.tail, in one allocation.
using AppendPositions = void (*)(std::string&, const PositionText&);
std::string joinAroundPositions(TextAroundPositions parts, const PositionText& positions,
                                AppendPositions appendPositions);

} // namespace vl::meshio
