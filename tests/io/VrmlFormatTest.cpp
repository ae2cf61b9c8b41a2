// VRML97 reader and writer: IndexedFaceSets inside any nesting, DEF/USE, comments and commas,
// several sets concatenated in file order, texture coordinates with and without texCoordIndex,
// bit-exact round trips, and every rejected input with its line.
#include "MeshIOTestUtil.h"
#include "core/io/MeshIO.h"

#include <cctype>

namespace vl {
namespace {

using test::expectIdenticalMesh;
using test::expectInputError;

const std::string kScene = R"(#VRML V2.0 utf8
# an XfaceEd-like scene: two shapes in a transform, one sharing another's coordinates
PROTO Dummy [ field SFFloat size 1 ] { Shape { geometry IndexedFaceSet { coord Coordinate { point [ 9 9 9 ] } coordIndex [ 0 0 0 ] } } }
Transform {
  translation 0 -1 -659   # ignored: positions are taken as written
  rotation 1 0 0 0.4
  children [
    DEF Head Shape {
      appearance Appearance { material Material { diffuseColor 1 0.8 0.7 } texture ImageTexture { url "face#1.png" } }
      geometry DEF HeadMesh IndexedFaceSet {
        solid FALSE
        creaseAngle 1.2
        coord DEF HeadCoords Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 2,2,2 ] }
        texCoord TextureCoordinate { point [ 0 0, 1 0, 1 1, 0 1 ] }
        coordIndex [ 0 1 2 3 -1, 0 1 2 3 4 -1 ]
        texCoordIndex [ 0 1 2 3 -1, 3 2 1 0 0 -1 ]
        normalPerVertex TRUE
      }
    }
    Group { children [
      Shape { geometry IndexedFaceSet {
        coord USE HeadCoords
        texCoord TextureCoordinate { point [ 0.5 0.5, 0.25 0.25, 0.75 0.75 ] }
        coordIndex [ 2, 1, 0 ]
      } }
      Shape { geometry USE HeadMesh }
    ] }
  ]
}
)";

TEST(VrmlFormat, ConcatenatesEveryIndexedFaceSetInFileOrder) {
    const MeshData mesh = parseVrml(kScene, "scene.wrl");
    ASSERT_EQ(mesh.positions.size(), 10u); // 5 + the 5 shared coordinates again; the USE'd set adds nothing
    EXPECT_EQ(mesh.positions[4], Vec3(2, 2, 2));
    EXPECT_EQ(mesh.positions[9], Vec3(2, 2, 2));
    const std::vector<Triangle> expected{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {7, 6, 5}};
    EXPECT_EQ(mesh.triangles, expected);
    ASSERT_EQ(mesh.uvs.size(), 10u);
    EXPECT_EQ(mesh.uvs[0], Vec2(0, 0)); // first corner of vertex 0 uses texCoord 0
    EXPECT_EQ(mesh.uvs[3], Vec2(0, 1));
    EXPECT_EQ(mesh.uvs[4], Vec2(0, 0));       // vertex 4's only corner uses texCoord 0
    EXPECT_EQ(mesh.uvs[7], Vec2(0.75, 0.75)); // no texCoordIndex: coordIndex indexes the texCoords
    EXPECT_EQ(mesh.uvs[5], Vec2(0.5, 0.5));
    EXPECT_EQ(mesh.uvs[9], Vec2(0, 0)); // used by no face
}

TEST(VrmlFormat, ReadsMinimalFileWithoutHeaderOrTrailingTerminator) {
    const MeshData mesh =
        parseVrml("IndexedFaceSet{coord Coordinate{point[0 0 0 1 0 0 0 1 0]}coordIndex[0 1 2]}", "m.wrl");
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
    EXPECT_FALSE(mesh.hasUVs());
}

TEST(VrmlFormat, WritesOneShapeAndRoundTripsBitExactly) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const MeshData mesh = test::randomMesh(seed, 30 + seed * 13, 60 + seed * 7, seed % 2 == 0);
        const std::string text = formatVrml(mesh);
        EXPECT_EQ(text.rfind("#VRML V2.0 utf8\n", 0), 0u);
        EXPECT_EQ(text.find("IndexedFaceSet"), text.rfind("IndexedFaceSet"));
        EXPECT_EQ(text.find("TextureCoordinate") != std::string::npos, mesh.hasUVs());
        expectIdenticalMesh(mesh, parseVrml(text, "roundtrip.wrl"));
    }
}

