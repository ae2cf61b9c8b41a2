#include "ui/session/ViewMaterials.h"

#include "core/document/Document.h"
#include "core/gltf/AvatarMaterials.h"
#include "core/gltf/AvatarScan.h"
#include "core/io/MeshIO.h"
#include "core/io/ObjMaterials.h"
#include "ui/session/EditorSession.h"

#include <cstdio>

namespace vl::ui {
namespace {

// The OBJ neutral mesh whose .mtl the set's materials come from, if any.
std::filesystem::path objOf(const Document& document) {
    if (document.avatar.isSet() || !document.visemes || document.neutralFile.empty() ||
        !isMeshFile(document.neutralFile) || meshFormatFromPath(document.neutralFile) != MeshFormat::Obj)
        return {};
    return document.neutralFile;
}

void report(const std::vector<std::string>& warnings, EditorSession& session) {
    constexpr std::size_t kShown = 3; // the status line is not a log: the rest are counted
    for (std::size_t i = 0; i < std::min(warnings.size(), kShown); ++i)
        session.info("Materials: " + warnings[i]);
    if (warnings.size() > kShown)
        session.info("Materials: " + std::to_string(warnings.size() - kShown) + " more textures not drawn");
}

} // namespace

std::string ViewMaterials::summary() const {
    std::size_t pixels = 0;
    for (const TextureImage& image : materials.images)
        pixels += static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    char text[128];
    std::snprintf(text, sizeof text, "%zu materials, %zu textures (%.1f MiB)", materials.materials.size(),
                  materials.images.size(), static_cast<double>(4 * pixels) / (1024.0 * 1024.0));
    return text;
}

bool refreshViewMaterials(ViewMaterials& shown, const Document& document, EditorSession& session) {
    // The scan is shared by every document of one import, so the source holds while the user edits.
    const std::shared_ptr<const AvatarScan> scan = document.avatar.isSet() ? document.avatar.scan : nullptr;
    std::filesystem::path obj = objOf(document);
    if (scan == shown.scan && obj == shown.obj) return false;
    shown = {};
    shown.scan = scan;
    shown.obj = std::move(obj);
    if (!scan && shown.obj.empty()) return true;
    session.attempt("Materials", [&] {
        if (document.avatar.isSet()) {
            AvatarSurfaces read = readAvatarSurfaces(*document.avatar.gltf, *document.avatar.scan);
            shown.materials = std::move(read.materials);
            shown.visemes = std::move(read.visemes);
            shown.context = std::move(read.context);
        } else {
            ObjSurface read = readObjSurface(shown.obj);
            // Drawn over the set's neutral: the same file, so the same triangles (else none).
            if (read.layout.cornerTexCoords.size() == document.visemes->neutral.triangles.size() ||
                read.layout.cornerTexCoords.empty())
                shown.visemes = std::move(read.layout);
            shown.materials = std::move(read.materials);
        }
        report(shown.materials.warnings, session);
    });
    return true;
}

} // namespace vl::ui
