#include "core/gltf/GlbContainer.h"
#include "core/common/Error.h"
#include "tests/gltf/GltfTestSupport.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(GlbContainer, JoinThenSplitGivesTheChunksBackPadded) {
    const std::string glb = joinGlb("{\"a\":1}", std::string("\x01\x02\x03\x04\x05", 5));
    EXPECT_EQ(glb.size() % 4, 0u);
    const GlbChunks chunks = splitGlb(glb, "mem.glb");
    EXPECT_EQ(chunks.json, "{\"a\":1} ");
    ASSERT_TRUE(chunks.hasBin);
    EXPECT_EQ(chunks.bin.size(), 8u);
    EXPECT_EQ(chunks.bin.substr(0, 5), std::string_view("\x01\x02\x03\x04\x05", 5));
    EXPECT_FALSE(splitGlb(joinGlb("{}", ""), "mem.glb").hasBin);
}

TEST(GlbContainer, LengthsBeyondTheFileAreErrorsNamingTheField) {
    std::string glb = joinGlb("{\"asset\":{}}", "abcd");
    test::expectInputError([&] { splitGlb(glb.substr(0, glb.size() - 1), "cut.glb"); },
                           {"cut.glb", "header declares"});
    std::string longChunk = glb;
    longChunk[12] = '\xff'; // JSON chunk length
    test::expectInputError([&] { splitGlb(longChunk, "chunk.glb"); }, {"chunk.glb", "chunk 0", "declares"});
    std::string version = glb;
    version[4] = 1;
    test::expectInputError([&] { splitGlb(version, "v1.glb"); }, {"v1.glb", "version 1"});
    test::expectInputError([&] { splitGlb("glTF", "tiny.glb"); }, {"tiny.glb", "too short"});
}

} // namespace
} // namespace vl
