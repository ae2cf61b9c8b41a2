// readMesh/writeMesh: format choice by extension, file errors, atomic saves, bit-exact round
// trips through every format, and identical triangulation of polygons in every format.
#include "core/io/MeshIO.h"
#include "MeshIOTestUtil.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <unistd.h>

namespace vl {
namespace {

namespace fs = std::filesystem;
using test::expectIdenticalMesh;
using test::expectInputError;

class MeshIOFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("visemelab-io-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path file(const std::string& name) const { return dir_ / name; }
    void writeText(const fs::path& path, const std::string& text) const {
        std::ofstream(path, std::ios::binary) << text;
    }

    fs::path dir_;
};

TEST(MeshFormatFromPath, ChoosesByExtensionInAnyCase) {
    EXPECT_EQ(meshFormatFromPath("a/b.obj"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatFromPath("B.OBJ"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatFromPath("x.ply"), MeshFormat::Ply);
    EXPECT_EQ(meshFormatFromPath("x.wrl"), MeshFormat::Vrml);
    EXPECT_EQ(meshFormatFromPath("x.VRML"), MeshFormat::Vrml);
    EXPECT_TRUE(isMeshFile("face.Wrl"));
    EXPECT_FALSE(isMeshFile("face.stl"));
    EXPECT_FALSE(isMeshFile("obj"));
    expectInputError([] { meshFormatFromPath("dir/face.stl"); },
                     {"dir/face.stl", "unknown mesh format '.stl'"});
    expectInputError([] { meshFormatFromPath("noextension"); }, {"noextension", "unknown mesh format"});
}

TEST_F(MeshIOFiles, RoundTripsEveryFormatBitExactlyInVertexOrder) {
    for (const char* ext : {".obj", ".ply", ".wrl"}) {
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            SCOPED_TRACE(std::string(ext) + " seed " + std::to_string(seed));
            const MeshData mesh =
                test::randomMesh(seed * 977, 200 + seed * 31, 400 + seed * 17, seed % 2 == 0);
            const fs::path path = file("mesh" + std::to_string(seed) + ext);
            writeMesh(path, mesh);
            const MeshData back = readMesh(path);
            expectIdenticalMesh(mesh, back);
            // Writing what was read gives the same bytes: nothing drifts over repeated saves.
            writeMesh(file("again" + std::string(ext)), back);
            std::ifstream a(path, std::ios::binary), b(file("again" + std::string(ext)), std::ios::binary);
            EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}),
                      std::string(std::istreambuf_iterator<char>(b), {}));
        }
    }
}

TEST_F(MeshIOFiles, PolygonsTriangulateIdenticallyInEveryFormat) {
    // A quad, a pentagon and a triangle over 6 vertices, written by hand in each format.
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 0\nv 3 0 1\n"
                            "f 1 2 3 4\nf 2 6 5 3 4\nf 6 1 4\n";
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\n"
        "property double z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n3 0 1\n4 0 1 2 3\n5 1 5 4 2 3\n3 5 0 3\n";
    const std::string wrl = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n"
                            " coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 2 2 0, 3 0 1 ] }\n"
                            " coordIndex [ 0 1 2 3 -1 1 5 4 2 3 -1 5 0 3 -1 ] } }\n";
    writeText(file("p.obj"), obj);
    writeText(file("p.ply"), ply);
    writeText(file("p.wrl"), wrl);
    const std::vector<Triangle> fan{{0, 1, 2}, {0, 2, 3}, {1, 5, 4}, {1, 4, 2}, {1, 2, 3}, {5, 0, 3}};
    const MeshData fromObj = readMesh(file("p.obj"));
    EXPECT_EQ(fromObj.triangles, fan);
    expectIdenticalMesh(fromObj, readMesh(file("p.ply")));
    expectIdenticalMesh(fromObj, readMesh(file("p.wrl")));
    // and the written files of each format read back to the same triangles
    for (const char* ext : {".obj", ".ply", ".wrl"}) {
        writeMesh(file(std::string("out") + ext), fromObj);
        expectIdenticalMesh(fromObj, readMesh(file(std::string("out") + ext)));
    }
}

