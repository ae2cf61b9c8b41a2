#pragma once
// The common large-mesh PLY layout read in bulk (internal to core/io): binary in the host's byte
// order, a vertex element of scalars with float or double x, y, z and no (u,v), then a face element
// whose only property is a uchar/char-counted int list of 3 indices per face. Anything else, and any
// value the general reader would reject, makes it decline, so the general reader (PlyFormat.cpp)
// reads the file and reports the error: both give the same mesh for every file the fast path takes
// (tests/io/PlyFastPathTest.cpp).
#include "core/io/PlyHeader.h"
#include "core/mesh/Mesh.h"

#include <optional>
#include <span>
#include <string_view>

namespace vl::meshio {

// The mesh of `bytes` (a whole PLY file, `header` its header) when it has the layout above, else
// nothing. With `expected` given, the faces are compared with it instead of stored: the result's
// triangles stay empty and a difference declines (a viseme read against its neutral's topology).
std::optional<MeshData> readPlyFast(std::string_view bytes, const PlyHeader& header,
                                    const std::vector<Triangle>* expected = nullptr);

// The positions of `bytes` (a whole PLY file, `header` its header) as float32 x, y, z into `out`
// (3 per vertex) when the file has the layout above with float32 coordinates (doubles would be
// rounded), as many vertices as `out` holds, and faces equal to `triangles`; else false (read it with
// parsePly then). The large-set loader's path (loadFloatVisemeSet): one copy from the file's bytes.
bool readPlyFloatsMatching(std::string_view bytes, const PlyHeader& header,
                           const std::vector<Triangle>& triangles, std::span<float> out);

// The positions of the PLY file `bytes` when readPlyFast reads it and its faces equal `triangles`,
// else nothing (read it with parsePly then); throws for a malformed header.
std::optional<std::vector<Vec3>> parsePlyPositionsMatching(std::string_view bytes, std::string_view source,
                                                           const std::vector<Triangle>& triangles);

} // namespace vl::meshio
