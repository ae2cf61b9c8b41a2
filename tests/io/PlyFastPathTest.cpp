// The bulk binary PLY path (core/io/PlyFastPath.h) against the general reader: the same random file
// written in the host's byte order (the fast path) and the other one (the general reader) must give
// the same mesh bit for bit, and a file the fast path declines must get the general reader's error.
#include "core/io/PlyFastPath.h"
#include "MeshIOTestUtil.h"
#include "core/io/MeshIO.h"
#include "core/io/PlyHeader.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace vl {
namespace {

using test::expectIdenticalMesh;
using test::expectInputError;
using test::put;

struct RandomPly {
    std::vector<std::array<double, 3>> xyz;
    std::vector<std::array<std::int32_t, 3>> faces;
    bool doubleZ = false, extraProperty = false, uintIndices = false;

    std::string bytes(bool hostOrder) const {
        const bool little = (std::endian::native == std::endian::little) == hostOrder;
        std::string out = std::string("ply\nformat binary_") + (little ? "little" : "big") +
                          "_endian 1.0\nelement vertex " + std::to_string(xyz.size()) + "\n" +
                          (extraProperty ? "property uchar red\n" : "") +
                          "property float x\nproperty float y\n" +
                          (doubleZ ? "property double z\n" : "property float z\n") + "element face " +
                          std::to_string(faces.size()) + "\nproperty list uchar " +
                          (uintIndices ? "uint" : "int") + " vertex_indices\nend_header\n";
        const bool big = !little;
        for (const auto& p : xyz) {
            if (extraProperty) put(out, std::uint8_t{7}, big);
            put(out, static_cast<float>(p[0]), big);
            put(out, static_cast<float>(p[1]), big);
            if (doubleZ)
                put(out, p[2], big);
            else
                put(out, static_cast<float>(p[2]), big);
        }
        for (const auto& f : faces) {
            put(out, std::uint8_t{3}, big);
            for (const auto v : f) put(out, v, big);
        }
        return out;
    }
};

RandomPly randomPly(std::mt19937& rng) {
    RandomPly ply;
    std::uniform_real_distribution<double> coordinate(-100, 100);
    const auto vertices = std::uniform_int_distribution<std::size_t>(3, 300)(rng);
    for (std::size_t i = 0; i < vertices; ++i)
        ply.xyz.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
    std::uniform_int_distribution<std::int32_t> vertex(0, static_cast<std::int32_t>(vertices) - 1);
    const auto faces = std::uniform_int_distribution<std::size_t>(1, 500)(rng);
    while (ply.faces.size() < faces) {
        const std::array<std::int32_t, 3> f{vertex(rng), vertex(rng), vertex(rng)};
        if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) ply.faces.push_back(f);
    }
    ply.doubleZ = rng() % 2, ply.extraProperty = rng() % 2, ply.uintIndices = rng() % 2;
    return ply;
}

bool takesFastPath(const std::string& bytes) {
    return meshio::readPlyFast(bytes, meshio::parsePlyHeader(bytes, "t.ply")).has_value();
}

TEST(PlyFastPath, AgreesWithTheGeneralReaderOnRandomFiles) {
    std::mt19937 rng(33);
    for (int round = 0; round < 200; ++round) {
        const RandomPly ply = randomPly(rng);
        const std::string fast = ply.bytes(true), general = ply.bytes(false);
        ASSERT_TRUE(takesFastPath(fast)) << "round " << round;
        ASSERT_FALSE(takesFastPath(general));
        const MeshData expected = parsePly(general, "t.ply");
        expectIdenticalMesh(expected, parsePly(fast, "t.ply"));
        const auto positions = meshio::parsePlyPositionsMatching(fast, "t.ply", expected.triangles);
        ASSERT_TRUE(positions.has_value());
        expectIdenticalMesh({expected.positions, {}, {}}, {*positions, {}, {}});
        auto otherFaces = expected.triangles;
        std::swap(otherFaces.front()[0], otherFaces.front()[1]);
        EXPECT_FALSE(meshio::parsePlyPositionsMatching(fast, "t.ply", otherFaces).has_value());
    }
}

// Each corruption makes the fast path decline; the general reader's error names file and element.
TEST(PlyFastPath, DeclinesWhatTheGeneralReaderRejects) {
    std::mt19937 rng(34);
    for (int round = 0; round < 50; ++round) {
        RandomPly ply = randomPly(rng);
        const std::size_t f = rng() % ply.faces.size();
        switch (round % 4) {
        case 0:
            ply.xyz[rng() % ply.xyz.size()][1] = std::numeric_limits<double>::quiet_NaN();
            expectInputError([&] { parsePly(ply.bytes(true), "t.ply"); }, {"t.ply: vertex ", "non-finite"});
            break;
        case 1:
            ply.faces[f][2] = static_cast<std::int32_t>(ply.xyz.size());
            expectInputError([&] { parsePly(ply.bytes(true), "t.ply"); },
                             {"t.ply: face " + std::to_string(f), "out of range"});
            break;
        case 2:
            ply.faces[f][2] = ply.faces[f][0];
            expectInputError([&] { parsePly(ply.bytes(true), "t.ply"); }, {"t.ply: face ", "degenerate"});
            break;
        default: { // truncated, or a header declaring far more than the file holds: nothing allocated
            std::string bytes = ply.bytes(true);
            const auto at = bytes.find("element face ") + 13;
            bytes.replace(at, bytes.find('\n', at) - at, "1000000000000");
            EXPECT_FALSE(takesFastPath(bytes));
            expectInputError([&] { parsePly(bytes, "t.ply"); }, {"t.ply: face ", "ends early"});
        }
        }
    }
}

} // namespace
} // namespace vl