TEST_F(MeshIOFiles, RejectsMissingEmptyAndUnknownFilesNamingThem) {
    const std::string missing = file("missing.obj").string();
    expectInputError([&] { readMesh(missing); }, {missing, "not found"});
    for (const char* name : {"empty.obj", "empty.ply", "empty.wrl"}) {
        writeText(file(name), "");
        const std::string path = file(name).string();
        expectInputError([&] { readMesh(path); }, {path + ": empty file"});
    }
    writeText(file("cube.stl"), "solid cube\n");
    expectInputError([&] { readMesh(file("cube.stl")); }, {"cube.stl", "unknown mesh format"});
    expectInputError([&] { readMesh(dir_); }, {"unknown mesh format"});
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 2}};
    expectInputError([&] { writeMesh(file("out.stl"), mesh); }, {"out.stl", "unknown mesh format"});
}

TEST_F(MeshIOFiles, WritesAtomicallyReplacingTheOldFileAndLeavingNoTemporaries) {
    const MeshData first = test::randomMesh(1, 30, 40, true);
    const MeshData second = test::randomMesh(2, 50, 70, false);
    writeMesh(file("m.obj"), first);
    writeMesh(file("m.obj"), second);
    expectIdenticalMesh(second, readMesh(file("m.obj")));
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 1u);
}

TEST(MeshWriters, RejectMeshesThatWouldNotReadBack) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 3}};
    for (const auto& format : {formatObj, formatPly, formatVrml})
        expectInputError([&] { format(mesh); }, {"mesh to write", "triangle 0", "out of range"});
    mesh.triangles = {{0, 1, 2}};
    mesh.uvs = {Vec2(0, 0)};
    expectInputError([&] { formatObj(mesh); }, {"mesh to write", "1 (u,v) pairs for 3 vertices"});
    mesh.uvs.clear();
    mesh.positions[1][2] = std::numeric_limits<double>::infinity();
    expectInputError([&] { formatVrml(mesh); }, {"mesh to write", "vertex 1", "non-finite"});
}

// Random awkward doubles (test::randomDouble) brought within float32's range: the ones beyond it
// are replaced by their remainder modulo 1e30, which keeps a full mantissa.
std::vector<Vec3> withinFloat32Range(std::vector<Vec3> positions) {
    for (Vec3& p : positions)
        for (int k = 0; k < 3; ++k)
            if (std::abs(p[k]) > std::numeric_limits<float>::max()) p[k] = std::fmod(p[k], 1e30);
    return positions;
}

TEST(MeshTextFormatter, EqualsFormatMeshForEveryMeshOfTheTopology) {
    for (const PositionPrecision precision : {PositionPrecision::Exact, PositionPrecision::Float32})
        for (const bool uvs : {false, true}) {
            const MeshData topology = test::randomMesh(uvs ? 5 : 6, 30, 50, uvs);
            for (const char* name : {"a.obj", "a.wrl", "a.ply"}) {
                const MeshTextFormatter formatter(name, topology, precision);
                for (std::uint64_t seed = 10; seed < 13; ++seed) {
                    MeshData mesh = topology;
                    mesh.positions = withinFloat32Range(test::randomMesh(seed, 30, 10, false).positions);
                    EXPECT_EQ(formatMesh(name, mesh, precision), formatter.format(mesh.positions))
                        << name << " seed " << seed << " float32 "
                        << (precision == PositionPrecision::Float32);
                }
            }
        }
}

