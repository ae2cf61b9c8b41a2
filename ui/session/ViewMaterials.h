#pragma once
// The materials the views draw for the document's viseme set: an avatar's (core/gltf/
// AvatarMaterials.h) or, for a set read from an OBJ neutral mesh, its .mtl's (core/io/
// ObjMaterials.h). Read once per source (an avatar scan, an OBJ file), not per geometry edit; read
// errors and warnings become status messages, and the views then draw without materials.
#include "core/mesh/SurfaceMaterials.h"

#include <filesystem>
#include <memory>
#include <string>

namespace vl {
struct Document;
struct AvatarScan;
} // namespace vl

namespace vl::ui {

class EditorSession;

// What the views' surfaces show where the document has materials: its materials, or the analysis
// colours (skin, and the merge error of the selected viseme once a reduction exists). Weight
// painting shows weights whatever this says.
enum class SurfaceShading { Materials, ErrorColours };

struct ViewMaterials {
    // What they were read from (both empty when the set has neither): held, not an address a later
    // allocation could reuse.
    std::shared_ptr<const AvatarScan> scan;
    std::filesystem::path obj;
    SurfaceMaterials materials;
    SurfaceLayout visemes, context;

    bool any() const { return !visemes.empty() || !context.empty(); }
    // Images and materials, for the probe and the status bar.
    std::string summary() const;
};

// Reads the materials of `document`'s set when their source differs from `shown`'s; returns
// true when `shown` changed.
bool refreshViewMaterials(ViewMaterials& shown, const Document& document, EditorSession& session);

} // namespace vl::ui
