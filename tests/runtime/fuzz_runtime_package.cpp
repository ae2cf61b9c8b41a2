// libFuzzer entry for the runtime package loader (built by scripts/fuzz-runtime.sh with clang).
#include "FuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::test::fuzzRuntimePackage(data, size);
    return 0;
}
