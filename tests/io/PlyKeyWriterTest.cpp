// Binary key mesh files (core/io/PlyKeyWriter.h) read back by the PLY reader: float32 positions,
// exact (u,v) and faces, for random meshes with and without (u,v).
#include "core/io/PlyKeyWriter.h"
#include "MeshIOTestUtil.h"
#include "core/io/MeshIO.h"

#include <random>

namespace vl {
namespace {

TEST(PlyKeyWriter, ReadsBackAsFloat32PositionsAndExactTopology) {
    std::mt19937 rng(35);
    std::uniform_real_distribution<double> coordinate(-10, 10);
    for (int round = 0; round < 50; ++round) {
        MeshData mesh;
        const std::size_t vertices = 3 + rng() % 200;
        for (std::size_t i = 0; i < vertices; ++i) {
            mesh.positions.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
            if (round % 2) mesh.uvs.emplace_back(coordinate(rng), coordinate(rng));
        }
        for (std::size_t f = 0; f < 1 + rng() % 300; ++f) {
            const auto a = static_cast<std::uint32_t>(rng() % (vertices - 2));
            mesh.triangles.push_back({a, a + 1, a + 2});
        }
        const PlyKeyWriter writer(mesh);
        std::string buffer;
        const std::string file = std::string(writer.head()) +
                                 std::string(writer.positions(mesh.positions, buffer)) +
                                 std::string(writer.faces());
        const MeshData read = parsePly(file, "key.ply");
        test::expectSameFloat32Positions(mesh.positions, read.positions);
        EXPECT_EQ(read.triangles, mesh.triangles);
        ASSERT_EQ(read.uvs.size(), mesh.uvs.size());
        for (std::size_t i = 0; i < mesh.uvs.size(); ++i) EXPECT_EQ(read.uvs[i], mesh.uvs[i]);
    }
    MeshData bad;
    bad.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1e300, 0}};
    bad.triangles = {{0, 1, 2}};
    std::string buffer;
    test::expectInputError([&] { PlyKeyWriter(bad).positions(bad.positions, buffer); }, {"mesh to write"});
}

} // namespace
} // namespace vl
