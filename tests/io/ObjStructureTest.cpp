// Reading a viseme against its neutral mesh's OBJ structure (readMeshLike): whatever the file, the
// result is readMesh's, and the positions-only path is taken exactly when only `v` numbers differ.
#include "MeshIOTestUtil.h"
#include "core/common/TextParsing.h"
#include "core/io/MeshIO.h"

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace vl {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        lines.push_back(text.substr(pos, end - pos));
        pos = end + 1;
    }
    return lines;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    return text;
}

// The reference: a random mesh with (u,v), a comment, a group and a smoothing line among its lines.
std::string referenceText(std::uint64_t seed) {
    std::vector<std::string> lines = splitLines(formatObj(test::randomMesh(seed, 12, 20, seed % 2 == 0)));
    lines.insert(lines.begin() + 1, "g face");
    lines.insert(lines.begin() + 5, "# a comment between vertices");
    lines.push_back("s off");
    return joinLines(lines);
}

// The outcome of parsing `text`: the mesh, or the error message.
struct Parsed {
    std::optional<MeshData> mesh;
    std::string error;
};

Parsed parseFully(const std::string& text) {
    try {
        return {parseObj(text, "viseme.obj"), {}};
    } catch (const InputError& e) {
        return {std::nullopt, e.what()};
    }
}

// What readMeshLike does with `text` against the reference, and whether it took the fast path.
Parsed parseLike(const std::string& text, const std::string& reference, bool& fast) {
    const MeshData ref = parseObj(reference, "neutral.obj");
    try {
        if (auto positions = parseObjPositionsMatching(text, "viseme.obj", objStructure(reference))) {
            fast = true;
            return {MeshData{std::move(*positions), ref.uvs, ref.triangles}, {}};
        }
        fast = false;
        return parseFully(text);
    } catch (const InputError& e) {
        fast = true;
        return {std::nullopt, e.what()};
    }
}

void expectSameOutcome(const Parsed& expected, const Parsed& actual, const std::string& what) {
    ASSERT_EQ(expected.mesh.has_value(), actual.mesh.has_value())
        << what << ": " << expected.error << actual.error;
    if (expected.mesh)
        test::expectIdenticalMesh(*expected.mesh, *actual.mesh);
    else
        EXPECT_EQ(expected.error, actual.error) << what;
}

TEST(ObjStructure, PositionsOnlyParseEqualsTheFullParseForRandomVariants) {
    std::mt19937_64 rng(2026);
    int fastCount = 0, slowCount = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const std::string reference = referenceText(seed);
        const std::vector<std::string> lines = splitLines(reference);
        for (int variant = 0; variant < 12; ++variant) {
            std::vector<std::string> edited = lines;
            const std::size_t at = rng() % edited.size();
            const bool vertexLine = edited[at].starts_with("v ");
            bool structureKept = true;
            switch (variant % 6) {
            case 0: // new numbers in every v line: the typical viseme
                for (auto& line : edited)
                    if (line.starts_with("v ")) {
                        line = "v " + formatDouble(test::randomDouble(rng)) + " " +
                               formatDouble(test::randomDouble(rng)) + " 0.5 # moved";
                    }
                break;
            case 1: // a colour after the coordinates and other spacing
                if (vertexLine) edited[at] = "  v\t1 2 3 0.1 0.2 0.3";
                break;
            case 2: // one index of one face line changed, or any non-v line altered
                edited[at] = vertexLine ? edited[at] : edited[at] + " 1";
                structureKept = vertexLine;
                break;
            case 3: // an extra vertex, or a line less
                if (rng() % 2)
                    edited.insert(edited.begin() + static_cast<std::ptrdiff_t>(at), "v 0 0 0");
                else
                    edited.erase(edited.begin() + static_cast<std::ptrdiff_t>(at));
                structureKept = false;
                break;
            case 4: { // a broken vertex line, or a comment cutting into one: the same outcome either way
                static const char* const kOddVertexLines[] = {"v 1 nan-ish", "v#1 2 3", "v 1 2#3",
                                                              "v 1 2 3#"};
                if (vertexLine) edited[at] = kOddVertexLines[rng() % std::size(kOddVertexLines)];
                break;
            }
            case 5: // a byte order mark only in the viseme
                edited.front() = "\xEF\xBB\xBF" + edited.front();
                structureKept = false;
                break;
            }
            const std::string text = joinLines(edited);
            bool fast = false;
            const Parsed like = parseLike(text, reference, fast);
            const std::string what = "seed " + std::to_string(seed) + " variant " + std::to_string(variant);
            expectSameOutcome(parseFully(text), like, what);
            if (structureKept) {
                EXPECT_TRUE(fast) << what << ": only v numbers differ";
            }
            (fast ? fastCount : slowCount) += 1;
        }
    }
    EXPECT_GT(fastCount, 100);
    EXPECT_GT(slowCount, 50);
}

