// libFuzzer target: Xface phoneme dictionaries (core/export parseXfaceDictionary).
#include "FuzzSupport.h"
#include "core/import/XfaceImport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.dic", [&] {
        std::string language;
        vl::parseXfaceDictionary(vl::fuzz::asText(data, size), "fuzz.dic", &language);
    });
    return 0;
}
