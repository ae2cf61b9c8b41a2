// libFuzzer target: glTF import of a reduced model (core/export parseGltf), GLB or JSON glTF chosen by
// the GLB magic, as readGltf chooses by extension.
#include "FuzzSupport.h"
#include "core/import/GltfImport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes = vl::fuzz::asText(data, size);
    const bool binary = bytes.starts_with("glTF");
    const char* source = binary ? "fuzz.glb" : "fuzz.gltf";
    vl::fuzz::expectLoadedOrDataError(source, [&] {
        const vl::ReducedModel model = vl::parseGltf(bytes, source, binary);
        vl::fuzz::checkMesh(model.neutral);
        for (const vl::KeyMesh& key : model.keys)
            if (key.positions.size() != model.neutral.positions.size())
                vl::fuzz::fail("key mesh size differs");
    });
    return 0;
}
