// libFuzzer target: project files, every version (core/project projectFromJsonText; mesh files are
// not opened, so the JSON reader and the validation are what is fuzzed).
#include "FuzzSupport.h"
#include "core/project/Project.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.vlproj", [&] {
        vl::projectFromJsonText(vl::fuzz::asText(data, size), "/nonexistent/fuzz.vlproj", false);
    });
    return 0;
}
