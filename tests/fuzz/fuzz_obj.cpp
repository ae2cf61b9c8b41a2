// libFuzzer target: Wavefront OBJ (core/io parseObj).
#include "FuzzSupport.h"
#include "core/io/MeshIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError(
        "fuzz.obj", [&] { vl::fuzz::checkMesh(vl::parseObj(vl::fuzz::asText(data, size), "fuzz.obj")); });
    return 0;
}
