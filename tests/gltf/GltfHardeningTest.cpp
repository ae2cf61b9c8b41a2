// Hostile glTF files (issue 12's catalogue, for the glTF reader): each ends in an InputError naming
// the file and the element, before anything is allocated for a declared size, written out of
// bounds, or read outside the file's folder.
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/GlbBuilder.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <random>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

std::string sparseFixture() {
    test::AvatarFixtureOptions options;
    options.storage = test::FixtureStorage::Sparse;
    return test::rpmLikeAvatar(options);
}

// The accessor of the head's viseme_aa target (stored sparsely in the fixture).
std::size_t firstSparse(const Json& j) {
    for (const auto& mesh : j["meshes"])
        if (mesh["name"] == "Wolf3D_Head") {
            const auto a = mesh["primitives"][0]["targets"][12]["POSITION"].get<std::size_t>();
            if (!j["accessors"][a].contains("sparse")) throw std::runtime_error("viseme_aa is not sparse");
            return a;
        }
    throw std::runtime_error("no head");
}

std::string withSparse(const std::function<void(Json& accessor, Json& root)>& edit) {
    return test::editGlb(sparseFixture(), [&](Json& j) { edit(j["accessors"][firstSparse(j)], j); });
}

TEST(GltfHardening, SparseIndicesOfTypesTheSpecForbidsAreRefused) {
    for (int type : {5120, 5122, 5126, 5130, 1234}) { // BYTE, SHORT, FLOAT, DOUBLE, junk
        const std::string glb =
            withSparse([&](Json& a, Json&) { a["sparse"]["indices"]["componentType"] = type; });
        test::expectInputError([&] { test::scanGlb(glb); },
                               {"avatar.glb", "sparse indices", "componentType"});
    }
}

TEST(GltfHardening, SparseIndicesOutOfRangeOrOutOfOrderAreRefusedBeforeAnyWrite) {
    // Point the index view at the value bytes (floats read as indices: huge and unordered).
    const std::string junk = withSparse([](Json& a, Json&) {
        a["sparse"]["indices"]["bufferView"] = a["sparse"]["values"]["bufferView"];
        a["sparse"]["indices"]["componentType"] = 5125;
    });
    test::expectInputError([&] { test::scanGlb(junk); }, {"avatar.glb", "sparse indices"});
    const std::string tooMany =
        withSparse([](Json& a, Json&) { a["sparse"]["count"] = a["count"].get<int>() + 1; });
    test::expectInputError([&] { test::scanGlb(tooMany); }, {"avatar.glb", "sparse", "count"});
    const std::string negative = withSparse([](Json& a, Json&) { a["sparse"]["count"] = -5; });
    EXPECT_THROW(test::scanGlb(negative), InputError);
    // Indices that run past their view.
    const std::string past =
        withSparse([](Json& a, Json&) { a["sparse"]["indices"]["byteOffset"] = 1 << 30; });
    test::expectInputError([&] { test::scanGlb(past); }, {"avatar.glb", "sparse indices", "run past"});
}

TEST(GltfHardening, UnsortedSparseIndicesAreRefused) {
    test::GlbBuilder b;
    const std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int pos = b.addFloats(positions, "VEC3", true);
    const std::uint16_t idx[2] = {2, 1};
    const float values[6] = {0, 0, 1, 0, 0, 1};
    const int iv = b.addView(idx, 4), vv = b.addView(values, 24);
    const int target = b.addAccessor(-1, test::kFloat, "VEC3", 3, false, {0, 0, 0}, {0, 0, 1});
    b.json["accessors"][static_cast<std::size_t>(target)]["sparse"] = {
        {"count", 2},
        {"indices", {{"bufferView", iv}, {"componentType", 5123}}},
        {"values", {{"bufferView", vv}}}};
    b.add("meshes",
          {{"primitives", {{{"attributes", {{"POSITION", pos}}}, {"targets", {{{"POSITION", target}}}}}}},
           {"extras", {{"targetNames", {"viseme_aa"}}}}});
    test::expectInputError([&] { test::scanGlb(b.glb()); }, {"avatar.glb", "not strictly increasing"});
}

