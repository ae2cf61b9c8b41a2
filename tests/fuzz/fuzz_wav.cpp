// libFuzzer target: RIFF WAVE files (core/speech parseWav).
#include "FuzzSupport.h"
#include "core/speech/WavFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.wav", [&] {
        const vl::WavAudio audio = vl::parseWav(vl::fuzz::asText(data, size), "fuzz.wav");
        if (audio.channels < 1 || audio.samples.size() % static_cast<std::size_t>(audio.channels) != 0)
            vl::fuzz::fail("samples do not fill whole frames");
    });
    return 0;
}
