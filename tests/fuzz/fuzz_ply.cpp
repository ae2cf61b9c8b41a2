// libFuzzer target: Stanford PLY, ASCII and binary (core/io parsePly).
#include "FuzzSupport.h"
#include "core/io/MeshIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError(
        "fuzz.ply", [&] { vl::fuzz::checkMesh(vl::parsePly(vl::fuzz::asText(data, size), "fuzz.ply")); });
    return 0;
}
