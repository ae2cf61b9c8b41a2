// libFuzzer target: frequency files, CSV or JSON (core/reduce loadFrequencyFile), written as .json
// when the input starts like JSON.
#include "FuzzSupport.h"
#include "core/reduce/Frequencies.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool json = vl::fuzz::looksLikeJson(vl::fuzz::asText(data, size));
    const auto path = vl::fuzz::writeInputFile(json ? "freq.json" : "freq.csv", data, size);
    vl::fuzz::expectLoadedOrDataError(path.string(), [&] { vl::loadFrequencyFile(path); });
    return 0;
}
