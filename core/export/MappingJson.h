#pragma once
// mapping.json of a reduced model: the document `visemelab reduce` writes beside its meshes (format
// "visemelab-mapping", version 1), so that a player of any export format can turn an original
// viseme or a phoneme into a key: {"visemes": {viseme: key}, "phonemes": {phoneme: key},
// "reduced": [{"index", "name", "members", "frequency"[, "file"]}]}.
#include "core/export/ReducedModel.h"

#include <string>
#include <vector>

namespace vl {

// `keyFiles` (empty, or one per key) names each key's file in a folder export.
std::string formatMappingJson(const ReducedModel& model, const std::vector<std::string>& keyFiles = {});

} // namespace vl
