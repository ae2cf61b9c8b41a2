// libFuzzer target: whole avatars (core/gltf): GLB/JSON glTF parsed by parseGltfDocument (tinygltf
// behind our own limits), then every mesh, node and morph target scanned and reported as `visemelab
// avatar inspect` does, and the materials the editor draws read (core/gltf/AvatarMaterials: images
// decoded with their declared size checked first).
#include "FuzzSupport.h"
#include "core/gltf/AvatarMaterials.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    vl::fuzz::expectLoadedOrDataError("fuzz.glb", [&] {
        const vl::GltfDocument doc =
            vl::parseGltfDocument(std::string(vl::fuzz::asText(data, size)), "fuzz.glb", {});
        const vl::AvatarScan scan = vl::scanAvatar(doc, {"", true});
        for (const auto& viseme : scan.set.visemes)
            if (viseme.positions.size() != scan.set.neutral.positions.size())
                vl::fuzz::fail("viseme size differs");
        // The report, including what a file claiming to be VisemeLab's output says (core/gltf/OwnOutput).
        if (vl::formatAvatarReport(scan).empty() || vl::avatarReportJson(scan).dump().empty())
            vl::fuzz::fail("empty report");
        const vl::AvatarSurfaces surfaces = vl::readAvatarSurfaces(doc, scan);
        if (surfaces.visemes.texCoords.size() != scan.set.neutral.positions.size())
            vl::fuzz::fail("materials layout differs from the viseme set");
        for (const vl::TextureImage& image : surfaces.materials.images)
            if (image.rgba.size() !=
                4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
                vl::fuzz::fail("image size differs from its pixels");
    });
    return 0;
}