TEST(GltfHardening, DeeplyNestedExtrasAreRefusedBeforeAnyParserRecurses) {
    for (std::size_t depth : {100ul, 200000ul}) {
        const std::string glb =
            test::editGlb(sparseFixture(), [](Json& j) { j["asset"]["extras"] = "NESTED"; });
        const GlbChunks chunks = splitGlb(glb, "x");
        std::string json(chunks.json);
        const std::string nested = std::string(depth, '[') + std::string(depth, ']');
        json.replace(json.find("\"NESTED\""), 8, nested);
        test::expectInputError([&] { parseGltfDocument(joinGlb(json, chunks.bin), "deep.glb", {}); },
                               {"deep.glb", "nested deeper than"});
    }
    // Up to the limit it reads.
    const std::string ok = test::editGlb(sparseFixture(), [](Json& j) {
        Json v = 1;
        for (int i = 0; i < 50; ++i) v = Json::array({v});
        j["asset"]["extras"] = v;
    });
    EXPECT_NO_THROW(test::scanGlb(ok));
}

TEST(GltfHardening, DeclaredCountsAreCheckedAgainstTheBytesBeforeAllocating) {
    // A small file declaring a billion vertices must fail at once, not allocate gigabytes.
    test::GlbBuilder b;
    const std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int pos = b.addFloats(positions, "VEC3", true);
    const int target = b.addFloats(positions, "VEC3", true);
    b.add("meshes",
          {{"primitives", {{{"attributes", {{"POSITION", pos}}}, {"targets", {{{"POSITION", target}}}}}}},
           {"extras", {{"targetNames", {"viseme_aa"}}}}});
    const std::string small = b.glb();
    ASSERT_LT(small.size(), 2000u);
    EXPECT_NO_THROW(test::scanGlb(small));
    const std::string huge = test::editGlb(small, [](Json& j) { j["accessors"][0]["count"] = 1000000000; });
    test::expectInputError([&] { test::scanGlb(huge); }, {"avatar.glb", "POSITION", "run past buffer view"});
    // A POSITION without a buffer view would be a billion zeros: refused.
    const std::string noView = test::editGlb(huge, [](Json& j) { j["accessors"][0].erase("bufferView"); });
    test::expectInputError([&] { test::scanGlb(noView); }, {"avatar.glb", "POSITION", "no buffer view"});
    // A target declaring more elements than the primitive has vertices.
    const std::string target2 = test::editGlb(small, [](Json& j) {
        j["accessors"][1]["count"] = 1000000000;
        j["accessors"][1].erase("bufferView");
    });
    test::expectInputError([&] { test::scanGlb(target2); }, {"avatar.glb", "targets/0/POSITION", "differs"});
    // Buffers larger than the BIN chunk.
    const std::string buffer =
        test::editGlb(small, [](Json& j) { j["buffers"][0]["byteLength"] = 4000000000u; });
    test::expectInputError([&] { test::scanGlb(buffer); },
                           {"avatar.glb", "buffers/0", "exceeds the BIN chunk"});
    // A view beyond its buffer.
    const std::string view =
        test::editGlb(small, [](Json& j) { j["bufferViews"][0]["byteOffset"] = 1 << 20; });
    test::expectInputError([&] { test::scanGlb(view); }, {"avatar.glb", "bufferViews/0", "outside buffer 0"});
    // Indices out of range.
    const std::uint32_t bad[3] = {0, 1, 7};
    test::GlbBuilder c = b;
    const int indices =
        c.addAccessor(c.addView(bad, 12, test::kElementArrayBuffer), test::kUnsignedInt, "SCALAR", 3, false);
    c.json["meshes"][0]["primitives"][0]["indices"] = indices;
    test::expectInputError([&] { test::scanGlb(c.glb()); }, {"avatar.glb", "indices", "index 7"});
}

