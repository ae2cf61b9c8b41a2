// The position views GpuMesh::setGeometry reads (ui/render/GpuMesh.h): a strided view reads the
// values where an interleaved array holds them, a packed one is the array itself, and the normals
// of a strided view equal those of the same positions packed (the reference: core's vertexNormals).
#include "ui/render/GpuMesh.h"

#include <gtest/gtest.h>

#include <vector>

namespace vl::ui {
namespace {

struct Interleaved {
    Vec3 position;
    float scalar = 0.0f;
    Vec3 colour;
};

std::vector<Interleaved> tetrahedron() {
    return {{Vec3(0, 0, 0), 1.0f, Vec3(1, 0, 0)},
            {Vec3(1, 0, 0), 2.0f, Vec3(0, 1, 0)},
            {Vec3(0, 1, 0), 3.0f, Vec3(0, 0, 1)},
            {Vec3(0, 0, 1), 4.0f, Vec3(1, 1, 1)}};
}

TEST(PositionSpan, AStridedViewReadsEachValueWhereItIs) {
    const std::vector<Interleaved> vertices = tetrahedron();
    const PositionSpan view(&vertices[0].position, vertices.size(), sizeof(Interleaved));
    ASSERT_EQ(view.size(), 4u);
    EXPECT_FALSE(view.packed());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        EXPECT_EQ(view[i], vertices[i].position);
        EXPECT_EQ(&view[i], &vertices[i].position) << "read in place, not copied";
    }
}

TEST(PositionSpan, AVectorIsAPackedViewOfItself) {
    const std::vector<std::vector<Vec3>> targets{{Vec3(1, 2, 3), Vec3(4, 5, 6)},
                                                 {Vec3(7, 8, 9), Vec3(0, 1, 2)}};
    const std::vector<PositionSpan> views = positionSpans(targets);
    ASSERT_EQ(views.size(), 2u);
    for (std::size_t k = 0; k < targets.size(); ++k) {
        EXPECT_TRUE(views[k].packed());
        EXPECT_EQ(views[k].data, targets[k].data());
        EXPECT_EQ(views[k].size(), targets[k].size());
    }
    struct Key {
        std::vector<Vec3> positions;
    };
    const std::vector<Key> keys{{targets[0]}, {targets[1]}};
    const std::vector<PositionSpan> members = positionSpans(keys, &Key::positions);
    EXPECT_EQ(members[1].data, keys[1].positions.data());
}

TEST(PositionSpan, NormalsOfAStridedViewEqualThoseOfThePackedPositions) {
    const std::vector<Interleaved> vertices = tetrahedron();
    const std::vector<Triangle> triangles{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::vector<Vec3> packed;
    for (const Interleaved& v : vertices) packed.push_back(v.position);
    const std::vector<Vec3> reference = vl::vertexNormals(std::span<const Vec3>(packed), triangles);
    const std::vector<Vec3> strided =
        vertexNormals(PositionSpan(&vertices[0].position, vertices.size(), sizeof(Interleaved)), triangles);
    ASSERT_EQ(strided.size(), reference.size());
    for (std::size_t i = 0; i < reference.size(); ++i) EXPECT_EQ(strided[i], reference[i]);
    EXPECT_EQ(vertexNormals(PositionSpan(packed), triangles), reference);
}

} // namespace
} // namespace vl::ui
