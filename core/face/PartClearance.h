#pragma once
// How far the head's parts stay behind the skin: for each part vertex, the signed distance to the
// nearest point of the skin, positive on the skin's inner side. The side is decided with the
// angle-weighted pseudo-normal at that point (Baerentzen and Aanaes 2005), which is right wherever the
// nearest point is an edge or a corner (the lips' rim squeezed into a slit, the mouth corners); the
// face normal alone is not. A part vertex whose nearest skin is the mouth's rim is seen through the
// open mouth and is not counted; one nearest the skin's outer border lies beyond the edge of a face
// that is a mask (counted apart); one that pokes through the lips comes out negative. Brute force over
// the skin's triangles: a check for tests and reports, not for interactive use.
#include "core/face/HeadParts.h"

#include <span>
#include <string>
#include <vector>

namespace vl::face {

struct PartClearance {
    std::string part;
    double clearance = 0.0;       // smallest signed distance of the part's vertices (model units)
    std::size_t vertex = 0;       // the vertex (index within the part) where it is smallest
    bool checked = false;         // false when no vertex was measured (see below)
    std::size_t throughMouth = 0; // vertices nearest the mouth's rim (seen through the opening)
    std::size_t beyondBorder = 0; // vertices nearest the skin's outer border
    std::size_t crossings = 0;    // the part's edges that pass through the skin (anywhere on it)
    double closest = 0.0;         // smallest unsigned distance of a counted or through-mouth vertex
};

// `head` holds the skin (its first `skinVertices` vertices, with (u,v) in the face domain) and then
// the parts in the order of `parts`. A vertex counts when its nearest skin point lies on a triangle
// whose three (u,v) are in [lo, hi]. The skin's outer side is the one that faces `forward` over the
// region on the whole. The outer border is the skin's boundary loop of largest (u,v) extent; the
// other loops are the mouth's rim.
std::vector<PartClearance> partClearances(const MeshData& head, std::size_t skinVertices,
                                          std::span<const HeadPart> parts, const Vec3& forward,
                                          const Vec2& lo, const Vec2& hi);

} // namespace vl::face
