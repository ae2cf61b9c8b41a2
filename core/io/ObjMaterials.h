#pragma once
// The materials of a Wavefront OBJ mesh, for drawing it: `mtllib` files (resolved against the OBJ's
// folder), `usemtl` per face, and in the .mtl each `newmtl` with `Kd` (diffuse colour), `d`/`Tr`
// (opacity) and `map_Kd` (diffuse texture, resolved against the .mtl's folder; options such as
// `-s 1 1 1` before the file name are skipped, `-clamp on` clamps it). With a map_Kd the texture is
// the colour (Kd is not multiplied in, as Blender's importer does). Texture coordinates are the
// faces' own per corner (seams kept), v flipped into glTF's convention (core/mesh/SurfaceMaterials.h).
//
// What cannot be drawn is a warning naming the file and line (a missing .mtl or texture, an unknown
// material name, a texture that is not PNG or JPEG); a texture declaring an absurd size is an
// InputError (core/io/ImageDecode.h), as is an OBJ parseObj refuses.
#include "core/mesh/SurfaceMaterials.h"

#include <filesystem>
#include <string_view>

namespace vl {

struct ObjSurface {
    SurfaceLayout layout; // empty when the file names no material
    SurfaceMaterials materials;
};

ObjSurface readObjSurface(const std::filesystem::path& objPath);
// The same on the file's text; `folder` resolves mtllib names.
ObjSurface parseObjSurface(std::string_view objText, std::string_view source,
                           const std::filesystem::path& folder);

} // namespace vl
