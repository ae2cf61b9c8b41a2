// libFuzzer target: viseme parameter files, visemes.json (core/export parseVisemeFile) for the
// bundled face's parameters, and the parameter vectors `visemelab visemes` builds from them.
#include "FuzzSupport.h"
#include "core/face/BundledFace.h"
#include "core/import/VisemeFile.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const vl::DeformationCascade face = vl::face::makeBundledFace();
    vl::fuzz::expectLoadedOrDataError("visemes.json", [&] {
        for (const auto& viseme : vl::parseVisemeFile(vl::fuzz::asText(data, size), "visemes.json", face)) {
            if (viseme.name.empty()) vl::fuzz::fail("loaded a viseme without a name");
            // The reader validated every value: parameterVector must accept them all (its errors do
            // not name the file, so one escaping here fails the run).
            for (const double x : vl::parameterVector(face, viseme))
                if (!std::isfinite(x)) vl::fuzz::fail("non-finite parameter value");
        }
    });
    return 0;
}
