#pragma once
// Where a glTF document refers to accessors, buffer views and buffers by index: glTF 2.0 itself
// (primitives, skins, animations, images, accessors' sparse storage, buffer views), plus the
// extensions that do so: KHR_draco_mesh_compression (buffer view), EXT_meshopt_compression (buffer)
// and EXT_mesh_gpu_instancing (accessors). The visitors hand out each reference as a mutable JSON
// value, so one pass can collect or renumber them. Extensions outside this list are kept verbatim;
// knownIndexFreeExtensions() lists those known to hold no such index.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace vl {

using JsonRef = std::function<void(nlohmann::ordered_json& index)>;

void forEachAccessorReference(nlohmann::ordered_json& doc, const JsonRef& visit);
void forEachBufferViewReference(nlohmann::ordered_json& doc, const JsonRef& visit);

// Renumbers every reference through `newIndex` (old index -> new index; -1 never happens for a
// reference that is kept) and rebuilds `array` (a top-level array name) keeping the entries whose
// new index is >= 0, in order.
void renumber(nlohmann::ordered_json& doc, const std::string& array, const std::vector<int>& newIndex,
              void (*forEach)(nlohmann::ordered_json&, const JsonRef&));

// Extensions that refer to no accessor, buffer view or buffer (so renumbering cannot break them),
// plus the ones handled above.
bool isKnownExtension(const std::string& name);

} // namespace vl
