// libFuzzer target: VRML97 IndexedFaceSets with DEF/USE (core/io parseVrml).
#include "FuzzSupport.h"
#include "core/io/MeshIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError(
        "fuzz.wrl", [&] { vl::fuzz::checkMesh(vl::parseVrml(vl::fuzz::asText(data, size), "fuzz.wrl")); });
    return 0;
}
