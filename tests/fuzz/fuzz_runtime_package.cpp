// libFuzzer target: runtime packages (core/runtime Package::load, C++17, no exceptions): loaded
// packages are animated with every interpolation (tests/runtime/FuzzTarget.cpp).
#include "tests/runtime/FuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::test::fuzzRuntimePackage(data, size);
    return 0;
}
