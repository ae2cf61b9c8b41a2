// OBJ reader: supported syntax, (u,v) rules, every rejected input, and agreement with a slow,
// obvious reference parser on random files.
#include "MeshIOTestUtil.h"
#include "core/common/TextParsing.h"
#include "core/io/MeshIO.h"

#include <cstdlib>
#include <sstream>
#include <vector>

namespace vl {
namespace {

using test::expectIdenticalMesh;
using test::expectInputError;

TEST(ObjFormat, ReadsCornerFormsNegativeIndicesAndFanTriangulation) {
    const std::string text = "# a quad and a pentagon\n"
                             "mtllib x.mtl\no thing\ng group\ns 1\nusemtl skin\n"
                             "v 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nv 2 2 2\n"
                             "vn 0 0 1\n"
                             "f 1 2 3 4\n"
                             "f -5//1 -4//1 -3//1 -2//1 -1//1\n";
    const MeshData mesh = parseObj(text, "t.obj");
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.positions[2], Vec3(1, 1, 0));
    EXPECT_FALSE(mesh.hasUVs());
    const std::vector<Triangle> expected{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(ObjFormat, EachVertexTakesTheUVOfItsFirstCornerAndSeamsKeepTheFirst) {
    // vt indices differ from v indices (as in MediaPipe's file); vertex 3 sits on a seam.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\n"
                             "vt 0.1 0.2\nvt 0.3 0.4\nvt 0.5 0.6\nvt 0.7 0.8\nvt 0.9\n"
                             "f 1/4/1 2/3 3/2/1\n"
                             "f 1/1 3/5 4/1\n"; // vertices 1 and 3 already have a uv: first one kept
    const MeshData mesh = parseObj(text, "t.obj");
    ASSERT_EQ(mesh.uvs.size(), 5u);
    EXPECT_EQ(mesh.uvs[0], Vec2(0.7, 0.8));
    EXPECT_EQ(mesh.uvs[1], Vec2(0.5, 0.6));
    EXPECT_EQ(mesh.uvs[2], Vec2(0.3, 0.4));
    EXPECT_EQ(mesh.uvs[3], Vec2(0.1, 0.2));
    EXPECT_EQ(mesh.uvs[4], Vec2(0.0, 0.0)); // used by no face: (0,0)
}

TEST(ObjFormat, AcceptsBomCrLfTabsPlusSignsCommentsAndForwardReferences) {
    const std::string text = "\xEF\xBB\xBF"
                             "fo 1 2 3 # old spelling\r\nv\t+1 2 3#c\r\nv 4 5 6 \r\n  v 7 8 9\r\n";
    const MeshData mesh = parseObj(text, "t.obj");
    ASSERT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.positions[0], Vec3(1, 2, 3));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(ObjFormat, RejectsBadInputNamingFileAndLine) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const auto bad = [](std::string text) { return [text] { parseObj(text, "bad.obj"); }; };
    expectInputError(bad(""), {"bad.obj: empty file"});
    expectInputError(bad(" \n\t\n"), {"bad.obj: empty file"});
    expectInputError(bad("# only a comment\n"), {"bad.obj: no vertices"});
    expectInputError(bad(tri), {"bad.obj: no faces"});
    expectInputError(bad("v 0 0 0\nv 1 nan 0\n"), {"bad.obj:2:", "non-finite", "nan"});
    expectInputError(bad("v 0 0 0\nv 1 0 inf\n"), {"bad.obj:2:", "non-finite", "inf"});
    expectInputError(bad("v 0 0 0\nv 1 0 -inf\n"), {"bad.obj:2:", "non-finite"});
    expectInputError(bad("v 0 0 0\nvt NaN 0\n"), {"bad.obj:2:", "non-finite"});
    expectInputError(bad("v 1 2\n"), {"bad.obj:1:", "3 coordinates"});
    expectInputError(bad("v 1 x 2\n"), {"bad.obj:1:", "expected a number", "'x'"});
    expectInputError(bad("v 1 1e999 2\n"), {"bad.obj:1:", "out of range"});
    expectInputError(bad(tri + "f 1 2 4\n"), {"bad.obj:4:", "vertex index 4 out of range (3 vertices)"});
    expectInputError(bad(tri + "f 1 2 3\nf 3 2 9\n"), {"bad.obj:5:", "vertex index 9 out of range"});
    expectInputError(bad(tri + "f 0 1 2\n"), {"bad.obj:4:", "index 0 is invalid"});
    expectInputError(bad(tri + "f -1 -2 -4\n"), {"bad.obj:4:", "relative vertex index -4"});
    expectInputError(bad(tri + "f 1 2\n"), {"bad.obj:4:", "face 0 has 2 corner(s)"});
    expectInputError(bad(tri + "f\n"), {"bad.obj:4:", "face 0 has 0 corner(s)"});
    expectInputError(bad(tri + "f 1 2 3\nf 1 2 1\n"), {"bad.obj:5:", "face 1 is degenerate", "vertex 1"});
    expectInputError(bad(tri + "vt 0 0\nf 1/1 2/2 3/1\n"),
                     {"bad.obj:5:", "texture coordinate index 2 out of range"});
    expectInputError(bad(tri + "f 1/ 2 3\n"), {"bad.obj:4:", "malformed face corner '1/'"});
    expectInputError(bad(tri + "f 1// 2 3\n"), {"bad.obj:4:", "malformed face corner"});
    expectInputError(bad(tri + "f /1 2 3\n"), {"bad.obj:4:", "malformed face corner"});
    expectInputError(bad(tri + "f 1 2 three\n"), {"bad.obj:4:", "expected an integer"});
    expectInputError(bad(tri + "V 1 2 3\nf 1 2 3\n"), {"bad.obj:4:", "unknown OBJ statement 'V'"});
    expectInputError(bad(tri + "vx 1 2 3\nf 1 2 3\n"), {"bad.obj:4:", "unknown OBJ statement 'vx'"});
    expectInputError(bad(tri + "f 1 2 \\\n 3\n"), {"bad.obj:4:", "expected an integer, found '\\'"});
}

// ---- reference: a deliberately plain parser (istringstream, strtod), no shortcuts ----

MeshData referenceParseObj(const std::string& text) {
    std::vector<Vec3> positions;
    std::vector<Vec2> texCoords;
    std::vector<std::vector<std::pair<long, long>>> faces; // resolved 0-based (v, vt or -1)
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        std::string keyword;
        in >> keyword;
        if (keyword == "v") {
            std::string x, y, z;
            in >> x >> y >> z;
            positions.emplace_back(std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr),
                                   std::strtod(z.c_str(), nullptr));
        } else if (keyword == "vt") {
            std::string u, v;
            in >> u >> v;
            texCoords.emplace_back(std::strtod(u.c_str(), nullptr),
                                   v.empty() ? 0.0 : std::strtod(v.c_str(), nullptr));
        } else if (keyword == "f") {
            std::vector<std::pair<long, long>> face;
            std::string corner;
            while (in >> corner) {
                std::string parts[3];
                int part = 0;
                for (const char c : corner) {
                    if (c == '/')
                        ++part;
                    else
                        parts[part] += c;
                }
                const long v = std::stol(parts[0]);
                const long t = parts[1].empty() ? 0 : std::stol(parts[1]);
                face.emplace_back(v > 0 ? v - 1 : static_cast<long>(positions.size()) + v,
                                  t == 0 ? -1 : (t > 0 ? t - 1 : static_cast<long>(texCoords.size()) + t));
            }
            faces.push_back(face);
        }
    }
    MeshData mesh;
    mesh.positions = positions;
    std::vector<long> firstUV(positions.size(), -1);
    bool anyUV = false;
    for (const auto& face : faces) {
        for (const auto& [v, t] : face)
            if (t >= 0) {
                anyUV = true;
                if (firstUV[v] < 0) firstUV[v] = t;
            }
        for (std::size_t k = 2; k < face.size(); ++k)
            mesh.triangles.push_back({static_cast<std::uint32_t>(face[0].first),
                                      static_cast<std::uint32_t>(face[k - 1].first),
                                      static_cast<std::uint32_t>(face[k].first)});
    }
    if (anyUV)
        for (std::size_t v = 0; v < positions.size(); ++v)
            mesh.uvs.push_back(firstUV[v] < 0 ? Vec2(0, 0) : texCoords[static_cast<std::size_t>(firstUV[v])]);
    return mesh;
}