TEST(GltfHardening, MeshoptCountsBeyondWhatTheCompressedBytesCanHoldAreRefused) {
    test::AvatarFixtureOptions options;
    options.storage = test::FixtureStorage::Meshopt;
    const std::string glb = test::editGlb(test::rpmLikeAvatar(options), [](Json& j) {
        for (auto& view : j["bufferViews"])
            if (view.contains("extensions")) {
                auto& ext = view["extensions"]["EXT_meshopt_compression"];
                ext["count"] = 100000000;
                view["byteLength"] = 100000000ull * ext["byteStride"].get<std::uint64_t>();
            }
    });
    test::expectInputError([&] { test::scanGlb(glb); },
                           {"avatar.glb", "EXT_meshopt_compression", "cannot hold"});
    const std::string corrupt = test::editGlb(test::rpmLikeAvatar(options), [](Json& j) {
        for (auto& view : j["bufferViews"])
            if (view.contains("extensions")) view["extensions"]["EXT_meshopt_compression"]["byteLength"] = 40;
    });
    test::expectInputError([&] { test::scanGlb(corrupt); }, {"avatar.glb", "EXT_meshopt_compression"});
}

TEST(GltfHardening, NodeCyclesAndSharedChildrenAreRefused) {
    const std::string base = sparseFixture();
    const std::string cycle = test::editGlb(base, [](Json& j) { j["nodes"][4]["children"].push_back(0); });
    test::expectInputError([&] { test::scanGlb(cycle); }, {"avatar.glb", "nodes/"});
    const std::string twoParents =
        test::editGlb(base, [](Json& j) { j["nodes"][0]["children"].push_back(3); });
    test::expectInputError([&] { test::scanGlb(twoParents); }, {"avatar.glb", "already is a child"});
}

class ExternalFiles : public ::testing::Test {
  protected:
    // One folder per test: ctest runs the tests of this fixture in parallel.
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                (std::string("visemelab_gltf_uris_") +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::path folder = dir / "avatar";
    GlbChunks chunks;
    std::string glb;

    void SetUp() override {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(folder / "sub");
        glb = sparseFixture();
        chunks = splitGlb(glb, "x");
        std::ofstream(folder / "avatar.bin", std::ios::binary)
            .write(chunks.bin.data(), static_cast<long>(chunks.bin.size()));
        std::ofstream(dir / "outside.bin", std::ios::binary)
            .write(chunks.bin.data(), static_cast<long>(chunks.bin.size()));
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    // A .gltf beside avatar.bin whose buffer URI is `uri`.
    std::filesystem::path gltfWithUri(const std::string& uri) {
        Json j = Json::parse(chunks.json);
        j["buffers"][0]["uri"] = uri;
        const auto path = folder / "avatar.gltf";
        std::ofstream(path) << j.dump();
        return path;
    }
};

TEST_F(ExternalFiles, RelativeFilesBesideTheGltfAreRead) {
    const AvatarScan a = scanAvatar(loadGltfDocument(gltfWithUri("avatar.bin")), {});
    EXPECT_EQ(a.visemes.size(), 15u);
    std::filesystem::copy_file(folder / "avatar.bin", folder / "sub" / "my buffer.bin");
    EXPECT_EQ(scanAvatar(loadGltfDocument(gltfWithUri("sub/my%20buffer.bin")), {}).visemes.size(), 15u);
}

TEST_F(ExternalFiles, UrisLeadingOutsideTheFolderAreRefused) {
    for (const std::string uri : {"../outside.bin", "sub/../../outside.bin", "%2E%2E/outside.bin"}) {
        const auto path = gltfWithUri(uri);
        test::expectInputError([&] { loadGltfDocument(path); }, {path.string(), "buffers/0/uri", "outside"});
    }
    for (const std::string uri :
         {"/etc/passwd", "file:///etc/passwd", "http://example.com/a.bin", "C:\\a.bin", "a\\b.bin"}) {
        const auto path = gltfWithUri(uri);
        test::expectInputError([&] { loadGltfDocument(path); },
                               {path.string(), "buffers/0/uri", "absolute or remote"});
    }
    for (const std::string uri : {"sub", "sub/", "."}) {
        const auto path = gltfWithUri(uri);
        test::expectInputError([&] { loadGltfDocument(path); },
                               {path.string(), "buffers/0/uri", "not a regular file"});
    }
    std::filesystem::create_symlink(dir / "outside.bin", folder / "link.bin");
    const auto path = gltfWithUri("link.bin");
    test::expectInputError([&] { loadGltfDocument(path); }, {path.string(), "symlink"});
    const auto missing = gltfWithUri("missing.bin");
    test::expectInputError([&] { loadGltfDocument(missing); }, {missing.string(), "not found"});
    // From memory there is no folder: no external file at all.
    Json j = Json::parse(chunks.json);
    j["buffers"][0]["uri"] = "avatar.bin";
    test::expectInputError([&] { parseGltfDocument(j.dump(), "mem.gltf", {}); }, {"mem.gltf", "refused"});
}

TEST_F(ExternalFiles, AFileShorterThanItsByteLengthIsRefusedWithoutReadingMore) {
    Json j = Json::parse(chunks.json);
    j["buffers"][0]["uri"] = "avatar.bin";
    j["buffers"][0]["byteLength"] = 1ull << 40;
    std::ofstream(folder / "big.gltf") << j.dump();
    test::expectInputError([&] { loadGltfDocument(folder / "big.gltf"); },
                           {"big.gltf", "buffers/0", "exceeds"});
}

} // namespace
} // namespace vl

