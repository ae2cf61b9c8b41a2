// libFuzzer target: Xface face definition files (core/export parseFdp).
#include "FuzzSupport.h"
#include "core/import/XfaceImport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.fdp",
                                      [&] { vl::parseFdp(vl::fuzz::asText(data, size), "fuzz.fdp"); });
    return 0;
}
