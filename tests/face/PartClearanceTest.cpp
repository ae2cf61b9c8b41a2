// The clearance of head parts behind the skin on skins whose answer is known: a flat face sheet with
// the domain's mouth hole, and a sharp ridge where the side of the skin cannot be read from one
// triangle's normal.
#include "core/face/PartClearance.h"
#include "core/face/FaceDomain.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vl::face {
namespace {

// The face domain as a flat sheet 10 units wide at z = height(x), facing +z, followed by `part`.
MeshData headWith(const HeadPart& part, double (*height)(double) = nullptr) {
    MeshData head = faceDomainMesh(20, DomainDensity::Uniform);
    for (std::size_t v = 0; v < head.positions.size(); ++v) {
        const double x = 10.0 * head.uvs[v][0];
        head.positions[v] = Vec3(x, 10.0 * head.uvs[v][1], height ? height(x) : 0.0);
    }
    head.positions.insert(head.positions.end(), part.rest.positions.begin(), part.rest.positions.end());
    head.uvs.resize(head.positions.size(), Vec2(2.5, 0.5));
    return head;
}

// A small triangle with its corners at `centre` + offsets.
HeadPart triangleAt(const Vec3& centre, double depth = 0.0) {
    HeadPart part;
    part.name = "tooth";
    part.rest.positions = {centre + Vec3(-0.1, 0, 0), centre + Vec3(0.1, 0, 0), centre + Vec3(0, 0.1, depth)};
    part.rest.triangles = {{0, 1, 2}};
    return part;
}

PartClearance measure(const HeadPart& part, double (*height)(double) = nullptr) {
    const MeshData head = headWith(part, height);
    const std::size_t skin = head.positions.size() - part.rest.positions.size();
    const std::vector<HeadPart> parts{part};
    return partClearances(head, skin, parts, Vec3(0, 0, 1), Vec2(0, 0), Vec2(1, 1)).front();
}

TEST(PartClearance, APartBehindTheSkinHasItsDistanceAsClearance) {
    const auto c = measure(triangleAt(Vec3(3, 7, -0.5)));
    EXPECT_TRUE(c.checked);
    EXPECT_NEAR(c.clearance, 0.5, 1e-9);
    EXPECT_EQ(c.crossings, 0u);
    EXPECT_EQ(c.throughMouth, 0u);
}

TEST(PartClearance, APartThroughTheSkinIsNegativeAndCrossesIt) {
    const auto c = measure(triangleAt(Vec3(3, 7, -0.1), 0.3)); // one corner 0.2 in front of the skin
    EXPECT_TRUE(c.checked);
    EXPECT_NEAR(c.clearance, -0.2, 1e-9);
    EXPECT_EQ(c.crossings, 2u); // the two edges to the front corner
}

// Behind the mouth hole (u 0.4..0.6 on v = 0.3) the lips' rim is nearest: seen through the opening, not
// counted. In front of the hole the same vertices stick out of the mouth.
TEST(PartClearance, APartBehindTheMouthIsSeenThroughItAndOneInFrontSticksOut) {
    const auto behind = measure(triangleAt(Vec3(5, 2.98, -0.3)));
    EXPECT_FALSE(behind.checked);
    EXPECT_EQ(behind.throughMouth, 3u);
    EXPECT_DOUBLE_EQ(behind.clearance, 0.0);
    EXPECT_GT(behind.closest, 0.29);

    const auto front = measure(triangleAt(Vec3(5, 2.98, 0.3)));
    EXPECT_TRUE(front.checked);
    EXPECT_LT(front.clearance, -0.29);
    EXPECT_EQ(front.crossings, 0u); // in front of the hole: no edge passes through the skin
}

// A ridge along x = 5 whose sides slope back steeply: a point just outside it, off the ridge towards
// the right side's normal, is outside although it lies behind the left side's plane (the nearest point is
// the ridge edge, shared by both sides; a single face normal gets one of the two ties wrong).
TEST(PartClearance, TheSideOfASharpRidgeComesFromItsPseudoNormal) {
    const auto ridge = [](double x) { return -2.0 * std::abs(x - 5.0); };
    const Vec3 right = Vec3(2.0, 0.0, 1.0).normalized();
    HeadPart point;
    point.name = "point";
    point.rest.positions = {Vec3(5.0, 8.0, 0.0) + right * 0.3};
    const auto outside = measure(point, ridge);
    EXPECT_TRUE(outside.checked);
    EXPECT_NEAR(outside.clearance, -0.3, 1e-9);
    point.rest.positions = {Vec3(5.0, 8.0, -0.3)}; // straight behind the ridge: nearest the sides
    const auto inside = measure(point, ridge);
    EXPECT_NEAR(inside.clearance, 0.3 * right[2], 1e-9);
}

} // namespace
} // namespace vl::face