namespace vl {
namespace {

// Deterministic mutations of real-shaped files (bytes of the JSON and BIN chunks flipped, JSON
// numbers changed): reading, reducing and writing end in an InputError or in a file that reads back,
// never in another exception (libFuzzer with sanitizers runs the same loop longer, issue 12).
TEST(GltfHardening, MutatedAvatarsEndInDataErrorsOrValidOutput) {
    std::mt19937 rng(9);
    const std::string sources[] = {test::rpmLikeAvatar({test::FixtureStorage::Sparse}),
                                   test::rpmLikeAvatar({test::FixtureStorage::Meshopt}),
                                   test::rpmLikeAvatar({test::FixtureStorage::Draco}),
                                   test::vroidLikeAvatar(true)};
    int readBack = 0;
    for (int round = 0; round < 240; ++round) {
        std::string glb = sources[round % 4];
        const GlbChunks chunks = splitGlb(glb, "x");
        std::string json(chunks.json);
        for (int flips = 1 + round % 3; flips > 0; --flips) {
            const std::size_t at = rng() % json.size();
            const char digits[] = "0123456789-.e[]{}\",:";
            if (std::isdigit(static_cast<unsigned char>(json[at])) || round % 5 == 0)
                json[at] = digits[rng() % (sizeof(digits) - 1)];
        }
        std::string bin(chunks.bin);
        if (round % 2 == 1)
            for (int flips = 0; flips < 8; ++flips) bin[rng() % bin.size()] = static_cast<char>(rng());
        glb = joinGlb(json, bin);
        try {
            const GltfDocument doc = parseGltfDocument(glb, "mutant.glb", {});
            const AvatarScan scan = scanAvatar(doc, {round % 4 == 3 ? "Fcl_MTH_[AIUEO]" : ""});
            if (scan.visemes.size() < 2) continue;
            ReduceSettings settings;
            settings.target = 2;
            AvatarWriteOptions write;
            write.names = round % 2 ? AvatarNames::Merged : AvatarNames::Original;
            const AvatarReduction r = reduceAvatar(doc, scan, uniformFrequencies(scan), settings, write);
            scanAvatar(parseGltfDocument(r.glb, "out.glb", {}), {round % 4 == 3 ? "Fcl_MTH_[AIUEO]" : ""});
            ++readBack;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(".glb"), std::string::npos) << e.what();
        }
    }
    EXPECT_GT(readBack, 0); // some mutants stay readable (a changed number in a harmless place)
}

} // namespace
} // namespace vl