// A random valid OBJ file mixing every corner form, relative indices, polygons, statements the
// reader ignores, odd spacing and CRLF line ends, with faces interleaved between vertices.
std::string randomObjText(std::mt19937_64& rng) {
    std::ostringstream out;
    const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
    const char* eol = pick(2) ? "\n" : "\r\n";
    const std::string space = pick(2) ? " " : " \t ";
    std::size_t vertices = 0, texCoords = 0;
    const bool useUVs = pick(4) != 0;
    for (int block = 0; block < 4; ++block) {
        const std::size_t newVertices = 3 + pick(30);
        for (std::size_t i = 0; i < newVertices; ++i) {
            out << "v" << space << formatDouble(test::randomDouble(rng)) << space
                << formatDouble(test::randomDouble(rng)) << space << formatDouble(test::randomDouble(rng))
                << (pick(5) == 0 ? " 1.0" : "") << eol;
            if (useUVs && pick(3) != 0) {
                out << "vt " << formatDouble(test::randomDouble(rng)) << " "
                    << formatDouble(test::randomDouble(rng)) << eol;
                ++texCoords;
            }
            if (pick(10) == 0) out << (pick(2) ? "vn 0 0 1" : "# comment f 1 2 3") << eol;
        }
        vertices += newVertices;
        if (pick(6) == 0) out << "g part" << block << eol << "usemtl m" << eol << "s off" << eol;
        const std::size_t faces = 1 + pick(20);
        for (std::size_t f = 0; f < faces; ++f) {
            const std::size_t corners = std::min<std::size_t>(vertices, 3 + pick(4));
            std::vector<std::size_t> order(vertices);
            std::iota(order.begin(), order.end(), std::size_t{0});
            std::shuffle(order.begin(), order.end(), rng);
            out << "f";
            for (std::size_t c = 0; c < corners; ++c) {
                const std::size_t v = order[c];
                const auto index = [&](std::size_t i, std::size_t count) {
                    return pick(3) == 0 ? std::to_string(static_cast<long>(i) - static_cast<long>(count))
                                        : std::to_string(i + 1);
                };
                out << space << index(v, vertices);
                const bool withUV = texCoords > 0 && pick(4) != 0;
                const std::size_t form = pick(3); // 0: none extra, 1: normal, 2: normal index too
                if (withUV) out << "/" << index(pick(texCoords), texCoords);
                if (form == 1 && !withUV) out << "//1";
                if (form == 2 && withUV) out << "/1";
            }
            out << eol;
        }
    }
    return out.str();
}

