// libFuzzer target: painted weight files, plain text or JSON (core/reduce loadWeightsFile).
#include "FuzzSupport.h"
#include "core/reduce/Weights.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool json = vl::fuzz::looksLikeJson(vl::fuzz::asText(data, size));
    const auto path = vl::fuzz::writeInputFile(json ? "weights.json" : "weights.txt", data, size);
    vl::fuzz::expectLoadedOrDataError(path.string(), [&] {
        for (const double w : vl::loadWeightsFile(path))
            if (!std::isfinite(w) || w < 0) vl::fuzz::fail("loaded a negative or non-finite weight");
    });
    return 0;
}