TEST(ObjStructure, CrLfAgainstLfIsParsedFully) {
    const std::string reference = referenceText(3);
    std::string crlf;
    for (const char c : reference) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    bool fast = true;
    expectSameOutcome(parseFully(crlf), parseLike(crlf, reference, fast), "crlf");
    EXPECT_FALSE(fast);
}

TEST(ObjStructure, ReadMeshLikeEqualsReadMeshOnFiles) {
    const fs::path dir = fs::temp_directory_path() / ("visemelab-objstructure-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string reference = referenceText(7);
    std::vector<std::string> lines = splitLines(reference);
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].starts_with("v ")) lines[i] = "v " + std::to_string(i) + " 2 3"; // new positions
    const std::string viseme = joinLines(lines);
    // The last face's corners rotated: the same triangle, other triangle data.
    const std::size_t lastFace = reference.rfind("\nf ") + 1;
    const std::size_t end = reference.find('\n', lastFace);
    std::istringstream corners(reference.substr(lastFace + 2, end - lastFace - 2));
    std::string a, b, c;
    corners >> a >> b >> c;
    const std::string other =
        reference.substr(0, lastFace) + "f " + b + " " + c + " " + a + reference.substr(end);
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
        return dir / name;
    };
    const ReferenceMesh ref = readReferenceMesh(write("neutral.obj", reference));
    test::expectIdenticalMesh(readMesh(dir / "neutral.obj"), ref.mesh);
    for (const auto& [name, text] : {std::pair{"a.obj", viseme}, std::pair{"b.obj", other}}) {
        const fs::path path = write(name, text);
        test::expectIdenticalMesh(readMesh(path), readMeshLike(path, ref));
        // Without the copies: the fast path (the viseme) leaves the reference's faces and (u,v) out.
        const MeshLike read = readPositionsLike(path, ref);
        EXPECT_EQ(read.sameTopology, name == std::string("a.obj")) << name;
        MeshData full = read.mesh;
        if (read.sameTopology) {
            EXPECT_TRUE(read.mesh.triangles.empty() && read.mesh.uvs.empty());
            full.triangles = ref.mesh.triangles;
            full.uvs = ref.mesh.uvs;
        }
        test::expectIdenticalMesh(readMesh(path), full);
    }
    // A binary PLY of the reference's faces (and no (u,v)) keeps only its positions too.
    writeMesh(dir / "c.ply", readMesh(dir / "a.obj"));
    test::expectIdenticalMesh(readMesh(dir / "c.ply"), readMeshLike(dir / "c.ply", ref));
    const MeshLike ply = readPositionsLike(dir / "c.ply", ref);
    EXPECT_EQ(ply.sameTopology, ref.mesh.uvs.empty());
    if (ply.sameTopology) {
        EXPECT_EQ(ply.mesh.positions, readMesh(dir / "c.ply").positions);
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace vl
