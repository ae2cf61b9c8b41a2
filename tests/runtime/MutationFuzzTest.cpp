// The fuzz target run over deterministic mutations of valid packages, so every build (GCC too)
// exercises the loader on hostile input; tests/fuzz fuzz_runtime_package runs the real libFuzzer.
#include "FuzzTarget.h"

#include "core/export/RuntimePackageWriter.h"
#include "core/runtime/Crc32.h"
#include "core/runtime/PackageFormat.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <random>

namespace vl {
namespace {

// Mutations a fuzzer tries first: bit flips, byte overwrites with boundary values, 32-bit field
// overwrites (counts, offsets), truncation, duplication and deletion of ranges.
std::string mutate(std::string bytes, std::mt19937& rng) {
    auto pick = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
    const int rounds = 1 + static_cast<int>(rng() % 4);
    for (int r = 0; r < rounds && !bytes.empty(); ++r) {
        switch (rng() % 6) {
        case 0:
            bytes[pick(bytes.size())] ^= static_cast<char>(1u << (rng() % 8));
            break;
        case 1:
            bytes[pick(bytes.size())] =
                static_cast<char>(std::vector<int>{0, 1, 0x7F, 0x80, 0xFF}[rng() % 5]);
            break;
        case 2: {
            const std::size_t at = pick(bytes.size() >= 4 ? bytes.size() - 3 : 1);
            const std::uint32_t values[] = {
                0, 1, 3, 0x7FFFFFFF, 0xFFFFFFFF, 0x10000, static_cast<std::uint32_t>(rng())};
            const std::uint32_t v = values[rng() % 7];
            for (std::size_t i = 0; i < 4 && at + i < bytes.size(); ++i)
                bytes[at + i] = static_cast<char>(v >> (8 * i));
            break;
        }
        case 3:
            bytes.resize(pick(bytes.size()));
            break;
        case 4: {
            const std::size_t at = pick(bytes.size()),
                              length = pick(std::min<std::size_t>(64, bytes.size() - at) + 1);
            bytes.insert(at, bytes.substr(at, length));
            break;
        }
        default: {
            const std::size_t at = pick(bytes.size());
            bytes.erase(at, pick(std::min<std::size_t>(64, bytes.size() - at) + 1));
        }
        }
    }
    return bytes;
}

std::string withValidCrc(std::string bytes) {
    test::repairPayloadCrc(bytes);
    return bytes;
}

TEST(RuntimeMutationFuzz, HostileInputIsRejectedOrLoadsConsistently) {
    std::vector<std::string> seeds;
    for (bool quantise : {false, true})
        for (bool uvs : {false, true})
            seeds.push_back(
                encodeRuntimePackage(test::randomModel(4, 3, 3, uvs, 21), {.quantise = quantise}));
    std::mt19937 rng(1234);
    int loaded = 0;
    const int iterations = 200000;
    for (int i = 0; i < iterations; ++i) {
        std::string input = mutate(seeds[rng() % seeds.size()], rng);
        if (rng() % 2) input = withValidCrc(std::move(input));
        loaded += test::fuzzRuntimePackage(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    }
    for (const std::string& seed : seeds)
        EXPECT_EQ(test::fuzzRuntimePackage(reinterpret_cast<const std::uint8_t*>(seed.data()), seed.size()),
                  1);
    // Nearly all mutations must be rejected; the few that load (e.g. a changed float) are valid.
    EXPECT_LT(loaded, iterations / 4);
}

} // namespace
} // namespace vl
