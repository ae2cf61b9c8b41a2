#pragma once
// How far the head's parts stay behind the skin: for each part vertex, the signed distance to the
// nearest skin triangle of a region (the lips and around), positive on the skin's inner side. A part
// seen through the open mouth has the lips' rim as its nearest skin and is not counted; one that
// pokes through the lips comes out negative. Brute force over the region's triangles: a check for
// tests and reports, not for interactive use.
#include "core/face/HeadParts.h"

#include <span>
#include <string>
#include <vector>

namespace vl::face {

struct PartClearance {
    std::string part;
    double clearance = 0.0; // smallest signed distance of the part's vertices (model units)
    std::size_t vertex = 0; // the vertex (index within the part) where it is smallest
    bool checked = false;   // false when no vertex had a skin triangle of the region nearest
};

// `head` holds the skin (its first `skinVertices` vertices, with (u,v) in the face domain) and then
// the parts in the order of `parts`. Skin triangles count when all three (u,v) lie in [lo, hi]; their
// outer side faces `forward`.
std::vector<PartClearance> partClearances(const MeshData& head, std::size_t skinVertices,
                                          std::span<const HeadPart> parts, const Vec3& forward,
                                          const Vec2& lo, const Vec2& hi);

} // namespace vl::face
