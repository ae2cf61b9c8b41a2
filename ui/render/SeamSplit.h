#pragma once
// The vertices GpuSurface draws: one per distinct (mesh vertex, texture coordinate) pair met at the
// triangles' corners, so a UV seam (a mesh vertex with two texture coordinates) keeps both while the
// mesh itself is never split. No GL here (tests/ui/SeamSplitTest.cpp checks it corner by corner).
#include "core/mesh/SurfaceMaterials.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl::ui {

struct SeamSplit {
    std::vector<std::uint32_t> source;   // per drawn vertex: its mesh vertex
    std::vector<std::uint32_t> texCoord; // per drawn vertex: its index into layout.texCoords (0 without)
    std::vector<std::uint32_t> indices;  // 3 per triangle, into the drawn vertices
};

// Throws std::invalid_argument when a corner indexes beyond `vertexCount` or layout.texCoords, or
// the layout has texture coordinates for another number of triangles.
SeamSplit splitAtSeams(std::span<const Triangle> triangles, std::size_t vertexCount,
                       const SurfaceLayout& layout);

} // namespace vl::ui
