// PLY reader and writer: ASCII and both binary byte orders, skipped properties and elements,
// (u,v) name variants, bit-exact round trips, and every rejected input.
#include "MeshIOTestUtil.h"
#include "core/io/MeshIO.h"

#include <cstring>
#include <limits>

namespace vl {
namespace {

using test::expectIdenticalMesh;
using test::expectInputError;

using test::put;

const std::string kAsciiQuads = "ply\r\n"
                                "format ascii 1.0\r\n"
                                "comment made by hand\r\n"
                                "obj_info nothing\r\n"
                                "element vertex 5\r\n"
                                "property float x\r\nproperty float y\r\nproperty double z\r\n"
                                "property float nx\r\nproperty uchar red\r\n"
                                "property float s\r\nproperty float t\r\n"
                                "element face 2\r\n"
                                "property uchar flags\r\n"
                                "property list uchar int vertex_index\r\n"
                                "property list uchar float texcoord\r\n"
                                "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
                                "end_header\r\n"
                                "0 0 0 0.5 255 0 0\r\n"
                                "1 0 0 0.5 255 1 0\r\n"
                                "1 1 0 0.5 255 1 1\r\n"
                                "0 1 0 0.5 255 0 1\r\n"
                                "2 2 2 0.5 255 0.25 0.75\r\n"
                                "7 4 0 1 2 3 2 0.5 0.5\r\n"
                                "0 5 0 1 2 3 4 0\r\n"
                                "0 1\r\n";

TEST(PlyFormat, ReadsAsciiSkippingUnknownPropertiesListsAndElements) {
    const MeshData mesh = parsePly(kAsciiQuads, "q.ply");
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.positions[4], Vec3(2, 2, 2));
    ASSERT_EQ(mesh.uvs.size(), 5u); // from s/t
    EXPECT_EQ(mesh.uvs[4], Vec2(0.25, 0.75));
    const std::vector<Triangle> expected{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(mesh.triangles, expected);
}

// The same quads as kAsciiQuads (without uvs) in binary, with mixed types and extra data.
std::string binaryQuads(bool bigEndian) {
    std::string out = std::string("ply\nformat ") +
                      (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 5\nproperty float x\nproperty double y\nproperty int16 z\n"
                      "property uchar alpha\nproperty list uint8 float32 weights\n"
                      "element face 2\nproperty list ushort uint vertex_indices\nproperty int material\n"
                      "end_header\n";
    const float xs[5] = {0, 1, 1, 0, 2};
    const double ys[5] = {0, 0, 1, 1, 2};
    const std::int16_t zs[5] = {0, 0, 0, 0, 2};
    for (int i = 0; i < 5; ++i) {
        put(out, xs[i], bigEndian);
        put(out, ys[i], bigEndian);
        put(out, zs[i], bigEndian);
        put(out, std::uint8_t{200}, bigEndian);
        put(out, std::uint8_t{2}, bigEndian);
        put(out, 0.5f, bigEndian);
        put(out, 0.25f, bigEndian);
    }
    put(out, std::uint16_t{4}, bigEndian);
    for (std::uint32_t v : {0u, 1u, 2u, 3u}) put(out, v, bigEndian);
    put(out, std::int32_t{-7}, bigEndian);
    put(out, std::uint16_t{5}, bigEndian);
    for (std::uint32_t v : {0u, 1u, 2u, 3u, 4u}) put(out, v, bigEndian);
    put(out, std::int32_t{9}, bigEndian);
    return out;
}

TEST(PlyFormat, BinaryLittleAndBigEndianAgreeWithAscii) {
    MeshData expected = parsePly(kAsciiQuads, "q.ply");
    expected.uvs.clear();
    expectIdenticalMesh(expected, parsePly(binaryQuads(false), "le.ply"));
    expectIdenticalMesh(expected, parsePly(binaryQuads(true), "be.ply"));
}

TEST(PlyFormat, ElementWithoutPropertiesHoldsNoDataHoweverLargeItsCount) {
    const std::string text = "ply\nformat binary_little_endian 1.0\nelement junk 4000000000000\n" +
                             binaryQuads(false).substr(binaryQuads(false).find("element vertex"));
    EXPECT_EQ(parsePly(text, "junk.ply").triangles.size(), 5u);
}

TEST(PlyFormat, ReadsEveryUVNamingConvention) {
    for (const auto& [u, v] :
         {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
        const std::string text =
            std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                        "property double z\nproperty float ") +
            u + "\nproperty float " + v +
            "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0 0.5 0.25\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n";
        const MeshData mesh = parsePly(text, "uv.ply");
        ASSERT_EQ(mesh.uvs.size(), 3u) << u;
        EXPECT_EQ(mesh.uvs[0], Vec2(0.5, 0.25)) << u;
    }
}

TEST(PlyFormat, WritesBinaryLittleEndianDoublesAndRoundTripsBitExactly) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const MeshData mesh = test::randomMesh(seed, 40 + seed * 11, 90 + seed * 5, seed % 2 == 1);
        const std::string bytes = formatPly(mesh);
        EXPECT_EQ(bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
        EXPECT_NE(bytes.find("property double x\n"), std::string::npos);
        expectIdenticalMesh(mesh, parsePly(bytes, "roundtrip.ply"));
    }
}

const std::string kHeader3 =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kVertices3 = "0 0 0\n1 0 0\n0 1 0\n"; // lines 10-12

TEST(PlyFormat, RejectsBadAsciiInputNamingFileLineAndElement) {
    const auto bad = [](std::string text) { return [text] { parsePly(text, "bad.ply"); }; };
    expectInputError(bad(""), {"bad.ply: empty file"});
    expectInputError(bad("solid cube\nfacet normal 0 0 1\n"), {"bad.ply:1:", "not a PLY file"});
    expectInputError(bad("ply\nformat ascii 1.0\nelement vertex 3\n"), {"bad.ply", "no end_header"});
    expectInputError(bad("ply\nelement vertex 0\nend_header\n"), {"bad.ply:3:", "no format line"});
    expectInputError(bad("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n"),
                     {"bad.ply:4:", "unknown PLY property type 'float128'"});
    expectInputError(
        bad("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n1 2\n3 0 0 0\n"),
        {"bad.ply:3:", "no 'z' property"});
    expectInputError(bad("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n"),
                     {"bad.ply: no vertices"});
    expectInputError(
        bad("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n1 2 3\n"),
        {"bad.ply: no faces"});
    expectInputError(bad(kHeader3 + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                     {"bad.ply:11: vertex 1", "non-finite"});
    expectInputError(bad(kHeader3 + "0 0 0\n1 0 0\n0 1 inf\n3 0 1 2\n"),
                     {"bad.ply:12: vertex 2", "non-finite"});
    expectInputError(bad(kHeader3 + kVertices3 + "3 0 1 3\n"),
                     {"bad.ply:13: face 0", "vertex index 3 out of range"});
    expectInputError(bad(kHeader3 + kVertices3 + "3 0 -1 2\n"),
                     {"bad.ply:13: face 0", "negative vertex index -1"});
    expectInputError(bad(kHeader3 + kVertices3 + "2 0 1\n"), {"bad.ply:13: face 0", "2 corner(s)"});
    expectInputError(bad(kHeader3 + kVertices3 + "3 0 1 1\n"),
                     {"bad.ply:13: face 0", "degenerate", "vertex 1"});
    expectInputError(bad(kHeader3 + kVertices3 + "3 0 1\n"), {"bad.ply:13: face 0", "data ends early"});
    expectInputError(bad(kHeader3 + kVertices3 + "3 0 1 2\n7 7\n"), {"bad.ply:14:", "unexpected data"});
    expectInputError(bad(kHeader3 + "0 0 0\n1 0 zero\n"), {"bad.ply:11: vertex 1", "expected a number"});
}

TEST(PlyFormat, RejectsBadBinaryInputNamingTheElement) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    const std::string good = formatPly(mesh);
    const std::size_t dataStart = good.find("end_header\n") + 11;
    const auto bad = [](std::string bytes) { return [bytes] { parsePly(bytes, "bin.ply"); }; };

    expectInputError(bad(good.substr(0, good.size() - 3)), {"bin.ply: face 1", "binary data ends early"});
    expectInputError(bad(good.substr(0, dataStart + 8 * 5)), {"bin.ply: vertex 1", "binary data ends early"});

    std::string nan = good;
    const double nanValue = std::numeric_limits<double>::quiet_NaN();
    std::memcpy(nan.data() + dataStart + 8 * 7, &nanValue, 8); // vertex 2, y
    expectInputError(bad(nan), {"bin.ply: vertex 2", "non-finite"});

    const std::size_t face1 = dataStart + 4 * 24 + 13; // 4 vertices of 3 doubles, face 0 is 13 bytes
    std::string negative = good;
    const std::int32_t minusTwo = -2;
    std::memcpy(negative.data() + face1 + 1 + 4, &minusTwo, 4);
    expectInputError(bad(negative), {"bin.ply: face 1", "negative vertex index -2"});

    std::string outOfRange = good;
    const std::int32_t nine = 9;
    std::memcpy(outOfRange.data() + face1 + 1, &nine, 4);
    expectInputError(bad(outOfRange), {"bin.ply: face 1", "vertex index 9 out of range (4 vertices)"});

    std::string degenerate = good;
    const std::int32_t three = 3;
    std::memcpy(degenerate.data() + face1 + 1 + 8, &three, 4);
    expectInputError(bad(degenerate), {"bin.ply: face 1", "degenerate"});

    std::string twoCorners = good;
    twoCorners[face1] = 2;
    expectInputError(bad(twoCorners), {"bin.ply: face 1", "2 corner(s)"});
}

} // namespace
} // namespace vl
