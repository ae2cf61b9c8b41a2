// Hostile mesh files: counts and indices that would allocate gigabytes from a few bytes, and VRML
// DEF/USE amplification, are refused before allocating, naming the file and the element.
#include "MeshIOTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/common/Limits.h"
#include "core/io/MeshIO.h"

#include <filesystem>

namespace vl {
namespace {

using test::expectInputError;

TEST(HostileMesh, ObjHugeForwardIndexAllocatesNothing) {
    // 60 bytes that used to grow a per-vertex table to 4 billion entries (32 GB) before the range check.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 4000000000/1\n";
    expectInputError([&] { parseObj(text, "huge.obj"); },
                     {"huge.obj:5: vertex index 4000000000 out of range (3 vertices)"});
    expectInputError([&] { parseObj("vt 0 0\nf 1/1 2/1 999999999/1\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "f.obj"); },
                     {"f.obj:2: vertex index 999999999 out of range (3 vertices)"});
}

TEST(HostileMesh, ObjForwardReferencesKeepTheFirstCornersTextureCoordinate) {
    // Faces before the vertices they use: the first corner in file order still gives the (u,v).
    const std::string text = "vt 0.5 0.5\nvt 0.25 0.75\nf 1/1 2/2 3/1\nf 3/2 2/1 4/2\n"
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 4/1 1/2 2/2\n";
    const MeshData mesh = parseObj(text, "fwd.obj");
    ASSERT_EQ(mesh.uvs.size(), 4u);
    EXPECT_EQ(mesh.uvs[0], Vec2(0.5, 0.5));
    EXPECT_EQ(mesh.uvs[1], Vec2(0.25, 0.75));
    EXPECT_EQ(mesh.uvs[2], Vec2(0.5, 0.5));
    EXPECT_EQ(mesh.uvs[3], Vec2(0.25, 0.75));
}

TEST(HostileMesh, PlyCountsBeyondTheBytesPresentAllocateNothing) {
    // A trillion vertices declared, 64 bytes present: nothing is reserved from the count, and the walk
    // reports where the data ends.
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                               "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    expectInputError([&] { parsePly(header + std::string(64, '\0'), "big.ply"); },
                     {"big.ply: vertex 5: binary data ends early"});
    const std::string ascii =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2000000000\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expectInputError([&] { parsePly(ascii, "faces.ply"); }, {"faces.ply:13: face 1: data ends early"});
    // Exactly enough bytes is fine: the smallest ASCII file has one-character values.
    EXPECT_NO_THROW(parsePly("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                             "end_header\n0 0 0 1 0 0 0 1 0 3 0 1 2",
                             "min.ply"));
}

TEST(HostileMesh, VrmlUseExpansionHasABudget) {
    // One DEF'd Coordinate of 5000 points used by 2000 IndexedFaceSets: 30 M numbers from 110 KB.
    std::string text = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord DEF P Coordinate { point [";
    for (int i = 0; i < 5000; ++i) text += std::to_string(i) + " 0 1,";
    text += "] } coordIndex [0 1 2] } }\n";
    for (int i = 0; i < 2000; ++i)
        text += "Shape { geometry IndexedFaceSet { coord USE P coordIndex [0 1 2] } }\n";
    expectInputError([&] { parseVrml(text, "amp.wrl"); }, {"amp.wrl:", "USE of 'P' would copy", "limit"});
    // A few uses of a shared node are fine.
    std::string few = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord DEF P Coordinate { point "
                      "[0 0 0, 1 0 0, 0 1 0] } coordIndex [0 1 2] } }\n";
    for (int i = 0; i < 3; ++i)
        few += "Shape { geometry IndexedFaceSet { coord USE P coordIndex [0 1 2] } }\n";
    EXPECT_EQ(parseVrml(few, "few.wrl").positions.size(), 12u);
}

TEST(HostileMesh, SpecialAndHugeFilesAreRefusedByName) {
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_hostile_mesh";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "dir.obj");
    expectInputError([&] { readMesh(dir / "dir.obj"); }, {"dir.obj: is a directory"});
    expectInputError([] { readMesh("/dev/null.obj"); }, {"/dev/null.obj: file not found"});
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl
