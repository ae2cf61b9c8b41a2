// libFuzzer target: corpus text for phoneme counting (core/phonetics forEachTextChunk): every chunk
// handed on must be valid UTF-8.
#include "FuzzSupport.h"
#include "core/phonetics/CorpusText.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.txt", [&] {
        vl::forEachTextChunk(
            vl::fuzz::asText(data, size), "fuzz.txt", [](std::string_view, std::uint64_t, std::uint64_t) {},
            64);
    });
    return 0;
}