// Key meshes (docs/export.md): every coordinate reads back as the same float32, (u,v) and faces
// exactly, in every format; the text is shorter than a double's, and the bundled sample's first
// vertex (read from text with 7-8 digits) is written back as the same text.
TEST(MeshWriters, Float32PositionsReadBackAsTheSameFloats) {
    for (std::uint64_t seed = 20; seed < 26; ++seed) {
        MeshData mesh = test::randomMesh(seed, 40, 60, seed % 2 == 0);
        mesh.positions = withinFloat32Range(mesh.positions);
        for (const char* name : {"a.obj", "a.wrl", "a.ply"}) {
            SCOPED_TRACE(std::string(name) + " seed " + std::to_string(seed));
            const std::string text = formatMesh(name, mesh, PositionPrecision::Float32);
            const std::string source(name);
            const MeshData back = source.ends_with(".obj")   ? parseObj(text, source)
                                  : source.ends_with(".wrl") ? parseVrml(text, source)
                                                             : parsePly(text, source);
            test::expectSameFloat32Positions(mesh.positions, back.positions);
            MeshData exact = back; // (u,v) and faces compared bit for bit
            exact.positions = mesh.positions;
            test::expectIdenticalMesh(mesh, exact);
            if (!source.ends_with(".ply")) {
                EXPECT_LT(text.size(), formatMesh(name, mesh).size());
            }
        }
    }
    MeshData sample;
    sample.positions = {Vec3(-3.970852, -12.144, -12.833978), Vec3(1, 0, 0), Vec3(0, 1e-3, 0.5)};
    sample.triangles = {{0, 1, 2}};
    const std::string obj = formatMesh("a.obj", sample, PositionPrecision::Float32);
    EXPECT_NE(obj.find("\nv -3.970852 -12.144 -12.833978\nv 1 0 0\nv 0 0.001 0.5\n"), std::string::npos)
        << obj;
    // A mean: 16-17 significant digits as a double, at most 9 as float32.
    sample.positions[1] = Vec3(1.0 / 3.0, 0, 0);
    EXPECT_NE(formatObj(sample).find("\nv 0.3333333333333333 0 0\n"), std::string::npos);
    EXPECT_NE(formatMesh("a.obj", sample, PositionPrecision::Float32).find("\nv 0.33333334 0 0\n"),
              std::string::npos);
}

TEST(MeshWriters, Float32RefusesCoordinatesBeyondItsRange) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, -1e39, 0)};
    mesh.triangles = {{0, 1, 2}};
    EXPECT_NO_THROW(formatObj(mesh)); // a double holds it
    for (const char* name : {"a.obj", "a.wrl", "a.ply"}) {
        expectInputError([&] { formatMesh(name, mesh, PositionPrecision::Float32); },
                         {"mesh to write", "vertex 2", "float32"});
        const MeshTextFormatter formatter(name,
                                          {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {}, mesh.triangles},
                                          PositionPrecision::Float32);
        expectInputError([&] { formatter.format(mesh.positions); }, {"mesh to write", "vertex 2", "float32"});
    }
}

// Positions formatted once (PositionText) give the same files, and a coordinate copied from the
// reference's text is the text formatting it gives: equal bits reuse it; -0 and 0, or doubles that
// differ but round to one float, are told apart exactly as the precision tells them apart.
TEST(PositionText, ReusingTheReferenceGivesTheTextOfFormattingEveryCoordinate) {
    for (const PositionPrecision precision : {PositionPrecision::Exact, PositionPrecision::Float32})
        for (std::uint64_t seed = 30; seed < 34; ++seed) {
            SCOPED_TRACE("seed " + std::to_string(seed) + " float32 " +
                         std::to_string(precision == PositionPrecision::Float32));
            const MeshData topology = test::randomMesh(seed, 40, 60, seed % 2 == 0);
            const std::vector<Vec3> base = withinFloat32Range(topology.positions);
            std::vector<Vec3> moved =
                withinFloat32Range(test::randomMesh(seed + 100, 40, 10, false).positions);
            for (std::size_t i = 0; i < moved.size(); ++i)
                for (int k = 0; k < 3; ++k) {
                    const double b = base[i][k];
                    switch ((i * 3 + static_cast<std::size_t>(k)) % 5) {
                    case 0: // unmoved
                    case 1:
                        moved[i][k] = b;
                        break;
                    case 2: // the same float, another double (where there is one)
                        moved[i][k] = std::nextafter(b, 0.0) == 0.0 ? b : std::nextafter(b, 0.0);
                        break;
                    case 3: // zero of the other sign
                        moved[i][k] = b == 0.0 ? -b : moved[i][k];
                        break;
                    default: // moved
                        break;
                    }
                }
            const PositionText reference(base, precision);
            const PositionText reused(moved, precision, &reference), fresh(moved, precision);
            ASSERT_EQ(reused.vertexCount(), moved.size());
            for (std::size_t i = 0; i < moved.size(); ++i) {
                ASSERT_EQ(reused.vertex(i), fresh.vertex(i)) << "vertex " << i;
                for (int k = 0; k < 3; ++k) {
                    char buffer[32];
                    const auto end =
                        precision == PositionPrecision::Float32
                            ? std::to_chars(buffer, buffer + 32, static_cast<float>(moved[i][k])).ptr
                            : std::to_chars(buffer, buffer + 32, moved[i][k]).ptr;
                    ASSERT_EQ(reused.coordinate(i, k), std::string_view(buffer, end));
                }
            }
            MeshData mesh = topology;
            mesh.positions = moved;
            for (const char* name : {"a.obj", "a.wrl", "a.ply"}) {
                const MeshTextFormatter formatter(name, topology, precision);
                std::string text, buffer;
                formatter.format(reused, text);
                EXPECT_EQ(text, formatMesh(name, mesh, precision)) << name;
                const MeshTextFormatter::Parts file = formatter.parts(reused, buffer);
                EXPECT_EQ(std::string(file.head) + std::string(file.middle) + std::string(file.tail), text)
                    << name;
            }
        }
    // A reference of another precision or size is not used.
    const std::vector<Vec3> one{Vec3(1.0 / 3.0, 0, 0)};
    const PositionText exact(one, PositionPrecision::Exact);
    EXPECT_EQ(PositionText(one, PositionPrecision::Float32, &exact).vertex(0), "0.33333334 0 0");
    const MeshTextFormatter formatter("a.obj",
                                      {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {}, {{0, 1, 2}}},
                                      PositionPrecision::Float32);
    std::string text;
    EXPECT_THROW(formatter.format(exact, text), std::invalid_argument);
}