// XfacePlayer's loader loops on VRML it does not expect: a comma after every index and value, none
// before a closing ']', and an explicit texCoordIndex.
TEST(VrmlFormat, WritesTheLayoutXfacePlayerReads) {
    for (bool uvs : {false, true}) {
        const MeshData mesh = test::randomMesh(3, 40, 70, uvs);
        const std::string text = formatVrml(mesh);
        EXPECT_EQ(text.find(",\n      ]"), std::string::npos);
        EXPECT_EQ(text.find(",\n    ]"), std::string::npos);
        EXPECT_EQ(text.find("texCoordIndex") != std::string::npos, uvs);
        const std::size_t begin = text.find("coordIndex [\n") + 13, end = text.find("    ]", begin);
        const std::string indices = text.substr(begin, end - begin);
        std::size_t numbers = 0, commas = 0;
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] == ',') ++commas;
            if ((std::isdigit(static_cast<unsigned char>(indices[i])) || indices[i] == '-') &&
                (i == 0 || indices[i - 1] == ' ' || indices[i - 1] == '\n'))
                ++numbers;
        }
        // XfacePlayer reads "value ," pairs with `>>`: a comma followed by anything but white space
        // would be read together with the next value.
        for (std::size_t i = text.find(','); i != std::string::npos; i = text.find(',', i + 1))
            ASSERT_TRUE(i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\n')) << i;
        EXPECT_EQ(numbers, 4 * mesh.triangles.size());
        EXPECT_EQ(commas, numbers - 1); // after every index but the last
        EXPECT_EQ(indices.substr(indices.size() - 3), "-1\n");
        expectIdenticalMesh(mesh, parseVrml(text, "xface.wrl"));
    }
}

std::string faceSet(const std::string& points, const std::string& indices, const std::string& extra = "") {
    return "#VRML V2.0 utf8\nShape {\n geometry IndexedFaceSet {\n  coord Coordinate {\n   point [\n" +
           points + "\n   ]\n  }\n  coordIndex [\n" + indices + "\n  ]\n" + extra + " }\n}\n";
}

TEST(VrmlFormat, RejectsBadInputNamingFileAndLine) {
    const std::string points = "0 0 0,\n1 0 0,\n0 1 0,\n1 1 0"; // lines 6-9; coordIndex values from line 13
    const auto bad = [](std::string text) { return [text] { parseVrml(text, "bad.wrl"); }; };
    expectInputError(bad(""), {"bad.wrl: empty file"});
    expectInputError(bad("#VRML V2.0 utf8\nGroup { }\n"), {"bad.wrl: no IndexedFaceSet found"});
    expectInputError(bad("#VRML V1.0 ascii\nSeparator { }\n"), {"bad.wrl:1:", "VRML 1.0"});
    expectInputError(bad(std::string("\x1f\x8b\x08\x00", 4)), {"bad.wrl", "gzip"});
    expectInputError(bad(faceSet("", "")), {"bad.wrl: no vertices"});
    expectInputError(bad(faceSet(points, "")), {"bad.wrl: no faces"});
    expectInputError(bad(faceSet("0 0 0,\n1 nan 0,\n0 1 0", "0 1 2")), {"bad.wrl:7:", "non-finite"});
    expectInputError(bad(faceSet("0 0 0,\n1 0 0,\n0 1 Infinity", "0 1 2")), {"bad.wrl:8:", "Infinity"});
    expectInputError(bad(faceSet("0 0 0,\n1 0 0,\n0 1", "0 1 2")), {"bad.wrl:5:", "not a multiple of 3"});
    expectInputError(bad(faceSet(points, "0 1 2 -1\n1 3 7 -1")),
                     {"bad.wrl:14:", "coordIndex index 7 out of range (4 points)"});
    expectInputError(bad(faceSet(points, "0 1 2 -1\n1 3 -2 -1")),
                     {"bad.wrl:14:", "negative coordIndex index -2"});
    expectInputError(bad(faceSet(points, "0 1 2 -1\n1 3 -1")), {"bad.wrl:14:", "face 1 has 2 corner(s)"});
    expectInputError(bad(faceSet(points, "0 1 2 -1\n-1")), {"bad.wrl:14:", "face 1 has 0 corner(s)"});
    expectInputError(bad(faceSet(points, "0 1 2 -1\n1 3 1 -1")),
                     {"bad.wrl:14:", "face 1 is degenerate", "vertex 1"});
    expectInputError(bad(faceSet(points, "0 1 x")), {"bad.wrl:13:", "expected an integer"});
    expectInputError(bad(faceSet(points, "0 1 2", "  texCoord TextureCoordinate { point [ 0 0 1 0 ] }\n")),
                     {"bad.wrl:13:", "texture coordinate index 2 out of range (2 points)"});
    expectInputError(
        bad(faceSet(points, "0 1 2 -1",
                    "  texCoord TextureCoordinate { point [ 0 0 1 0 0 1 ] }\n  texCoordIndex [ 0 1 -1 ]\n")),
        {"bad.wrl:16:", "texCoordIndex does not have the same faces"});
    expectInputError(bad(faceSet(points, "0 1 2", "  coord USE Nowhere\n")),
                     {"bad.wrl:15:", "unknown Coordinate 'Nowhere'"});
    expectInputError(
        bad("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n coord Coordinate { point [ 0 0 0"),
        {"bad.wrl:3:", "unexpected end of file"});
    expectInputError(bad("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n coord Box { }"),
                     {"bad.wrl:3:", "expected a Coordinate node, found 'Box'"});
}

} // namespace
} // namespace vl
