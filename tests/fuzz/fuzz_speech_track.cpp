// libFuzzer target: speech track JSON, ours and Rhubarb's (core/speech parseTrackJson).
#include "FuzzSupport.h"
#include "core/speech/TrackJson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.json",
                                      [&] { vl::parseTrackJson(vl::fuzz::asText(data, size), "fuzz.json"); });
    return 0;
}