// appendLines against the lines built one by one: short and long separators and prefixes (the
// padded copies have a limit), text already in the output, and a PositionText reused for a smaller
// mesh after a larger one.
TEST(PositionText, AppendLinesJoinsEveryVertexWithItsPrefixAndSeparator) {
    PositionText text;
    for (const std::size_t count : {std::size_t{300}, std::size_t{1}, std::size_t{57}}) {
        const std::vector<Vec3> positions =
            withinFloat32Range(test::randomMesh(7 + count, count, 0, false).positions);
        for (const PositionPrecision precision : {PositionPrecision::Exact, PositionPrecision::Float32}) {
            text.assign(positions, precision);
            const std::string longText(40, '#');
            for (const auto& [prefix, separator, last] : std::vector<std::array<std::string, 3>>{
                     {"v ", "\n", "\n"}, {"", ",\n", "\n"}, {longText, "\n", ""}, {"<", longText, ">"}}) {
                std::string expected = "head:";
                for (std::size_t i = 0; i < count; ++i)
                    expected += prefix + std::string(text.vertex(i)) + (i + 1 < count ? separator : last);
                std::string out = "head:";
                text.appendLines(out, prefix, separator, last);
                ASSERT_EQ(out, expected) << count << " vertices, prefix '" << prefix << "'";
            }
        }
    }
}

TEST(MeshTextFormatter, RejectsNonFinitePositionsAndOtherVertexCounts) {
    const MeshData topology = test::randomMesh(3, 6, 4, true);
    const MeshTextFormatter formatter("a.obj", topology, PositionPrecision::Exact);
    std::vector<Vec3> positions = topology.positions;
    positions[4][1] = std::numeric_limits<double>::quiet_NaN();
    expectInputError([&] { formatter.format(positions); }, {"mesh to write", "vertex 4", "non-finite"});
    positions.pop_back();
    EXPECT_THROW(formatter.format(positions), std::invalid_argument);
}

} // namespace
} // namespace vl

namespace vl {
namespace {

// A vertex no face uses keeps its position everywhere and its (u,v) in PLY and VRML; OBJ has no
// way to store it, so it reads back as (0,0) (documented in MeshIO.h).
TEST(MeshWriters, KeepVerticesNoFaceUses) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.1, 0.2, 0.3)};
    mesh.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(0.3, 0.7)};
    mesh.triangles = {{0, 1, 2}};
    test::expectIdenticalMesh(mesh, parsePly(formatPly(mesh), "iso.ply"));
    test::expectIdenticalMesh(mesh, parseVrml(formatVrml(mesh), "iso.wrl"));
    MeshData objExpected = mesh;
    objExpected.uvs[3] = Vec2(0, 0);
    test::expectIdenticalMesh(objExpected, parseObj(formatObj(mesh), "iso.obj"));
}

} // namespace
} // namespace vl
