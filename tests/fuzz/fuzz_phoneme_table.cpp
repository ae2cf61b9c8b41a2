// libFuzzer target: phoneme frequency tables written by `visemelab freq`, CSV or JSON
// (core/phonetics loadPhonemeTable).
#include "FuzzSupport.h"
#include "core/phonetics/PhonemeTableIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool json = vl::fuzz::looksLikeJson(vl::fuzz::asText(data, size));
    const auto path = vl::fuzz::writeInputFile(json ? "table.json" : "table.csv", data, size);
    vl::fuzz::expectLoadedOrDataError(path.string(), [&] { vl::loadPhonemeTable(path); });
    return 0;
}