TEST(ObjFormat, AgreesWithReferenceParserOnRandomFiles) {
    std::mt19937_64 rng(20261121);
    for (int trial = 0; trial < 300; ++trial) {
        const std::string text = randomObjText(rng);
        SCOPED_TRACE("trial " + std::to_string(trial) + ":\n" + text.substr(0, 400));
        expectIdenticalMesh(referenceParseObj(text), parseObj(text, "random.obj"));
        if (HasFatalFailure()) return;
    }
}

TEST(ObjFormat, WritesFacesWithUVIndicesOnlyWhenThereAreUVs) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 2}};
    EXPECT_NE(formatObj(mesh).find("\nf 1 2 3\n"), std::string::npos);
    EXPECT_EQ(formatObj(mesh).find("vt "), std::string::npos);
    mesh.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
    EXPECT_NE(formatObj(mesh).find("\nf 1/1 2/2 3/3\n"), std::string::npos);
    EXPECT_NE(formatObj(mesh).find("\nvt 1 0\n"), std::string::npos);
}

TEST(ObjFormat, RoundTripIsBitExact) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const MeshData mesh = test::randomMesh(seed, 50 + seed * 7, 100 + seed * 3, seed % 2 == 0);
        expectIdenticalMesh(mesh, parseObj(formatObj(mesh), "roundtrip.obj"));
    }
}

} // namespace
} // namespace vl
