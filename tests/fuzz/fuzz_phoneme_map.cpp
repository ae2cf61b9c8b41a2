// libFuzzer target: phoneme -> viseme map files, CSV or JSON (core/reduce loadPhonemeMapFile).
#include "FuzzSupport.h"
#include "core/reduce/Frequencies.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool json = vl::fuzz::looksLikeJson(vl::fuzz::asText(data, size));
    const auto path = vl::fuzz::writeInputFile(json ? "map.json" : "map.csv", data, size);
    vl::fuzz::expectLoadedOrDataError(path.string(), [&] { vl::loadPhonemeMapFile(path); });
    return 0;
}
