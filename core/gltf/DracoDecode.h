#pragma once
// KHR_draco_mesh_compression primitives decoded with Google's Draco (the extension's reference
// decoder, Debian libdraco-dev). The decoded attributes replace the contents of the primitive's
// accessors in the AccessorReader (the extension requires the accessors to describe the decoded
// data); the triangle indices are returned. The compressed stream stays in the file untouched: the
// avatar writer keeps the extension and its buffer view.
#include <cstdint>
#include <vector>

namespace vl {

class GltfDocument;
class BufferViews;
class AccessorReader;

// True when primitive `primitive` of mesh `mesh` carries KHR_draco_mesh_compression.
bool hasDraco(const GltfDocument& doc, int mesh, int primitive);

// Decodes the primitive; throws InputError naming the primitive for a stream Draco rejects, a
// missing attribute id, or a point count that differs from the accessors'.
std::vector<std::uint32_t> decodeDracoPrimitive(const GltfDocument& doc, BufferViews& views,
                                                AccessorReader& reader, int mesh, int primitive);

} // namespace vl
